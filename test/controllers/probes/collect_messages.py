"""The messages of several topics over SECONDS of simulated time from when every one of them is
connected, as dicts per topic (test_group_and_ackermann_controllers_ros.py's collect):

    collect_messages.py SECONDS TOPIC...

prints one JSON object {topic: [message, ...]} on its last line."""
import json, rospy, rostopic, sys, time
from ros_harness import message_to_dict
seconds, topics = float(sys.argv[1]), sys.argv[2:]
rospy.init_node('probe', anonymous=True)
got = {t: [] for t in topics}
subs = []
for topic in got:
    cls, name, _ = rostopic.get_topic_class(topic, blocking=True)
    subs.append(rospy.Subscriber(name, cls, lambda m, t=topic: got[t].append(message_to_dict(m))))
while rospy.Time.now().is_zero() or any(s.get_num_connections() == 0 for s in subs):
    time.sleep(0.01)
for messages in got.values():
    messages.clear()
end = rospy.Time.now() + rospy.Duration(seconds)
while rospy.Time.now() < end:
    time.sleep(0.01)
print(json.dumps(got))
