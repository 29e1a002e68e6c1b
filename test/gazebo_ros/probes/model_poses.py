"""Where each model named on the command line is and what it is made of (test_spawn_sdf.py's spawn_model
test), a rospy program run against the test's master (ros.probe):

    model_poses.py MODEL...

prints {MODEL: [x, y, z, yaw], 'bodies': {MODEL: [...]}, 'geoms': {MODEL: [...]}, 'static': {MODEL: bool}}
on its last line."""
import sys

from gazebo_services_probe import *  # noqa: F401,F403  (the node, srv, pose, result, out)
get = srv('get_model_state', GetModelState)
properties = srv('get_model_properties', GetModelProperties)
out['bodies'], out['geoms'], out['static'] = {}, {}, {}
for name in sys.argv[1:]:
    p = get(name, '').pose
    out[name] = [p.position.x, p.position.y, p.position.z, 2 * math.atan2(p.orientation.z, p.orientation.w)]
    props = properties(name)
    out['bodies'][name], out['geoms'][name] = list(props.body_names), list(props.geom_names)
    out['static'][name] = bool(props.is_static)
print(json.dumps(out))
