"""The ROS side of test_ranger_plugins_ros.py::test_hector_sonar_and_block_laser, a rospy program the test
runs against its own master (ros.probe); it prints one JSON value on its last line."""
import json, rospy
from sensor_msgs.msg import PointCloud, Range
rospy.init_node('probe')
def ranges(topic, n):
    msgs = []
    sub = rospy.Subscriber(topic, Range, msgs.append)
    while len(msgs) < n and not rospy.is_shutdown():
        rospy.sleep(0.05)
    sub.unregister()
    return [{'frame': m.header.frame_id, 'stamp_ns': m.header.stamp.to_nsec(), 'radiation': m.radiation_type,
             'fov': m.field_of_view, 'limits': [m.min_range, m.max_range], 'range': m.range} for m in msgs[:n]]
cloud = rospy.wait_for_message('/block_cloud', PointCloud, 30)
print(json.dumps({'front': ranges('/sonar_front', 4), 'back': ranges('/sonar', 2),
                  'cloud': {'frame': cloud.header.frame_id,
                            'points': [[p.x, p.y, p.z] for p in cloud.points],
                            'channels': [[c.name, list(c.values)] for c in cloud.channels]}}))
