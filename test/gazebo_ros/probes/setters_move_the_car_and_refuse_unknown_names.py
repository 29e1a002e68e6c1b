"""The ROS side of test_gazebo_ros.py::test_setters_move_the_car_and_refuse_unknown_names, a rospy program the
test runs against its own master (ros.probe); it prints one JSON value on its last line."""
from gazebo_services_probe import *  # noqa: F401,F403  (the node, srv, pose, result, out)
get = srv('get_model_state', GetModelState)
set_model = srv('set_model_state', SetModelState)
out['set'] = result(set_model(ModelState('tianracer', pose(1.0, 2.0, 0.0, 1.0), Twist(), 'world')))
m = get('tianracer', '')
out['after_set'] = [m.pose.position.x, m.pose.position.y, 2 * math.atan2(m.pose.orientation.z, m.pose.orientation.w)]
out['set_unknown'] = result(set_model(ModelState('nobody', pose(), Twist(), '')))
out['set_bad_frame'] = result(set_model(ModelState('tianracer', pose(), Twist(), 'nowhere')))
pub = connected_publisher('/gazebo/set_model_state', ModelState, queue_size=1, latch=True)
pub.publish(ModelState('tianracer', pose(-1.0, 0.5), Twist(), 'world'))
deadline = time.time() + 20
while time.time() < deadline and abs(get('tianracer', '').pose.position.x + 1.0) > 1e-3:
    time.sleep(0.1)
out['by_topic'] = get('tianracer', '').pose.position.x
set_link = srv('set_link_state', SetLinkState)
out['set_link'] = result(set_link(LinkState('tianracer::base_footprint', pose(3.0, 0.0), Twist(), '')))
out['after_set_link'] = get('tianracer', '').pose.position.x
out['set_link_unknown'] = result(set_link(LinkState('tianracer::nowhere', pose(), Twist(), '')))
out['set_link_bad_frame'] = result(set_link(LinkState('tianracer::base_footprint', pose(), Twist(), 'nowhere')))
config = srv('set_model_configuration', SetModelConfiguration)
out['config'] = result(config('tianracer', '', ['left_steering_hinge_joint'], [0.3]))
hinge = srv('get_link_state', GetLinkState)('tianracer::left_steering_hinge', 'tianracer::base_link').link_state.pose
out['hinge_yaw'] = 2 * math.atan2(hinge.orientation.z, hinge.orientation.w)
out['config_unknown'] = result(config('nobody', '', [], []))
out['config_lengths'] = result(config('tianracer', '', ['left_steering_hinge_joint'], []))
print(json.dumps(out))
