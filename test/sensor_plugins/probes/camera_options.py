"""The ROS side of test_camera_options_ros.py: one image and one CameraInfo of each camera, the red
post's column (the mean of the red pixels' columns on the middle row) in the colour ones, and who
subscribes to the cameras' set_hfov and set_update_rate; one JSON value on its last line."""
import json, rospy, rosgraph
from sensor_msgs.msg import CameraInfo, Image

rospy.init_node('probe')
names = ['rgb', 'mono', 'mono16', 'bayer', 'odd', 'barrel', 'pincushion', 'tuned']
out = {'images': {}, 'infos': {}, 'post': {}}
for name in names:
    image = rospy.wait_for_message('/%s/image_raw' % name, Image, 60)
    info = rospy.wait_for_message('/%s/camera_info' % name, CameraInfo, 10)
    data = bytes(image.data)
    out['images'][name] = {'encoding': image.encoding, 'step': image.step, 'is_bigendian': image.is_bigendian,
                           'data': data.hex() if name in ('rgb', 'mono', 'mono16', 'bayer', 'odd') else ''}
    out['infos'][name] = {'K': list(info.K), 'P': list(info.P), 'D': list(info.D), 'model': info.distortion_model}
    if image.encoding == 'rgb8':
        row = image.height // 2
        red = [u for u in range(image.width)
               if data[(row * image.width + u) * 3] > 2 * data[(row * image.width + u) * 3 + 1] + 20]
        out['post'][name] = sum(red) / len(red) if red else None
state = rosgraph.Master('/probe').getSystemState()
out['control_subscribers'] = sorted(t for t, _ in state[1] if t.endswith('/set_hfov') or t.endswith('/set_update_rate'))
print(json.dumps(out))
