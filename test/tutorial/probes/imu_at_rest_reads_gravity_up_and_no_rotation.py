"""The ROS side of test_two_cars.py::test_imu_at_rest_reads_gravity_up_and_no_rotation, a rospy program the
test runs against its own master (ros.probe); it prints one JSON value on its last line."""
import json, rospy
from sensor_msgs.msg import Imu
rospy.init_node('imu_probe', anonymous=True)
m = rospy.wait_for_message('/car2/imu', Imu, timeout=30)
a, w = m.linear_acceleration, m.angular_velocity
print(json.dumps({'frame': m.header.frame_id, 'a': [a.x, a.y, a.z], 'w': [w.x, w.y, w.z]}))
