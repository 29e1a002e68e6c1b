"""The ROS side of test_spawn_sdf.py::test_world_file_models_are_gazebo_ros_models: the world file's crate
and pendulum (and a ball-jointed bob) in /gazebo/model_states, the crate falling and resting once
unpaused, set_model_state and reset_world on them, get_model_properties, get_joint_properties of the
ball joint, delete_model; it prints one JSON value on its last line."""
from gazebo_services_probe import *  # noqa: F401,F403  (the node, srv, pose, result, out)
get = srv('get_model_state', GetModelState)
link = srv('get_link_state', GetLinkState)


def xyz(name):
    p = get(name, '').pose.position
    return [p.x, p.y, p.z]


def pitch(link_name):
    q = link(link_name, '').link_state.pose.orientation
    return math.asin(max(-1.0, min(1.0, 2 * (q.w * q.y - q.z * q.x))))


def props(name):
    r = srv('get_model_properties', GetModelProperties)(name)
    return {'success': bool(r.success), 'body_names': list(r.body_names), 'geom_names': list(r.geom_names),
            'joint_names': list(r.joint_names), 'is_static': bool(r.is_static)}


def link_xyz(name):
    p = link(name, '').link_state.pose.position
    return [p.x, p.y, p.z]


def bob():
    p = link('swivel::bob', '').link_state.pose.position
    return [p.x, p.y, p.z]


out['start'] = xyz('crate')
out['pendulum_start'] = pitch('pendulum::bar')
swivel_start = bob()
srv('unpause_physics', Empty)()
states = rospy.wait_for_message('/gazebo/model_states', ModelStates, timeout=30)
out['model_states'] = list(states.name)
# 1 m falls in 0.45 s; rested well within 2 s of simulated time
start = rospy.get_time()
while rospy.get_time() - start < 2.0:
    time.sleep(0.05)
m = get('crate', '')
out['rested'] = [m.pose.position.x, m.pose.position.y, m.pose.position.z]
out['rested_speed'] = m.twist.linear.z
out['pendulum_swung'] = abs(pitch('pendulum::bar') - out['pendulum_start'])
out['swivel_swung'] = math.dist(bob(), swivel_start)
out['link_states'] = list(rospy.wait_for_message('/gazebo/link_states', LinkStates, timeout=30).name)
out['pair_rested'] = [link_xyz('pair::left'), link_xyz('pair::right')]
srv('pause_physics', Empty)()
out['set'] = result(srv('set_model_state', SetModelState)(ModelState('crate', pose(1.0, -4.0, 0.5), Twist(), 'world')))
out['moved'] = xyz('crate')
srv('reset_world', Empty)()
out['reset_crate'] = xyz('crate')
out['reset_pendulum'] = pitch('pendulum::bar')
out['props'] = props('pendulum')
out['crate_props'] = props('crate')
out['swivel_props'] = props('swivel')
out['pair_props'] = props('pair')
# reset_world put the pair back in the air; its model frame is its left box's (the file's link pose).
srv('set_model_state', SetModelState)(ModelState('pair', pose(-5.0, 5.0, 0.1), Twist(), 'world'))
out['pair_moved'] = [link_xyz('pair::left'), link_xyz('pair::right')]
srv('delete_model', DeleteModel)('pair')
out['after_pair_delete'] = list(srv('get_world_properties', GetWorldProperties)().model_names)
out['pair_link_after_delete'] = bool(link('pair::right', '').success)
socket = srv('get_joint_properties', GetJointProperties)('socket')
out['socket'] = [bool(socket.success), list(socket.position), list(socket.rate)]
out['delete'] = result(srv('delete_model', DeleteModel)('crate'))
out['after_delete'] = list(srv('get_world_properties', GetWorldProperties)().model_names)
print(json.dumps(out))
