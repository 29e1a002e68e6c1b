"""The ROS side of test_ros_plant.py::test_cameras_publish_at_their_rates_only_while_subscribed, a rospy
program the test runs against its own master (ros.probe); it prints one JSON value on its last line."""
import json, time, rospy
from ros_harness import rate_of_stamps
from sensor_msgs.msg import CameraInfo, Image, PointCloud2
rospy.init_node('camera_probe', anonymous=True)
got = {}
def keep(topic):
    return lambda m: got.setdefault(topic, []).append(m)
topics = {'/camera/image_raw': Image, '/camera/camera_info': CameraInfo,
          '/depth_camera/depth/image_raw': Image,
          '/depth_camera/depth/camera_info': CameraInfo,
          '/depth_camera/depth/points': PointCloud2}
subs = [rospy.Subscriber(t, cls, keep(t)) for t, cls in topics.items()]
time.sleep(4.0)
out = {}
for topic, msgs in got.items():
    stamps = [m.header.stamp.to_sec() for m in msgs[2:]]
    out[topic] = dict(rate=rate_of_stamps(stamps), frame=msgs[-1].header.frame_id,
                      size=[msgs[-1].width, msgs[-1].height],
                      encoding=getattr(msgs[-1], 'encoding', None))
for s in subs:
    s.unregister()
time.sleep(2.0)
print(json.dumps(out))
