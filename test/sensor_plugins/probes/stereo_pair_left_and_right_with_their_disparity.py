"""The ROS side of test_multicamera_ros.py::test_stereo_pair_left_and_right_with_their_disparity, a rospy
program the test runs against its own master (ros.probe); it prints one JSON value on its last line."""
import json, rospy
from sensor_msgs.msg import CameraInfo, Image
rospy.init_node('probe')
out = {'topics': sorted(t for t, _ in rospy.get_published_topics() if 'stereo' in t or 'middle' in t)}
for side in ('left', 'right'):
    image = rospy.wait_for_message('/stereo/%s/image_raw' % side, Image, 30)
    info = rospy.wait_for_message('/stereo/%s/camera_info' % side, CameraInfo, 10)
    data = bytes(image.data)
    # columns of the middle row where the pixel is red (the post), and the wall's grey
    row = image.height // 2
    red = [u for u in range(image.width)
           if data[(row * image.width + u) * 3] > 2 * data[(row * image.width + u) * 3 + 1] + 20]
    out[side] = {'frame': image.header.frame_id, 'size': [image.width, image.height, image.encoding],
                 'red': red, 'P': list(info.P), 'K': list(info.K), 'stamp': image.header.stamp.to_sec()}
print(json.dumps(out))
