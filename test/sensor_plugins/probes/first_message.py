"""The first message of TOPIC: its header's frame id, its type and (odometry) its child frame id
(test_sensor_plugins_ros.py's first_message):

    first_message.py TOPIC

prints them as one JSON object on its last line."""
import json, rospy, rostopic, sys
topic = sys.argv[1]
rospy.init_node('probe', anonymous=True)
cls, name, _ = rostopic.get_topic_class(topic, blocking=True)
m = rospy.wait_for_message(topic, cls, timeout=30)
out = {'frame': m.header.frame_id, 'type': m._type}
if hasattr(m, 'child_frame_id'):
    out['child'] = m.child_frame_id
print(json.dumps(out))
