"""gazebo_plugins' libgazebo_ros_diff_drive.so on the plant, through its Python module, on the
diff_bot written for the tests (test/fixtures/urdf/diff_bot.urdf): upstream's parameters, its
motors, ramp, torque limit, odometry (world and encoder) and frames."""
import math

import pytest

from plant_helpers import DIFF_RADIUS, DIFF_SEPARATION, diff_bot, logged, spawned, yaw_of


def drive(world, robot, linear, angular, seconds):
    assert robot.plugin_send('diff_drive', 'cmd_vel', (linear, angular))
    world.step(int(round(seconds / world.time_step)))


def test_the_plugin_loads_with_upstreams_topics():
    world, robot = spawned()
    assert robot.model_plugins == ['diff_drive']
    topics = robot.plugin_topics('diff_drive')
    assert topics['subscribes'] == ['cmd_vel']
    assert topics['publishes'] == ['odom', '/tf', 'joint_states'], 'publishWheelJointState true'
    assert not [m for m in logged(world, 'WARN') if 'diff_drive' in m], 'legacyMode and rosDebugLevel: ignored silently'
    quiet = spawned(diff_bot(publishWheelJointState=None, publishTf='false'))[1]
    assert quiet.plugin_topics('diff_drive')['publishes'] == [], 'publishTf false: no odometry, no transform'


def test_a_twist_drives_the_wheels_and_the_robot():
    world, robot = spawned()
    start = robot.base_pose()
    drive(world, robot, 0.2, 0.0, 3.0)
    left, right = robot.joint_state('wheel_left_joint')[1], robot.joint_state('wheel_right_joint')[1]
    assert left == pytest.approx(0.2 / DIFF_RADIUS, rel=0.01) and right == pytest.approx(left, rel=0.01)
    linear, _ = robot.base_twist()
    assert math.hypot(linear[0], linear[1]) == pytest.approx(0.2, rel=0.03)
    travelled = robot.base_pose()[0] - start[0]
    assert 0.5 < travelled < 0.6, 'a ramp of 1 m/s^2 to 0.2 m/s, then 2.8 s at it: about 0.58 m'


def test_turning_in_place_at_the_asked_rate():
    world, robot = spawned()
    drive(world, robot, 0.0, 1.0, 1.0)
    yaw_before = yaw_of(robot.base_pose())
    world.step(500)
    turned = math.remainder(yaw_of(robot.base_pose()) - yaw_before, 2 * math.pi)
    assert turned == pytest.approx(0.5, rel=0.05)
    left, right = robot.joint_state('wheel_left_joint')[1], robot.joint_state('wheel_right_joint')[1]
    assert right == pytest.approx(DIFF_SEPARATION / 2 / DIFF_RADIUS, rel=0.02) and left == pytest.approx(-right, rel=0.02)


def test_wheel_acceleration_ramps_and_zero_sets_the_speed_at_once():
    for accel, expected in ((1.0, 0.05), (0.0, 0.2)):
        world, robot = spawned(diff_bot(wheelAcceleration=accel))
        drive(world, robot, 0.2, 0.0, 0.05)
        speed = robot.joint_state('wheel_left_joint')[1] * DIFF_RADIUS
        assert speed == pytest.approx(expected, abs=0.04), f'wheelAcceleration {accel}: {speed} m/s after 50 ms'


def test_wheel_torque_bounds_the_motors():
    world, robot = spawned(diff_bot(wheelTorque=0, wheelAcceleration=0))
    drive(world, robot, 0.5, 0.0, 1.0)
    assert abs(robot.base_pose()[0]) < 1e-3, 'no torque: the wheels cannot turn the robot'
    world, robot = spawned(diff_bot(wheelTorque=0.002, wheelAcceleration=0))
    drive(world, robot, 0.5, 0.0, 0.5)
    speed = robot.base_twist()[0][0]
    # Two wheels of 2 mN m over 35 mm push at most 0.114 N on 1.11 kg: 0.1 m/s^2, 0.05 m/s in 0.5 s.
    assert 0.0 < speed < 0.06


