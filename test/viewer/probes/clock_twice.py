"""/clock read twice a second of wall time apart (None where nothing is published: stopped), for
test_viewer.py's pause and play; prints [first, second] on its last line."""
import json, time, rospy
from rosgraph_msgs.msg import Clock
rospy.init_node('clock_probe', anonymous=True)
times = []
for _ in range(2):
    try:
        times.append(rospy.wait_for_message('/clock', Clock, timeout=2.0).clock.to_sec())
    except rospy.ROSException:  # nothing published: stopped
        times.append(None)
    time.sleep(1.0)  # wall time: sim time stands while paused
print(json.dumps(times))
