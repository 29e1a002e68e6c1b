"""The ROS side of test_scene_markers.py::test_rviz_started_with_rviz_true_draws_the_race_tracks_walls, a
rospy program the test runs against its own master (ros.probe); it prints one JSON value on its last line."""
import json, rospy
from visualization_msgs.msg import MarkerArray
rospy.init_node('markers_probe', anonymous=True)
rospy.wait_for_message('/gazebo/scene_markers', MarkerArray, timeout=60)
print(json.dumps(True))
