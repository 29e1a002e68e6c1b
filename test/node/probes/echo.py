"""COUNT messages of TOPIC as dicts, waiting TIMEOUT s at most (test_ros_plant.py's echo: no YAML
guessing of nan/inf, as `rostopic echo` would need):

    echo.py TOPIC COUNT TIMEOUT

prints the JSON list of them on its last line."""
import json, rospy, rostopic, sys
from ros_harness import message_to_dict
topic, count, timeout = sys.argv[1], int(sys.argv[2]), float(sys.argv[3])
rospy.init_node('probe', anonymous=True)
cls, name, _ = rostopic.get_topic_class(topic, blocking=True)
got = []
sub = rospy.Subscriber(name, cls, lambda m: got.append(message_to_dict(m)))
import time
end = time.monotonic() + timeout
while len(got) < count and time.monotonic() < end:
    time.sleep(0.01)
print(json.dumps(got[:count]))
