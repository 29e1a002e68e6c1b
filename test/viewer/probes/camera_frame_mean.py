"""One frame of the camera TOPIC: its encoding, size and mean colour, for test_viewer.py's camera overlay,

    camera_frame_mean.py TOPIC

printed as one JSON object on its last line."""
import json, rospy, numpy, sys
from sensor_msgs.msg import Image
rospy.init_node('camera_probe', anonymous=True)
m = rospy.wait_for_message(sys.argv[1], Image, timeout=10)
pixels = numpy.frombuffer(m.data, numpy.uint8).reshape(m.height, m.step)[:, :3 * m.width]
print(json.dumps({'encoding': m.encoding, 'size': [m.width, m.height],
                  'mean': pixels.reshape(m.height, m.width, 3).reshape(-1, 3).mean(axis=0).tolist()}))
