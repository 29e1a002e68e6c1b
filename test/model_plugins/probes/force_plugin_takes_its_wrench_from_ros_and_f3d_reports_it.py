"""The ROS side of test_force_and_f3d_ros.py::test_force_plugin_takes_its_wrench_from_ros_and_f3d_reports_it,
a rospy program the test runs against its own master (ros.probe); it prints one JSON value on its last
line."""
import json, rospy
from gazebo_msgs.srv import GetModelState
from geometry_msgs.msg import Wrench, WrenchStamped
from ros_harness import connected_publisher
rospy.init_node('probe')
state = rospy.ServiceProxy('/gazebo/get_model_state', GetModelState)
pub = connected_publisher('/force', Wrench, queue_size=1, latch=True)
wrench = Wrench()
wrench.force.z = 60.0
before = state('pushed', '').pose.position.z
pub.publish(wrench)
rospy.sleep(1.0)
truth = rospy.wait_for_message('/force_truth', WrenchStamped, 10)
# gazebo_ros's apply_body_wrench runs before the model plugins: f3d sees the sum
from gazebo_msgs.srv import ApplyBodyWrench
apply = rospy.ServiceProxy('/gazebo/apply_body_wrench', ApplyBodyWrench)
extra = Wrench()
extra.force.x = 5.0
apply('pushed::base_link', '', None, extra, rospy.Time(0), rospy.Duration(-1))
rospy.sleep(0.2)
both = rospy.wait_for_message('/force_truth', WrenchStamped, 10).wrench.force
print(json.dumps({'both': [both.x, both.y, both.z], 'rise': state('pushed', '').pose.position.z - before, 'frame': truth.header.frame_id,
                  'force': [truth.wrench.force.x, truth.wrench.force.y, truth.wrench.force.z],
                  'stamped': truth.header.stamp.to_sec()}))