def test_world_odometry_is_the_models_pose_and_its_twist_in_the_base_frame():
    world, robot = spawned()
    drive(world, robot, 0.2, 0.5, 2.0)
    world.step(34)  # one update period past the last publish at most
    odom = robot.plugin_latest('diff_drive', 'odom')
    assert world.time - odom['stamp'] <= 0.035, 'at updateRate 30'
    assert (odom['frame_id'], odom['child_frame_id']) == ('odom', 'base_footprint'), \
        'no tf_prefix parameter: no prefix (noetic gazebo_ros_utils)'
    pose = robot.base_pose()
    assert odom['pose'][:3] == pytest.approx(pose[:3], abs=0.01)
    assert odom['linear'] == pytest.approx(0.2, rel=0.05) and odom['angular'] == pytest.approx(0.5, rel=0.05)
    assert abs(odom['twist'][1]) < 0.01, 'the twist is in the base frame: no sideways speed'
    tf = robot.plugin_latest('diff_drive', '/tf')
    assert (tf['frame_id'], tf['child_frame_id']) == ('odom', 'base_footprint')
    assert list(tf['pose']) == list(odom['pose'])
    joints = robot.plugin_latest('diff_drive', 'joint_states')
    assert joints['name'] == ['wheel_right_joint', 'wheel_left_joint'] and len(joints['position']) == 2
    assert joints['velocity'] == [] and joints['effort'] == [], 'names and positions only, as upstream'


def test_encoder_odometry_integrates_the_wheels_from_zero():
    world, robot = spawned(diff_bot(odometrySource='encoder'))
    start = robot.base_pose()
    drive(world, robot, 0.2, 0.0, 2.0)
    odom = robot.plugin_latest('diff_drive', 'odom')
    travelled = robot.base_pose()[0] - start[0]
    assert odom['x'] == pytest.approx(travelled, rel=0.05), 'the wheels roll without slipping'
    assert abs(odom['y']) < 0.01 and odom['linear'] == pytest.approx(0.2, rel=0.05)


def test_namespaces_and_frames_as_gazebo_ros_gives_them():
    world, robot = spawned(namespace='/')
    drive(world, robot, 0.1, 0.0, 0.1)
    assert robot.plugin_latest('diff_drive', 'odom')['frame_id'] == 'odom', "spawn_model's '/': no prefix"
    world, robot = spawned(diff_bot(robotNamespace='/robot_1'))
    drive(world, robot, 0.1, 0.0, 0.1)
    assert robot.plugin_latest('diff_drive', 'odom')['child_frame_id'] == 'base_footprint', \
        'a namespace is no prefix (noetic gazebo_ros_utils reads only a tf_prefix parameter)'
    world, robot = spawned(diff_bot(robotNamespace='/robot_1'), params={'robot_1': {'tf_prefix': 'robot_1'}})
    drive(world, robot, 0.1, 0.0, 0.1)
    assert robot.plugin_latest('diff_drive', 'odom')['child_frame_id'] == 'robot_1/base_footprint', \
        "the tf_prefix parameter found from the plugin's namespace"
    world, robot = spawned(diff_bot(robotNamespace='/robot_1/left'), params={'robot_1': {'tf_prefix': 'fleet'}})
    drive(world, robot, 0.1, 0.0, 0.1)
    assert robot.plugin_latest('diff_drive', 'odom')['child_frame_id'] == 'fleet/base_footprint', 'or a parent\'s'


def test_a_reset_stops_the_robot_and_zeroes_the_encoders():
    world, robot = spawned(diff_bot(odometrySource='encoder'))
    drive(world, robot, 0.2, 0.0, 1.0)
    world.reset_world()
    world.step(300)
    assert abs(robot.base_twist()[0][0]) < 0.01, 'the command is forgotten'
    assert abs(robot.plugin_latest('diff_drive', 'odom')['x']) < 0.01


def test_bad_input_is_refused_naming_what_and_the_robot_still_spawns():
    world, robot = spawned(diff_bot(leftJoint='no_such_joint'))
    assert robot.model_plugins == []
    assert any("plugin 'diff_drive' (libgazebo_ros_diff_drive.so) <leftJoint> names joint 'no_such_joint', which "
               "robot 'diff_bot' does not have" in m for m in logged(world, 'ERROR'))
    world, robot = spawned(diff_bot(leftJoint='caster_joint'))
    assert any("'caster_joint', which is fixed" in m for m in logged(world, 'ERROR'))
    world, robot = spawned(diff_bot(wheelSeparation='wide'))
    assert robot.model_plugins == []
    assert any('<wheelSeparation> of plugin' in m for m in logged(world, 'ERROR'))
    world, robot = spawned()
    assert not robot.plugin_send('diff_drive', 'cmd_vel', (math.nan, 0.0)), 'a NaN twist is refused'
    world.step(100)
    assert all(math.isfinite(v) for v in robot.base_pose())
    with pytest.raises(KeyError, match="publishes no topic 'odometry' \\(it has: odom, /tf, joint_states\\)"):
        robot.plugin_latest('diff_drive', 'odometry')
