"""The ROS side of
test_diff_drive_controller_ros.py::test_diff_drive_controller_through_gazebo_ros_control_and_the_spawner, a
rospy program the test runs against its own master (ros.probe); it prints one JSON value on its last line."""
import json, rospy
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry
from ros_harness import connected_publisher
rospy.init_node('probe')
pub = connected_publisher('/diff_bot/mobile_base_controller/cmd_vel', Twist, queue_size=1)
# Read while the commands still come: 0.5 s after the last one (cmd_vel_timeout) the controller stops.
latest = []
rospy.Subscriber('/diff_bot/mobile_base_controller/odom', Odometry, latest.append)
twist = Twist()
twist.linear.x, twist.angular.z = 0.2, 0.5
for _ in range(30):
    pub.publish(twist)
    rospy.sleep(0.1)
odom = latest[-1]
print(json.dumps({'frames': [odom.header.frame_id, odom.child_frame_id],
                  'linear': odom.twist.twist.linear.x, 'angular': odom.twist.twist.angular.z,
                  'x': odom.pose.pose.position.x}))
