"""The ROS side of test_tutorial.py::test_rostopic_pub_drives_the_circle_of_the_geometry_and_the_car_stops:
the tutorial's Twist at 10 Hz for 8 s, then nothing; prints the odometry of the circle, the last Twist's
time, the wheel commands and the last odometry on its last line."""
import json, math, time, rospy
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry
from std_msgs.msg import Float64
rospy.init_node('tutorial_probe', anonymous=True)
odom, wheel = [], []
rospy.Subscriber('/tianracer/odom', Odometry, lambda m: odom.append(
    (m.header.stamp.to_sec(), m.pose.pose.position.x, m.pose.pose.position.y, m.twist.twist.linear.x)))
rospy.Subscriber('/tianracer/rear_left_velocity_controller/command', Float64,
                 lambda m: wheel.append((rospy.get_rostime().to_sec(), m.data)))
pub = rospy.Publisher('/tianracer/cmd_vel', Twist, queue_size=1)
time.sleep(1.0)
twist = Twist()
twist.linear.x, twist.angular.z = 1.0, 1.0   # the tutorial's rostopic pub line, at 10 Hz
start = rospy.get_rostime().to_sec()
rate = rospy.Rate(10)
while rospy.get_rostime().to_sec() - start < 8.0:
    pub.publish(twist)
    last_twist = rospy.get_rostime().to_sec()
    rate.sleep()
circle = [(x, y) for t, x, y, v in odom if start + 3.0 <= t <= last_twist]
time.sleep(2.5)
print(json.dumps(dict(circle=circle, last_twist=last_twist, wheel=wheel, odom_after=odom[-1])))
