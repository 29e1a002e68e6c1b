"""The ROS side of test_fuzz.py::test_the_node_survives_the_fuzzed_urdfs: spawns the fuzzed copies of the
car's URDF of seeds FIRST to LAST - 1 (test/helpers/fuzz_cases.py) through /gazebo/spawn_urdf_model and
deletes each that spawned,

    spawn_the_fuzzed_urdfs.py FIRST LAST

and prints how many spawned on its last line."""
import json, sys, time, rospy
import fuzz_cases  # test/helpers, on the harness's PYTHONPATH
from gazebo_msgs.srv import SpawnModel, DeleteModel
from tianracer_description.tianracer import tianracer_urdf
from geometry_msgs.msg import Pose
first, last = int(sys.argv[1]), int(sys.argv[2])
rospy.wait_for_service('/gazebo/spawn_urdf_model', 30)
spawn = rospy.ServiceProxy('/gazebo/spawn_urdf_model', SpawnModel)
delete = rospy.ServiceProxy('/gazebo/delete_model', DeleteModel)
urdf = tianracer_urdf()
spawned = 0
for seed in range(first, last):
    text, pose, _ = fuzz_cases.mutated_urdf(seed, urdf)
    start = Pose()
    start.position.z = pose[2]
    start.orientation.w = 1.0
    if spawn(model_name='fuzz%d' % seed, model_xml=text, robot_namespace='', initial_pose=start).success:
        spawned += 1
        time.sleep(0.05)
        assert delete(model_name='fuzz%d' % seed).success
print(json.dumps(spawned))
