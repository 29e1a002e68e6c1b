"""The ROS side of test_gazebo_ros.py::test_queries_answer_with_gazebo_ros_flags_and_messages, a rospy program
the test runs against its own master (ros.probe); it prints one JSON value on its last line."""
from gazebo_services_probe import *  # noqa: F401,F403  (the node, srv, pose, result, out)
world = srv('get_world_properties', GetWorldProperties)()
out['world'] = [world.model_names, world.success, world.status_message]
props = srv('get_model_properties', GetModelProperties)
p = props('tianracer')
out['props'] = [result(p), 'base_link' in p.body_names, 'left_rear_wheel_joint' in p.joint_names]
out['props_unknown'] = result(props('nobody'))
get = srv('get_model_state', GetModelState)
m = get('tianracer', '')
out['model'] = [result(m), m.pose.position.z, m.header.frame_id]
out['model_unknown'] = result(get('nobody', ''))
out['model_bad_frame'] = result(get('tianracer', 'nowhere'))
rel = get('tianracer', 'tianracer::base_link')
out['model_relative'] = [result(rel), rel.pose.position.x, rel.pose.position.z]
link = srv('get_link_state', GetLinkState)
l = link('tianracer::laser_link', '')
out['link'] = [result(l), l.link_state.pose.position.z]
out['link_unknown'] = result(link('tianracer::nowhere', ''))
out['link_unscoped'] = result(link('laser_link', ''))
out['link_bad_frame'] = result(link('tianracer::laser_link', 'nowhere'))
phys = srv('get_physics_properties', GetPhysicsProperties)()
out['physics'] = [result(phys), phys.time_step, phys.pause, phys.gravity.z, phys.max_update_rate]
print(json.dumps(out))
