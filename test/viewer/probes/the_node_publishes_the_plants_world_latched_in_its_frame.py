"""The ROS side of test_scene_markers.py::test_the_node_publishes_the_plants_world_latched_in_its_frame, a
rospy program the test runs against its own master (ros.probe); it prints one JSON value on its last line."""
import json, rospy
from visualization_msgs.msg import MarkerArray
rospy.init_node('markers_probe', anonymous=True)
markers = rospy.wait_for_message('/gazebo/scene_markers', MarkerArray, timeout=30).markers
print(json.dumps([[m.header.frame_id, m.action, m.type, m.ns] for m in markers]))
