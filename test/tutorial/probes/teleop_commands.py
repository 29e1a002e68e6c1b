"""The ROS side of test_tutorial.py::test_teleop_in_a_terminal: the Twists teleop.py sends on
/tianracer/cmd_vel for SECONDS of wall time,

    teleop_commands.py SECONDS

printed as [[wall time, linear.x, angular.z], ...] on its last line."""
import json, sys, time, rospy
from geometry_msgs.msg import Twist
rospy.init_node('teleop_probe', anonymous=True)
got = []
rospy.Subscriber('/tianracer/cmd_vel', Twist, lambda m: got.append((time.time(), m.linear.x, m.angular.z)))
end = time.time() + float(sys.argv[1])
while time.time() < end:
    time.sleep(0.05)
print(json.dumps(got))
