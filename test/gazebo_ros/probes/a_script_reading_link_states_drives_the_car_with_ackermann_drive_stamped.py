"""The ROS side of
test_gazebo_ros.py::test_a_script_reading_link_states_drives_the_car_with_ackermann_drive_stamped, a rospy
program the test runs against its own master (ros.probe); it prints one JSON value on its last line."""
from gazebo_services_probe import *  # noqa: F401,F403  (the node, srv, pose, result, out)
m = srv('get_model_state', GetModelState)('tianracer', '')
print(json.dumps([m.pose.position.x, m.pose.position.y]))
