"""The ROS side of
test_mimic_joint_ros.py::test_the_mimic_joint_plugin_reads_its_pid_gains_from_the_parameter_server, a rospy
program the test runs against its own master (ros.probe); it prints one JSON value on its last line."""
import json, rospy
from gazebo_msgs.msg import LinkStates
from std_msgs.msg import Float64
from ros_harness import connected_publisher
rospy.init_node('probe')
pub = connected_publisher('/gripper/finger_controller/command', Float64, queue_size=1, latch=True)
pub.publish(Float64(0.03))
rospy.sleep(2.0)
links = rospy.wait_for_message('/gazebo/link_states', LinkStates, 10)
y = {name.split('::')[1]: pose.position.y for name, pose in zip(links.name, links.pose)}
print(json.dumps(y))
