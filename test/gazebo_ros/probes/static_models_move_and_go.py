"""The ROS side of test_static_world_models.py: the sign in model_states and get_model_properties, then what the
post's lidar (its middle ray) and camera (its middle pixel) see where the file put the sign, after
set_model_state moved it 3 m sideways, back, and after delete_model; it prints one JSON value on its last
line."""
from gazebo_services_probe import *  # noqa: F401,F403  (the node, srv, pose, result, out)
from rosgraph_msgs.msg import Clock
from sensor_msgs.msg import Image, LaserScan


def seen():
    """The middle ray's range and whether the middle pixel is red, from messages stamped after now."""
    after = rospy.wait_for_message('/clock', Clock, timeout=30).clock  # the simulated time now
    while True:
        scan = rospy.wait_for_message('/post/scan', LaserScan, timeout=30)
        if scan.header.stamp > after:
            break
    while True:
        image = rospy.wait_for_message('/post/camera/image_raw', Image, timeout=30)
        if image.header.stamp > after:
            break
    middle = (image.height // 2) * image.step + (image.width // 2) * 3
    r, g, b = image.data[middle], image.data[middle + 1], image.data[middle + 2]
    return {'range': scan.ranges[len(scan.ranges) // 2], 'red': r > 2 * g + 30 and r > 2 * b + 30, 'rgb': [r, g, b]}


def listed(name):
    states = rospy.wait_for_message('/gazebo/model_states', ModelStates, timeout=30)
    p = states.pose[list(states.name).index(name)].position
    return [p.x, p.y, p.z]


def state(name):
    p = srv('get_model_state', GetModelState)(name, '').pose.position
    return [p.x, p.y, p.z]


out['models'] = list(rospy.wait_for_message('/gazebo/model_states', ModelStates, timeout=30).name)
props = srv('get_model_properties', GetModelProperties)('sign')
out['sign_props'] = {'success': bool(props.success), 'body_names': list(props.body_names),
                     'geom_names': list(props.geom_names), 'joint_names': list(props.joint_names),
                     'is_static': bool(props.is_static)}
out['sign_state'] = state('sign')
out['before'] = seen()
move = srv('set_model_state', SetModelState)
out['moved_set'] = result(move(ModelState('sign', pose(2.0, 3.0, 0.5), Twist(), 'world')))
out['moved_state'] = state('sign')
out['moved_listed'] = listed('sign')
out['moved'] = seen()
move(ModelState('sign', pose(2.0, 0.0, 0.5), Twist(), 'world'))
out['back'] = seen()
out['delete'] = result(srv('delete_model', DeleteModel)('sign'))
out['after_delete'] = list(srv('get_world_properties', GetWorldProperties)().model_names)
out['deleted'] = seen()
print(json.dumps(out))
