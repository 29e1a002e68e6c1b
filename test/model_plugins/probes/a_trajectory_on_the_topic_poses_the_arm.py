"""The ROS side of test_joint_pose_trajectory_ros.py::test_a_trajectory_on_the_topic_poses_the_arm, a rospy
program the test runs against its own master (ros.probe); it prints one JSON value on its last line."""
import json, rospy
from gazebo_msgs.srv import GetJointProperties
from trajectory_msgs.msg import JointTrajectory, JointTrajectoryPoint
from ros_harness import connected_publisher
rospy.init_node('probe')
joint = rospy.ServiceProxy('/gazebo/get_joint_properties', GetJointProperties)
pub = connected_publisher('/set_joint_trajectory', JointTrajectory, queue_size=1, latch=True)
t = JointTrajectory(joint_names=['shoulder', 'elbow'])
t.header.frame_id = 'world'
t.points.append(JointTrajectoryPoint(positions=[0.5, -0.3], time_from_start=rospy.Duration(0.3)))
t.points.append(JointTrajectoryPoint(positions=[1.0, -0.6], time_from_start=rospy.Duration(5.0)))
pub.publish(t)
rospy.sleep(1.5)  # the second point is held 5 s with the physics off
shoulder, elbow = joint('shoulder'), joint('elbow')
print(json.dumps({'shoulder': list(shoulder.position), 'elbow': list(elbow.position),
                  'elbow_rate': list(elbow.rate), 'missing': [joint('nowhere').success, joint('nowhere').status_message]}))
