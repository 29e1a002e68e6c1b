"""The ROS side of test_spawn_sdf.py::test_spawn_sdf_model_service_names_places_refuses_and_deletes: SDF
text to /gazebo/spawn_sdf_model under another name and at an initial pose, a second spawn of the
name, a model the plant refuses, XML that is neither SDF nor URDF, SDF to spawn_urdf_model, then
delete_model; it prints one JSON value on its last line."""
from gazebo_services_probe import *  # noqa: F401,F403  (the node, srv, pose, result, out)


def box(name, pose_text, mass=1.0):
    return ('<?xml version="1.0"?><sdf version="1.6"><model name="%s"><pose>%s</pose><link name="body">'
            '<inertial><mass>%g</mass><inertia><ixx>0.01</ixx><iyy>0.01</iyy><izz>0.01</izz></inertia></inertial>'
            '<collision name="shell"><geometry><box><size>0.1 0.1 0.1</size></box></geometry></collision>'
            '</link></model></sdf>' % (name, pose_text, mass))


spawn = srv('spawn_sdf_model', SpawnModel)
get = srv('get_model_state', GetModelState)
world = srv('get_world_properties', GetWorldProperties)
out['spawn'] = result(spawn('service_box', box('named_in_sdf', '1 0 0.2 0 0 0'), '', pose(0.0, -1.0, 0.0, math.pi / 2), ''))
p = get('service_box', '').pose
out['at'] = [p.position.x, p.position.y, p.position.z, 2 * math.atan2(p.orientation.z, p.orientation.w)]
names = world().model_names
out['names_have'] = ['service_box' in names, 'named_in_sdf' in names]
out['again'] = result(spawn('service_box', box('other', '0 0 0 0 0 0'), '', pose(), ''))
out['bad_mass'] = result(spawn('heavy', box('heavy', '0 0 0 0 0 0', mass=-1.0), '', pose(), ''))
out['not_sdf'] = result(spawn('plain', '<model name="plain"/>', '', pose(), ''))
try:
    srv('spawn_urdf_model', SpawnModel)('urdf_box', box('urdf_box', '0 0 0 0 0 0'), '', pose(), '')
    out['urdf_service_refuses_sdf'] = 'answered'
except rospy.ServiceException:
    out['urdf_service_refuses_sdf'] = 'call failed'
out['delete'] = result(srv('delete_model', DeleteModel)('service_box'))
out['after_delete'] = 'service_box' in world().model_names
out['still_running'] = bool(world().success)
print(json.dumps(out))
