"""The ROS side of test_two_cars.py::test_each_car_has_its_own_controllers, a rospy program the test runs
against its own master (ros.probe); it prints one JSON value on its last line."""
import json, rospy
from ackermann_msgs.msg import AckermannDriveStamped
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry
rospy.init_node('driver', anonymous=True)
x = {}
for car in ('car1', 'car2'):
    rospy.Subscriber('/%s/tianracer/odom' % car, Odometry, lambda m, c=car: x.__setitem__(c, m.pose.pose.position.x))
twist_pub = rospy.Publisher('/car1/tianracer/cmd_vel', Twist, queue_size=1)
ackermann_pub = rospy.Publisher('/car2/tianracer/ackermann_cmd_stamped', AckermannDriveStamped, queue_size=1)
while len(x) < 2:
    rospy.sleep(0.05)
moved = []
for pub, message in ((twist_pub, Twist()), (ackermann_pub, AckermannDriveStamped())):
    if isinstance(message, Twist):
        message.linear.x = 0.5
    else:
        message.drive.speed = 0.5
    start = dict(x)
    end = rospy.get_time() + 3.0
    while rospy.get_time() < end:
        pub.publish(message)
        rospy.sleep(0.05)
    rospy.sleep(1.0)  # the converter's dead man's switch stops the car
    moved.append({c: x[c] - start[c] for c in x})
print(json.dumps(moved))
