"""The ROS side of test_ros_network.py::test_the_viewers_topics_come_when_a_node_asks_for_them: subscribes
to /gazebo/scene as a viewer does and prints how long the latched scene took, what it names, and the
topics the master lists then, as one JSON object on its last line."""
import json, time
import rosgraph, rospy
from std_msgs.msg import String
rospy.init_node('viewer_probe', anonymous=True)
start = time.time()
scene = json.loads(rospy.wait_for_message('/gazebo/scene', String, timeout=30).data)
waited = time.time() - start
time.sleep(0.5)
publishers, subscribers, _ = rosgraph.Master(rospy.get_name()).getSystemState()
print(json.dumps({'waited': waited, 'world': scene.get('world'),
                  'published': sorted(t for t, ns in publishers if ns),
                  'subscribed_by_others': sorted(t for t, ns in subscribers if set(ns) - {rospy.get_name()})}))
