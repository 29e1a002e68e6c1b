"""The ROS side of test_velodyne_ros.py::test_vlp16_and_hdl32_point_clouds, a rospy program the test runs
against its own master (ros.probe); it prints one JSON value on its last line."""
import json, math, rospy
from sensor_msgs import point_cloud2
from sensor_msgs.msg import PointCloud2
rospy.init_node('probe')
out = {}
for topic in ('/velodyne_points', '/hdl32/points'):
    cloud = rospy.wait_for_message(topic, PointCloud2, 30)
    points = list(point_cloud2.read_points(cloud, skip_nans=False))
    out[topic] = {
        'frame': cloud.header.frame_id,
        'fields': [(f.name, f.offset, f.datatype) for f in cloud.fields],
        'shape': [cloud.height, cloud.width, cloud.point_step, cloud.row_step, cloud.is_dense],
        'points': [[round(v, 5) if isinstance(v, float) and not math.isnan(v) else (None if isinstance(v, float) else v)
                    for v in p] for p in points[::7]],
        'count': len(points), 'rings_in_order': [p[4] for p in points[:40]]}
print(json.dumps(out))
