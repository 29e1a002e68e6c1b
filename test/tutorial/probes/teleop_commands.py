"""The ROS side of test_tutorial.py::test_teleop_in_a_terminal: the Twists teleop.py sends on
/tianracer/cmd_vel until the test closes this program's stdin (teleop.py has exited by then) or for
at most SECONDS of wall time,

    teleop_commands.py SECONDS

printed as [[wall time, linear.x, angular.z], ...] on its last line."""
import json, sys, threading, time, rospy
from geometry_msgs.msg import Twist
rospy.init_node('teleop_probe', anonymous=True)
got = []
rospy.Subscriber('/tianracer/cmd_vel', Twist, lambda m: got.append((time.time(), m.linear.x, m.angular.z)))
closed = threading.Event()
threading.Thread(target=lambda: (sys.stdin.read(), closed.set()), daemon=True).start()
closed.wait(float(sys.argv[1]))
# teleop.py's last Twist (zero, sent as it exits) may still be on its way: heard within 5 s.
end = time.time() + 5.0
while not (got and got[-1][1:] == (0.0, 0.0)) and time.time() < end:
    time.sleep(0.05)
print(json.dumps(got))
