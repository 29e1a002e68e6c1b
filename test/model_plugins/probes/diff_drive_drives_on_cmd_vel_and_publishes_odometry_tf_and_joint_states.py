"""The ROS side of
test_diff_drive_ros.py::test_diff_drive_drives_on_cmd_vel_and_publishes_odometry_tf_and_joint_states, a rospy
program the test runs against its own master (ros.probe); it prints one JSON value on its last line."""
import json, rospy, tf2_ros
from gazebo_msgs.msg import ModelStates
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry
from sensor_msgs.msg import JointState
from ros_harness import connected_publisher
rospy.init_node('probe')
odometry = []
rospy.Subscriber('/odom', Odometry, odometry.append)
buffer = tf2_ros.Buffer()
listener = tf2_ros.TransformListener(buffer)
pub = connected_publisher('/cmd_vel', Twist, queue_size=1)
twist = Twist()
twist.linear.x, twist.angular.z = 0.2, 0.5
start = rospy.wait_for_message('/gazebo/model_states', ModelStates, 30)
for _ in range(30):
    pub.publish(twist)
    rospy.sleep(0.1)
joints = rospy.wait_for_message('/joint_states', JointState, 10)
states = rospy.wait_for_message('/gazebo/model_states', ModelStates, 10)
last = odometry[-1]
tf = buffer.lookup_transform('odom', 'base_footprint', rospy.Time(0), rospy.Duration(5))
i = states.name.index('diff_bot')
print(json.dumps({
    'frames': sorted({(m.header.frame_id, m.child_frame_id) for m in odometry}),
    'covariances': sorted({(m.pose.covariance[0], m.pose.covariance[35]) for m in odometry}),
    'linear': last.twist.twist.linear.x, 'angular': last.twist.twist.angular.z,
    'odom_xy': [last.pose.pose.position.x, last.pose.pose.position.y],
    'model_xy': [states.pose[i].position.x, states.pose[i].position.y],
    'start_xy': [start.pose[start.name.index('diff_bot')].position.x,
                 start.pose[start.name.index('diff_bot')].position.y],
    'tf_x': tf.transform.translation.x,
    'joints': list(joints.name), 'positions': len(joints.position)}))
