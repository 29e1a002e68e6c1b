"""The ROS side of
test_joint_trajectory_controller_ros.py::test_a_trajectory_on_the_command_topic_the_state_topic_and_query_state,
a rospy program the test runs against its own master (ros.probe); it prints one JSON value on its last
line."""
import json, rospy
from control_msgs.msg import JointTrajectoryControllerState
from trajectory_msgs.msg import JointTrajectory, JointTrajectoryPoint
from ros_harness import connected_publisher, rate_of_stamps
rospy.init_node('probe')
states = []
rospy.Subscriber('/arm/arm_controller/state', JointTrajectoryControllerState, states.append)
pub = connected_publisher('/arm/arm_controller/command', JointTrajectory, queue_size=1, latch=True)
rospy.sleep(1.0)
t = JointTrajectory(joint_names=['elbow', 'shoulder', 'wrist'])
t.points.append(JointTrajectoryPoint(positions=[0.4, -0.6, 0.0], time_from_start=rospy.Duration(1.0)))
pub.publish(t)
rospy.sleep(2.5)
last = states[-1]
stamps = [s.header.stamp.to_sec() for s in states[-20:]]
from control_msgs.srv import QueryTrajectoryState
query = rospy.ServiceProxy('/arm/arm_controller/query_state', QueryTrajectoryState)
queried = query(rospy.Time.now())
try:
    query(rospy.Time(0.001))
    early = 'answered'
except rospy.ServiceException as e:
    early = 'failed'
print(json.dumps({'names': list(last.joint_names), 'actual': list(last.actual.positions),
                  'error': list(last.error.positions), 'period': 1.0 / rate_of_stamps(stamps),
                  'queried': [list(queried.name), list(queried.position), list(queried.velocity)], 'early': early}))
