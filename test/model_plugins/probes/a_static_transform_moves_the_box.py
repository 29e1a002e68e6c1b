"""The ROS side of test_hand_of_god_ros.py::test_a_static_transform_moves_the_box, a rospy program the test
runs against its own master (ros.probe); it prints one JSON value on its last line."""
import json, rospy, tf2_ros
from gazebo_msgs.srv import GetModelState
from geometry_msgs.msg import TransformStamped
rospy.init_node('probe')
broadcaster = tf2_ros.StaticTransformBroadcaster()
t = TransformStamped()
t.header.stamp = rospy.Time.now()
t.header.frame_id, t.child_frame_id = 'world', 'hog_desired'
t.transform.translation.x, t.transform.translation.z = 0.8, 1.5
t.transform.rotation.w = 1.0
broadcaster.sendTransform(t)
buffer = tf2_ros.Buffer()
listener = tf2_ros.TransformListener(buffer)
rospy.sleep(3.0)
p = rospy.ServiceProxy('/gazebo/get_model_state', GetModelState)('hog_box', '').pose.position
actual = buffer.lookup_transform('world', 'hog_actual', rospy.Time(0), rospy.Duration(5)).transform.translation
print(json.dumps({'box': [p.x, p.y, p.z], 'actual': [actual.x, actual.y, actual.z]}))
