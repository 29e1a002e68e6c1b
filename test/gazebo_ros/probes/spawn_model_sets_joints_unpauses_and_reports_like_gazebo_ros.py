"""The ROS side of test_gazebo_ros.py::test_spawn_model_sets_joints_unpauses_and_reports_like_gazebo_ros, a
rospy program the test runs against its own master (ros.probe); it prints one JSON value on its last line."""
from gazebo_services_probe import *  # noqa: F401,F403  (the node, srv, pose, result, out)
hinge = srv('get_link_state', GetLinkState)('car::left_steering_hinge', 'car::base_link').link_state.pose
out = {'hinge': 2 * math.atan2(hinge.orientation.z, hinge.orientation.w),
       'x': srv('get_model_state', GetModelState)('car', '').pose.position.x,
       'paused': srv('get_physics_properties', GetPhysicsProperties)().pause}
print(json.dumps(out))
