"""The ROS side of test_tutorial.py::test_tianracer_world_launch_angular_mode_yaw_rate_turns_at_the_asked_rate:
angular.z 0.4 as a yaw rate for 4 s; prints the last 20 yaw rates of /tianracer/odom on its last line."""
import json, rospy
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry
rospy.init_node('yaw_rate_driver', anonymous=True)
yaw_rates = []
rospy.Subscriber('/tianracer/odom', Odometry, lambda m: yaw_rates.append(m.twist.twist.angular.z))
pub = rospy.Publisher('/tianracer/cmd_vel', Twist, queue_size=1)
# the 4 s start once the converter listens and odometry arrives (connecting takes seconds on a
# slow machine)
while (pub.get_num_connections() == 0 or not yaw_rates) and not rospy.is_shutdown():
    rospy.sleep(0.05)
twist = Twist()
twist.linear.x, twist.angular.z = 0.5, 0.4
end = rospy.get_time() + 4.0
while rospy.get_time() < end:
    pub.publish(twist)
    rospy.sleep(0.05)
print(json.dumps(yaw_rates[-20:]))
