"""The ROS side of test_node_bad_settings.py::test_a_robot_with_a_bad_ros_name_is_refused_and_the_node_keeps_running:
spawns the robot of BAD_URDF (refused) and then that of GOOD_URDF through /gazebo/spawn_urdf_model,

    spawn_a_bad_and_a_good_robot.py BAD_URDF GOOD_URDF

and prints [bad's success, bad's status message, good's success] on its last line."""
import json, rospy, sys
from gazebo_msgs.srv import SpawnModel
bad_urdf, good_urdf = (open(path).read() for path in sys.argv[1:3])
call = rospy.ServiceProxy('/gazebo/spawn_urdf_model', SpawnModel)
bad = call(model_name='bad', model_xml=bad_urdf, robot_namespace='')
good = call(model_name='good', model_xml=good_urdf, robot_namespace='')
print(json.dumps([bad.success, bad.status_message, good.success]))
