"""The ROS side of test_fuzz.py::test_the_node_survives_the_fuzzed_models: spawns the fuzzed models of
seeds FIRST to LAST - 1 (test/helpers/fuzz_cases.py) through gazebo_ros's spawn service and deletes each
that spawned,

    spawn_the_fuzzed_models.py urdf FIRST LAST        # mutated copies of the car's URDF, /gazebo/spawn_urdf_model
    spawn_the_fuzzed_models.py sdf_model FIRST LAST   # mutated worlds of moving SDF models, /gazebo/spawn_sdf_model

and prints how many spawned on its last line."""
import json, sys, time, rospy
import fuzz_cases  # test/helpers, on the harness's PYTHONPATH
from gazebo_msgs.srv import SpawnModel, DeleteModel
from tianracer_description.tianracer import tianracer_urdf
from geometry_msgs.msg import Pose
kind, first, last = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
service = {'urdf': '/gazebo/spawn_urdf_model', 'sdf_model': '/gazebo/spawn_sdf_model'}[kind]
rospy.wait_for_service(service, 30)
spawn = rospy.ServiceProxy(service, SpawnModel)
delete = rospy.ServiceProxy('/gazebo/delete_model', DeleteModel)
urdf = tianracer_urdf()
spawned = 0
for seed in range(first, last):
    start = Pose()
    start.orientation.w = 1.0
    if kind == 'urdf':
        text, pose, _ = fuzz_cases.mutated_urdf(seed, urdf)
        start.position.z = pose[2]
    else:
        text, _ = fuzz_cases.mutated_sdf_models(seed)  # the service spawns its first model
        start.position.z = 1.0
    if spawn(model_name='fuzz%d' % seed, model_xml=text, robot_namespace='', initial_pose=start).success:
        spawned += 1
        time.sleep(0.05)
        assert delete(model_name='fuzz%d' % seed).success
print(json.dumps(spawned))
