"""The ROS side of
test_gazebo_ros.py::test_model_and_link_states_are_published_on_every_step_with_scoped_names, a rospy program
the test runs against its own master (ros.probe); it prints one JSON value on its last line."""
from gazebo_services_probe import *  # noqa: F401,F403  (the node, srv, pose, result, out)
stamps = []
sub = rospy.Subscriber('/gazebo/model_states', ModelStates, lambda m: stamps.append(rospy.get_rostime().to_sec()))
time.sleep(1.0)
out_while_paused = len(stamps)
srv('unpause_physics', Empty)()
time.sleep(3.0)
sub.unregister()
srv('pause_physics', Empty)()
time.sleep(0.5)
srv('unpause_physics', Empty)()
links = rospy.wait_for_message('/gazebo/link_states', LinkStates, 30)
models = rospy.wait_for_message('/gazebo/model_states', ModelStates, 30)
srv('pause_physics', Empty)()
get_link = srv('get_link_state', GetLinkState)('tianracer::laser_link', '')
i = links.name.index('tianracer::laser_link')
out = {'links': links.name, 'models': models.name, 'laser_z': [links.pose[i].position.z,
       get_link.link_state.pose.position.z], 'count': len(stamps), 'span': stamps[-1] - stamps[0],
       'while_paused': out_while_paused}
print(json.dumps(out))
