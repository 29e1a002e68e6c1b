"""The ROS side of test_gazebo_ros.py::test_efforts_physics_and_simulation_control, a rospy program the test
runs against its own master (ros.probe); it prints one JSON value on its last line."""
from gazebo_services_probe import *  # noqa: F401,F403  (the node, srv, pose, result, out)
get = srv('get_model_state', GetModelState)
clock = lambda: get('tianracer', '').header.stamp.to_sec()
wrench = srv('apply_body_wrench', ApplyBodyWrench)
lift = Wrench(force=Vector3(0, 0, 60.0))   # 2.69 kg: 60 N up beats 26 N of weight
out['wrench'] = result(wrench('tianracer::base_link', '', Point(), lift, rospy.Time(0), rospy.Duration(-1)))
out['wrench_unknown'] = result(wrench('tianracer::nowhere', '', Point(), lift, rospy.Time(0), rospy.Duration(-1)))
out['wrench_bad_frame'] = result(wrench('tianracer::base_link', 'nowhere', Point(), lift, rospy.Time(0), rospy.Duration(-1)))
srv('unpause_physics', Empty)()
start = clock()
while clock() < start + 0.3:
    time.sleep(0.05)
out['lifted'] = get('tianracer', '').pose.position.z
srv('clear_body_wrenches', BodyRequest)('tianracer::base_link')
srv('pause_physics', Empty)()
out['paused_clock'] = [clock(), (time.sleep(0.5), clock())[1]]
effort = srv('apply_joint_effort', ApplyJointEffort)
out['effort'] = result(effort('left_steering_hinge_joint', 0.5, rospy.Time(0), rospy.Duration(0.2)))
out['effort_unknown'] = result(effort('no_such_joint', 0.5, rospy.Time(0), rospy.Duration(0.2)))
srv('clear_joint_forces', JointRequest)('left_steering_hinge_joint')
set_physics = srv('set_physics_properties', SetPhysicsProperties)
phys = srv('get_physics_properties', GetPhysicsProperties)()
out['set_physics'] = result(set_physics(0.002, 250.0, Vector3(0, 0, -3.0), phys.ode_config))
p = srv('get_physics_properties', GetPhysicsProperties)()
out['new_physics'] = [p.time_step, p.max_update_rate, p.gravity.z]
out['bad_step'] = result(set_physics(0.0, 250.0, Vector3(0, 0, -3.0), phys.ode_config))
srv('reset_world', Empty)()
out['reset_world'] = [get('tianracer', '').pose.position.z, clock() > 0.2]
srv('reset_simulation', Empty)()
out['reset_simulation'] = clock()
print(json.dumps(out))
