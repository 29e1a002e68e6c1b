"""The ROS side of test_depth_cameras_ros.py::test_kinect_and_depth_camera_before_a_wall, a rospy program the
test runs against its own master (ros.probe); it prints one JSON value on its last line."""
import json, math, rospy
from sensor_msgs import point_cloud2
from sensor_msgs.msg import CameraInfo, Image, PointCloud2
import struct
rospy.init_node('probe')
out = {}
for name in ('kinect', 'depth_camera'):
    cloud = rospy.wait_for_message('/%s/points' % name, PointCloud2, 30)
    depth = rospy.wait_for_message('/%s/depth/image_raw' % name, Image, 10)
    # Noetic's depth camera publishes no CameraInfo, neither its depth's nor its image's
    # (test_depth_cameras_ros.py's second test)
    kinect = name == 'kinect'
    info = rospy.wait_for_message('/%s/depth/camera_info' % name, CameraInfo, 10) if kinect else None
    # the camera's own image, where GazeboRosCameraUtils::Load puts it
    ir = rospy.wait_for_message('/%s/image_raw' % name, Image, 10)
    ir_info = rospy.wait_for_message('/%s/camera_info' % name, CameraInfo, 10) if kinect else None
    depths = struct.unpack('<%df' % (depth.width * depth.height), bytes(depth.data))
    out[name] = {'shape': [cloud.height, cloud.width, cloud.is_dense], 'frame': cloud.header.frame_id,
                 'points': [None if math.isnan(p[2]) else [p[0], p[1], p[2]]
                            for p in point_cloud2.read_points(cloud, field_names=('x', 'y', 'z'))],
                 'depths': [None if math.isnan(d) else d for d in depths],
                 'image': [depth.height, depth.width, depth.encoding], 'info': info and [info.height, info.width],
                 'ir': [ir.height, ir.width, ir.encoding, ir_info and ir_info.width]}
print(json.dumps(out))
