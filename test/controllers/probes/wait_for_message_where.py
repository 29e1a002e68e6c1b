"""Waits (wall clock) for a message of TOPIC for which CONDITION, a Python expression of the message as a
dict `m`, holds (test_group_and_ackermann_controllers_ros.py's wait_for_message_where):

    wait_for_message_where.py TOPIC CONDITION TIMEOUT

prints true on its last line once one does; fails naming the last message otherwise."""
import json, rospy, rostopic, sys, time
from ros_harness import message_to_dict
topic, condition, timeout = sys.argv[1], sys.argv[2], float(sys.argv[3])
rospy.init_node('waiter', anonymous=True)
cls, name, _ = rostopic.get_topic_class(topic, blocking=True)
deadline = time.monotonic() + timeout
m = message_to_dict(rospy.wait_for_message(name, cls, timeout=timeout))
while not eval(condition):
    assert time.monotonic() < deadline, 'no message of %s where %s; the last: %r' % (topic, condition, m)
    m = message_to_dict(rospy.wait_for_message(name, cls, timeout=timeout))
print(json.dumps(True))
