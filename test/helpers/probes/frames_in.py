"""Through a tf2 buffer: one message of each TOPIC, its header's frame id and that frame's origin in
TARGET at the message's stamp (the harness's frames_in, which says why a message stamped before the
buffer's first transform is dropped for the next):

    frames_in.py TARGET TIMEOUT TOPIC...

prints {topic: {'frame': ..., 'xyz': [x, y, z]}} on its last line; a lookup that fails fails it."""
import json, rospy, rostopic, sys, tf2_ros
target, timeout, topics = sys.argv[1], float(sys.argv[2]), sys.argv[3:]
rospy.init_node('tf2_probe', anonymous=True)
buffer = tf2_ros.Buffer()
listener = tf2_ros.TransformListener(buffer)
out = {}
for topic in topics:
    cls, name, _ = rostopic.get_topic_class(topic, blocking=True)
    for attempt in range(5):
        msg = rospy.wait_for_message(topic, cls, timeout=timeout)
        try:
            t = buffer.lookup_transform(target, msg.header.frame_id, msg.header.stamp, rospy.Duration(10.0))
            break
        except tf2_ros.ExtrapolationException:
            # Stamped before the listener's first /tf message: rviz's message filter drops such a
            # message too. The next one is newer; a stamp that never resolves fails at the fifth.
            if attempt == 4:
                raise
    v = t.transform.translation
    out[topic] = {'frame': msg.header.frame_id, 'xyz': [v.x, v.y, v.z]}
print(json.dumps(out))
