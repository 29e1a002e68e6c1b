"""The ROS side of test_gazebo_ros.py::test_spawn_and_delete_with_gazebo_ros_messages, a rospy program the test
runs against its own master (ros.probe) with the car's URDF file; it prints one JSON value on its last line."""
import sys

from gazebo_services_probe import *  # noqa: F401,F403  (the node, srv, pose, result, out)
template = open(sys.argv[1]).read()  # the car's URDF
urdf = lambda ns: template.replace('/tianracer', ns)   # each car its own controller namespace
spawn = srv('spawn_urdf_model', SpawnModel)
sdf_spawn = srv('spawn_sdf_model', SpawnModel)
out['second'] = result(spawn('car2', urdf('/car2'), '/car2', pose(0.0, 1.0), 'tianracer::base_footprint'))
out['second_at'] = srv('get_model_state', GetModelState)('car2', '').pose.position.y
out['again'] = result(spawn('car2', urdf('/car2b'), '/car2b', pose(), ''))
out['bad_frame'] = result(spawn('car3', urdf('/car3'), '/car3', pose(), 'nowhere'))
try:
    spawn('box', '<sdf version="1.6"><model name="box"/></sdf>', '', pose(), '')
    out['not_urdf'] = 'answered'
except rospy.ServiceException:
    out['not_urdf'] = 'call failed'
sdf = sdf_spawn('box', '<sdf version="1.6"><model name="box"/></sdf>', '', pose(), '')
out['sdf'] = result(sdf)
out['sdf_takes_urdf'] = result(sdf_spawn('car4', urdf('/car4'), '/car4', pose(0.0, -1.0), ''))
delete = srv('delete_model', DeleteModel)
out['delete'] = result(delete('car2'))
out['delete_again'] = result(delete('car2'))
out['names'] = srv('get_world_properties', GetWorldProperties)().model_names
print(json.dumps(out))
