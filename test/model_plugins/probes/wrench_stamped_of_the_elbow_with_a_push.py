"""The ROS side of test_ft_sensor_ros.py::test_wrench_stamped_of_the_elbow_with_a_push, a rospy program the
test runs against its own master (ros.probe); it prints one JSON value on its last line."""
import json, rospy
from geometry_msgs.msg import Wrench, WrenchStamped
from ros_harness import connected_publisher
rospy.init_node('probe')
rospy.sleep(1.0)
def reading():
    m = rospy.wait_for_message('/elbow_ft', WrenchStamped, 10)
    return {'frame': m.header.frame_id, 'stamp': m.header.stamp.to_sec(),
            'force': [m.wrench.force.x, m.wrench.force.y, m.wrench.force.z],
            'torque': [m.wrench.torque.x, m.wrench.torque.y, m.wrench.torque.z]}
held = reading()
push = connected_publisher('/push', Wrench, queue_size=1, latch=True)
w = Wrench()
w.force.y = 5.0
push.publish(w)
rospy.sleep(1.0)
print(json.dumps({'held': held, 'pushed': reading()}))
