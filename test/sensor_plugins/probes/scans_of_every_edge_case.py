"""The ROS side of test_sensor_plugins_ros.py::test_the_node_survives_whatever_a_sensor_asks_for_on_every_embree_kernel:
a scan of each lidar named (on /NAME) and the one-pixel camera's image,

    scans_of_every_edge_case.py NAME...

prints {name: {'n', 'finite', 'below_min'}, 'one_pixel': {'n'}} on its last line."""
import json, math, rospy, sys
from sensor_msgs.msg import Image, LaserScan
rospy.init_node('probe', anonymous=True)
out = {}
for name in sys.argv[1:]:
    m = rospy.wait_for_message('/' + name, LaserScan, timeout=30)
    out[name] = {'n': len(m.ranges), 'finite': sum(math.isfinite(r) for r in m.ranges),
                 'below_min': sum(r < m.range_min for r in m.ranges)}
image = rospy.wait_for_message('/one_pixel/image_raw', Image, timeout=30)
out['one_pixel'] = {'n': image.width * image.height}
print(json.dumps(out))
