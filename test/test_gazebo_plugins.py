"""gazebo_plugins' model plugins on the plant, through its Python module, each on a small robot
written for the tests (test/fixtures/urdf): libgazebo_ros_diff_drive.so with upstream's parameters,
its motors, ramp, torque limit, odometry (world and encoder) and frames (diff_bot), and the same
robot driven by ros_controllers' diff_drive_controller through gazebo_ros_control;
skid_steer_drive and joint_state_publisher (skid_bot), planar_move (planar_bot) and the mimic joint
plugin (gripper)."""
import math

import pytest

from plant_helpers import (DIFF_DRIVE_CONTROLLERS, diff_bot, diff_bot_with_gazebo_ros_control, fixture_urdf,
                           f3d_bot, force_based_bot, force_bot, gripper, logged, planar_bot, skid_bot, tricycle_bot, yaw_of)
from tianracer_description import bullet_plant

WHEEL_RADIUS, SEPARATION = 0.035, 0.30


def spawned(urdf=None, namespace='', name='diff_bot', params=None):
    world = bullet_plant.World()
    world.echo = False
    if params:
        world.load_params(params)
    robot = world.spawn(urdf or diff_bot(), name, namespace=namespace)
    world.step(200)  # settle on the ground
    return world, robot


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
    assert left == pytest.approx(0.2 / WHEEL_RADIUS, rel=0.01) and right == pytest.approx(left, rel=0.01)
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
    assert right == pytest.approx(SEPARATION / 2 / WHEEL_RADIUS, rel=0.02) and left == pytest.approx(-right, rel=0.02)


def test_wheel_acceleration_ramps_and_zero_sets_the_speed_at_once():
    for accel, expected in ((1.0, 0.05), (0.0, 0.2)):
        world, robot = spawned(diff_bot(wheelAcceleration=accel))
        drive(world, robot, 0.2, 0.0, 0.05)
        speed = robot.joint_state('wheel_left_joint')[1] * WHEEL_RADIUS
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
    assert (odom['frame_id'], odom['child_frame_id']) == ('diff_bot/odom', 'diff_bot/base_footprint'), \
        'no namespace: the model name is the prefix'
    pose = robot.base_pose()
    assert odom['pose'][:3] == pytest.approx(pose[:3], abs=0.01)
    assert odom['linear'] == pytest.approx(0.2, rel=0.05) and odom['angular'] == pytest.approx(0.5, rel=0.05)
    assert abs(odom['twist'][1]) < 0.01, 'the twist is in the base frame: no sideways speed'
    tf = robot.plugin_latest('diff_drive', '/tf')
    assert (tf['frame_id'], tf['child_frame_id']) == ('diff_bot/odom', 'diff_bot/base_footprint')
    assert list(tf['pose']) == list(odom['pose'])
    joints = robot.plugin_latest('diff_drive', 'joint_states')
    assert joints['name'] == ['wheel_left_joint', 'wheel_right_joint'] and len(joints['position']) == 2
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
    assert robot.plugin_latest('diff_drive', 'odom')['child_frame_id'] == 'robot_1/base_footprint'


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


# ------------------------------------------------------------------------------------------------
# The same robot driven as Husky and Jackal drive: gazebo_ros_control and ros_controllers'
# diff_drive_controller (wheel separation and radius read from the URDF).

def controlled_diff_bot():
    urdf = diff_bot_with_gazebo_ros_control()
    world = bullet_plant.World()
    world.echo = False
    world.load_params(DIFF_DRIVE_CONTROLLERS)
    world.load_params({'diff_bot': {'robot_description': urdf}})
    robot = world.spawn(urdf, 'diff_bot')
    manager = robot.controller_manager
    names = ['joint_state_controller', 'mobile_base_controller']
    assert manager.spawn(names) == (names, True), world.messages()
    world.step(200)
    return world, robot, manager


def test_diff_drive_controller_drives_with_geometry_from_the_urdf():
    world, robot, manager = controlled_diff_bot()
    start = robot.base_pose()
    for _ in range(40):  # a Twist every 50 ms, as a teleop sends them
        assert manager.command('mobile_base_controller', (0.2, 0.5))
        world.step(50)
    left, right = robot.joint_state('wheel_left_joint')[1], robot.joint_state('wheel_right_joint')[1]
    assert left == pytest.approx((0.2 - 0.5 * SEPARATION / 2) / WHEEL_RADIUS, rel=0.02), 'separation 0.3 m'
    assert right == pytest.approx((0.2 + 0.5 * SEPARATION / 2) / WHEEL_RADIUS, rel=0.02), 'radius 35 mm'
    odometry = manager.odometry('mobile_base_controller')
    assert odometry['linear'] == pytest.approx(0.2, rel=0.03) and odometry['angular'] == pytest.approx(0.5, rel=0.03)
    # The wheels' odometry against the plant's pose, both from where the controller started.
    pose = robot.base_pose()
    moved = math.hypot(pose[0] - start[0], pose[1] - start[1])
    assert math.hypot(odometry['x'], odometry['y']) == pytest.approx(moved, rel=0.05)
    assert odometry['heading'] == pytest.approx(math.remainder(yaw_of(pose) - yaw_of(start), 2 * math.pi), abs=0.05)
    assert (odometry['frame_id'], odometry['child_frame_id']) == ('odom', 'base_footprint')
    world.step(600)  # 0.65 s after the last Twist: braking since 0.5 s, at 1 m/s^2 from 0.2 m/s
    assert robot.joint_state('wheel_left_joint')[1] * WHEEL_RADIUS == pytest.approx(0.05, abs=0.01)
    world.step(100)
    assert abs(robot.joint_state('wheel_left_joint')[1]) < 0.05, 'cmd_vel_timeout 0.5 s, then the ramp down: stopped'


# ------------------------------------------------------------------------------------------------
# libgazebo_ros_skid_steer_drive.so and libgazebo_ros_joint_state_publisher.so on a four-wheeled
# robot (skid_bot.urdf: wheels 0.08 m across, 0.26 m apart).

SKID_RADIUS, SKID_SEPARATION = 0.04, 0.26


def test_skid_steer_drives_four_wheels_and_reports_world_odometry():
    world, robot = spawned(skid_bot(), name='skid_bot', namespace='/')
    assert robot.model_plugins == ['skid_steer_drive', 'gps', 'imu', 'magnetic', 'joint_state_publisher'], world.messages()
    assert robot.plugin_topics('skid_steer_drive') == {'subscribes': ['cmd_vel'], 'publishes': ['odom', '/tf']}
    start = robot.base_pose()
    assert robot.plugin_send('skid_steer_drive', 'cmd_vel', (0.3, 0.0))
    world.step(2000)
    for joint in ('front_left_wheel_joint', 'front_right_wheel_joint', 'rear_left_wheel_joint', 'rear_right_wheel_joint'):
        assert robot.joint_state(joint)[1] == pytest.approx(0.3 / SKID_RADIUS, rel=0.01), joint
    assert robot.base_pose()[0] - start[0] == pytest.approx(0.6, abs=0.03), 'at once to 0.3 m/s, for 2 s'
    odom = robot.plugin_latest('skid_steer_drive', 'odom')
    assert world.time - odom['stamp'] <= 0.021, 'at updateRate 50'
    assert (odom['frame_id'], odom['child_frame_id']) == ('odom', 'base_footprint'), "spawn_model's '/': no prefix"
    assert odom['x'] == pytest.approx(robot.base_pose()[0], abs=0.01) and odom['linear'] == pytest.approx(0.3, rel=0.01)
    assert odom['pose'][2] == 0.0, 'upstream fills x and y of the pose'
    assert odom['pose_covariance'] == pytest.approx([1e-4, 1e-4, 1e12, 1e12, 1e12, 0.01])
    assert odom['twist_covariance'] == odom['pose_covariance']
    tf = robot.plugin_latest('skid_steer_drive', '/tf')
    assert tf['pose'][:2] == pytest.approx(odom['pose'][:2]) and tf['pose'][2] != 0.0, 'the transform has the height'


def test_skid_steer_turns_the_sides_apart_and_slips_as_skid_steering_does():
    world, robot = spawned(skid_bot(), name='skid_bot', namespace='/')
    robot.plugin_send('skid_steer_drive', 'cmd_vel', (0.0, 1.0))
    world.step(1000)
    yaw_before = yaw_of(robot.base_pose())
    world.step(1000)
    left, right = robot.joint_state('front_left_wheel_joint')[1], robot.joint_state('rear_right_wheel_joint')[1]
    assert right == pytest.approx(SKID_SEPARATION / 2 / SKID_RADIUS, rel=0.02) and left == pytest.approx(-right, rel=0.02)
    turned = math.remainder(yaw_of(robot.base_pose()) - yaw_before, 2 * math.pi)
    # Wheels 0.2 m apart along the robot must slide sideways to turn it: it turns slower than the
    # wheels' 1 rad/s, as a skid-steer robot in Gazebo does.
    assert 0.5 < turned < 1.0, turned


def test_skid_steer_without_broadcast_tf_publishes_odometry_only():
    world, robot = spawned(skid_bot(broadcastTF=None, covariance_x=0.5), name='skid_bot')
    assert robot.plugin_topics('skid_steer_drive')['publishes'] == ['odom'], 'broadcastTF defaults to false'
    world.step(30)
    odom = robot.plugin_latest('skid_steer_drive', 'odom')
    assert odom['pose_covariance'][0] == 0.5
    assert odom['frame_id'] == 'odom', 'no tf prefix: skid_steer_drive reads only a tf_prefix parameter'


def test_joint_state_publisher_reports_the_listed_joints():
    world, robot = spawned(skid_bot(), name='skid_bot')
    robot.plugin_send('skid_steer_drive', 'cmd_vel', (0.2, 0.0))
    world.step(1000)
    states = robot.plugin_latest('joint_state_publisher', 'joint_states')
    assert world.time - states['stamp'] <= 0.051, 'at updateRate 20'
    assert states['name'] == ['front_left_wheel_joint', 'front_right_wheel_joint', 'rear_left_wheel_joint',
                              'rear_right_wheel_joint'], 'spaces around the commas dropped'
    assert states['velocity'] == pytest.approx([0.2 / SKID_RADIUS] * 4, rel=0.02)
    assert states['position'][0] == pytest.approx(robot.joint_state('front_left_wheel_joint')[0], abs=0.3)
    assert states['effort'] == []
    publisher = 'joint_state_publisher'
    world, robot = spawned(skid_bot(), name='skid_bot')
    urdf = skid_bot().replace('front_left_wheel_joint, front_right', 'front_left_wheel_joint, base_joint, front_right')
    world, robot = spawned(urdf, name='skid_bot')
    assert publisher in robot.model_plugins
    assert any(f"plugin '{publisher}' (libgazebo_ros_joint_state_publisher.so) <jointName> names 'base_joint', which "
               "is no movable joint of 'skid_bot'; it is left out" in m for m in logged(world, 'ERROR'))
    world.step(60)
    assert len(robot.plugin_latest(publisher, 'joint_states')['name']) == 4


# ------------------------------------------------------------------------------------------------
# libgazebo_ros_planar_move.so on a holonomic base (planar_bot.urdf).

def test_planar_move_sets_the_models_velocity_in_its_heading():
    world, robot = spawned(planar_bot(), name='planar_bot', namespace='/')
    assert robot.plugin_topics('planar_move') == {'subscribes': ['cmd_vel'], 'publishes': ['odom', '/tf']}
    assert robot.plugin_send('planar_move', 'cmd_vel', (0.2, 0.1, 0.5)), '(linear x, linear y, angular z)'
    world.step(2000)
    linear, angular = robot.base_twist()
    heading = yaw_of(robot.base_pose())
    assert heading == pytest.approx(1.0, abs=0.06), '0.5 rad/s for 2 s, less what the skids drag in each step'
    forward = math.cos(heading) * linear[0] + math.sin(heading) * linear[1]
    sideways = math.cos(heading) * linear[1] - math.sin(heading) * linear[0]
    assert forward == pytest.approx(0.2, rel=0.05) and sideways == pytest.approx(0.1, rel=0.05)
    assert angular[2] == pytest.approx(0.5, rel=0.05)
    odom = robot.plugin_latest('planar_move', 'odom')
    assert world.time - odom['stamp'] <= 0.021, 'at odometryRate 50'
    assert odom['twist'][0] == pytest.approx(0.2, rel=0.05) and odom['twist'][1] == pytest.approx(0.1, rel=0.05), \
        'the twist differenced from the last published pose, in the base frame'
    assert odom['angular'] == pytest.approx(0.5, rel=0.05)
    assert odom['pose_covariance'] == pytest.approx([1e-5, 1e-5, 1e12, 1e12, 1e12, 0.001])
    tf = robot.plugin_latest('planar_move', '/tf')
    assert (tf['frame_id'], tf['child_frame_id']) == ('odom', 'base_footprint')


def test_planar_move_drops_a_stale_command_after_cmd_timeout():
    world, robot = spawned(planar_bot(cmdTimeout=0.5), name='planar_bot')
    robot.plugin_send('planar_move', 'cmd_vel', (0.3, 0.0, 0.0))
    world.step(400)
    assert robot.base_twist()[0][0] == pytest.approx(0.3, rel=0.05)
    world.step(300)
    assert abs(robot.base_twist()[0][0]) < 0.01, 'no command for more than 0.5 s: stopped'
    world, robot = spawned(planar_bot(), name='planar_bot')
    robot.plugin_send('planar_move', 'cmd_vel', (0.3, 0.0, 0.0))
    world.step(2000)
    assert robot.base_twist()[0][0] == pytest.approx(0.3, rel=0.05), 'cmdTimeout -1 (the default): held'
    world.reset_world()
    world.step(200)
    assert abs(robot.base_twist()[0][0]) < 0.01, 'a reset forgets the command'


# ------------------------------------------------------------------------------------------------
# The mimic joint plugin (gripper.urdf): the second finger follows the first, which
# gazebo_ros_control moves through a position transmission.

def grip(params=None, **plugin):
    world, robot = spawned(gripper(**plugin), name='gripper', namespace='/', params=params)
    robot.set_command('finger_joint', 0.03)
    world.step(500)
    return world, robot


def test_the_mimic_joint_follows_by_position():
    world, robot = grip()
    assert robot.model_plugins == ['mimic_finger']
    assert robot.joint_state('finger_mimic_joint')[0] == pytest.approx(0.03, abs=1e-6)
    world, robot = grip(multiplier=0.5, offset=0.005)
    assert robot.joint_state('finger_mimic_joint')[0] == pytest.approx(0.02, abs=1e-6), '0.03 * 0.5 + 0.005'
    world, robot = grip(multiplier=-1.0, sensitiveness=0.05)
    assert robot.joint_state('finger_mimic_joint')[0] == pytest.approx(0.0, abs=1e-6), \
        'within sensitiveness of its target the plugin does nothing'


def test_the_mimic_joint_follows_by_effort_with_has_pid():
    gains = {'gazebo_ros_control': {'pid_gains': {'finger_mimic_joint': {'p': 100.0, 'i': 0.0, 'd': 4.0}}}}
    world, robot = grip(params=gains, hasPID='')
    assert robot.joint_state('finger_mimic_joint')[0] == pytest.approx(0.03, abs=1e-4)
    world, robot = grip(params=gains, hasPID='', maxEffort=0.01)
    # 10 mN on 50 g: 0.2 m/s^2, 25 mm in 0.5 s at most.
    assert 0.0 < robot.joint_state('finger_mimic_joint')[0] < 0.026
    world, robot = grip(params={'my_gains': {'p': 100.0, 'd': 4.0}}, hasPID='my_gains')
    assert robot.joint_state('finger_mimic_joint')[0] == pytest.approx(0.03, abs=1e-4), '<hasPID> names the gains'
    world, robot = grip(hasPID='')
    assert robot.model_plugins == []
    assert any("plugin 'mimic_finger' (libroboticsgroup_gazebo_mimic_joint_plugin.so) <hasPID>: No p gain specified "
               "for pid.  Namespace: /gazebo_ros_control/pid_gains/finger_mimic_joint" in m for m in logged(world, 'ERROR'))


def test_both_mimic_plugin_files_and_their_errors():
    urdf = gripper().replace('libroboticsgroup_gazebo_mimic', 'libroboticsgroup_upatras_gazebo_mimic')
    world, robot = spawned(urdf, name='gripper', namespace='/')
    assert robot.model_plugins == ['mimic_finger'], 'the newer file name'
    world, robot = spawned(gripper(mimicJoint=None), name='gripper')
    assert any("plugin 'mimic_finger' (libroboticsgroup_gazebo_mimic_joint_plugin.so) has no <mimicJoint>" in m
               for m in logged(world, 'ERROR'))
    world, robot = spawned(gripper(mimicJoint='finger_joint'), name='gripper')
    assert any("names joint 'finger_joint', which a gazebo_ros_control transmission drives already" in m
               for m in logged(world, 'ERROR'))
    world, robot = spawned(gripper(joint='thumb'), name='gripper')
    assert robot.model_plugins == [] and any("<joint> names 'thumb', which is no movable joint of 'gripper'" in m
                                             for m in logged(world, 'ERROR'))


# ------------------------------------------------------------------------------------------------
# hector_gazebo_plugins' libhector_gazebo_ros_gps.so on the skid_bot, as Husky carries it.

WGS84_A, WGS84_F = 6378137.0, 1 / 298.257223563


def radii_of_curvature(latitude_deg):
    """The meridian and the prime-vertical-times-cos radii at a latitude (textbook WGS84 geodesy)."""
    e2 = WGS84_F * (2 - WGS84_F)
    s = math.sin(math.radians(latitude_deg))
    meridian = WGS84_A * (1 - e2) / (1 - e2 * s * s) ** 1.5
    prime_vertical = WGS84_A / math.sqrt(1 - e2 * s * s)
    return meridian, prime_vertical * math.cos(math.radians(latitude_deg))


def gps_bot(pose=(0, 0, 0, 0, 0, 0), **params):
    world = bullet_plant.World()
    world.echo = False
    robot = world.spawn(fixture_urdf('skid_bot', 'gps', **params), 'skid_bot', namespace='/', pose=pose)
    world.step(200)
    return world, robot


def test_gps_fix_is_the_position_on_the_tangent_plane_of_the_reference():
    world, robot = gps_bot(pose=(10, 5, 0, 0, 0, 0), drift=None)
    assert robot.plugin_topics('gps') == {'subscribes': [], 'publishes': ['navsat/fix', 'navsat/vel']}
    fix = robot.plugin_latest('gps', 'navsat/fix')
    north, east = radii_of_curvature(49.9)
    x, y, z = robot.link_pose('base_link')[:3]
    assert fix['latitude'] == pytest.approx(49.9 + math.degrees(x / north), abs=1e-10), 'x is north'
    assert fix['longitude'] == pytest.approx(8.9 - math.degrees(y / east), abs=1e-10), 'y is west (hector: y left of north)'
    assert fix['altitude'] == pytest.approx(z, abs=1e-6)
    assert (fix['frame_id'], fix['status'], fix['service']) == ('base_link', 0, 0), 'STATUS_FIX, service 0'
    assert fix['position_covariance'] == [0.0, 0.0, 0.0], 'no drift, no noise'
    # referenceHeading 90: the world's x axis points east.
    world, robot = gps_bot(pose=(10, 0, 0, 0, 0, 0), drift=None, referenceHeading=90, referenceLatitude=-33.9,
                           referenceLongitude=151.2, referenceAltitude=50)
    fix = robot.plugin_latest('gps', 'navsat/fix')
    north, east = radii_of_curvature(-33.9)
    assert fix['latitude'] == pytest.approx(-33.9, abs=1e-9)
    assert fix['longitude'] == pytest.approx(151.2 + math.degrees(10 / east), abs=1e-9)
    assert fix['altitude'] == pytest.approx(50.04, abs=1e-3)


def test_gps_velocity_north_west_up_at_the_update_rate():
    world, robot = gps_bot(drift=None)
    robot.plugin_send('skid_steer_drive', 'cmd_vel', (0.3, 0.0))
    world.step(1000)
    velocity = robot.plugin_latest('gps', 'navsat/vel')
    assert velocity['vector'] == pytest.approx([0.3, 0.0, 0.0], abs=0.005)
    stamps = []
    for _ in range(100):
        world.step(1)
        stamps.append(robot.plugin_latest('gps', 'navsat/fix')['stamp'])
    assert sorted(set(round(s, 6) for s in stamps)) == pytest.approx([1.2, 1.225, 1.25, 1.275]), \
        'updateRate 40, phase-locked to multiples of 25 ms'


def test_gps_error_model_drift_and_noise_deterministic():
    world, robot = gps_bot(drift='0.5 0.5 1.0', gaussianNoise=0.2)
    fix = robot.plugin_latest('gps', 'navsat/fix')
    assert fix['position_covariance'] == pytest.approx([0.25 + 0.04, 0.25 + 0.04, 1.0 + 0.04]), 'drift^2 + noise^2'
    north, _ = radii_of_curvature(49.9)
    latitudes = []
    for _ in range(40):
        world.step(25)
        latitudes.append(math.radians(robot.plugin_latest('gps', 'navsat/fix')['latitude'] - 49.9) * north)
    spread = max(latitudes) - min(latitudes)
    assert 0.2 < spread < 2.0, 'white noise of 0.2 m over a drift that moves by at most millimetres in a second'
    again = gps_bot(drift='0.5 0.5 1.0', gaussianNoise=0.2)
    assert again[1].plugin_latest('gps', 'navsat/fix') == fix, 'the same seed: the same fix'
    world, robot = gps_bot(bodyName='antenna')
    assert 'gps' not in robot.model_plugins
    assert any("plugin 'gps' (libhector_gazebo_ros_gps.so) <bodyName> names 'antenna', which is no link" in m
               for m in logged(world, 'ERROR'))
    world, robot = gps_bot(drift='1 2')
    assert any('<drift> of plugin' in m and 'expected 3 numbers' in m for m in logged(world, 'ERROR'))


# hector_gazebo_plugins' libhector_gazebo_ros_imu.so on the skid_bot, as Husky carries it.

NOISELESS_IMU = dict(accelDrift=None, accelGaussianNoise=None, rateDrift=None, rateGaussianNoise=None, yawDrift=None,
                     yawGaussianNoise=None)


def imu_bot(**params):
    world = bullet_plant.World()
    world.echo = False
    robot = world.spawn(fixture_urdf('skid_bot', 'imu', **params), 'skid_bot', namespace='/')
    world.step(500)
    return world, robot


def test_hector_imu_at_rest_feels_gravitys_reaction_and_turns_with_the_robot():
    world, robot = imu_bot(**NOISELESS_IMU)
    assert robot.plugin_topics('imu') == {'subscribes': [], 'publishes': ['imu/data', 'imu/data/bias'],
                                          'serves': ['imu/data/calibrate', 'imu/data/set_accel_bias', 'imu/data/set_rate_bias']}
    imu = robot.plugin_latest('imu', 'imu/data')
    assert imu['frame_id'] == 'base_link' and world.time - imu['stamp'] <= 0.021, 'updateRate 50'
    assert imu['linear_acceleration'] == pytest.approx([0, 0, 9.8], abs=1e-3)
    assert imu['angular_velocity'] == pytest.approx([0, 0, 0], abs=1e-4)
    assert imu['orientation'] == pytest.approx([0, 0, 0, 1], abs=1e-4)
    robot.plugin_send('skid_steer_drive', 'cmd_vel', (0.0, 1.0))
    world.step(2000)
    imu = robot.plugin_latest('imu', 'imu/data')
    assert imu['angular_velocity'][2] == pytest.approx(robot.base_twist()[1][2], rel=0.03), 'the turn over 20 ms'
    x, y, z, w = imu['orientation']
    assert math.atan2(2 * (w * z + x * y), 1 - 2 * (y * y + z * z)) == pytest.approx(yaw_of(robot.base_pose()), abs=0.02)
    # rpyOffset: the IMU mounted on its side reads gravity along its y axis.
    world, robot = imu_bot(rpyOffset='1.5707963 0 0', **NOISELESS_IMU)
    assert robot.plugin_latest('imu', 'imu/data')['linear_acceleration'] == pytest.approx([0, 9.8, 0], abs=1e-3)


def test_hector_imu_error_models_biases_and_covariances():
    world, robot = imu_bot(accelOffset='0.2 0 0', accelDrift=None, rateDrift=None, yawDrift=None)
    imu, bias = robot.plugin_latest('imu', 'imu/data'), robot.plugin_latest('imu', 'imu/data/bias')
    assert bias['linear_acceleration'] == pytest.approx([0.2, 0, 0]), 'the bias topic: offset plus drift'
    assert imu['linear_acceleration'][0] == pytest.approx(0.2, abs=0.03), 'offset plus white noise of 5 mm/s^2'
    # The accelerometer's bias tilts the pseudo-AHRS orientation: 0.2 / 9.8 / 2 about -y.
    assert bias['orientation'][1] == pytest.approx(-0.5 * 0.2 / 9.8, rel=0.01)
    assert imu['linear_acceleration_covariance'] == pytest.approx([0.005 ** 2] * 3)
    assert imu['angular_velocity_covariance'] == pytest.approx([0.005 ** 2] * 3)
    assert imu['orientation_covariance'] == pytest.approx([(0.005 / 9.8) ** 2, (0.005 / 9.8) ** 2, 0.005 ** 2])
    world, robot = imu_bot()
    first = robot.plugin_latest('imu', 'imu/data')
    assert abs(robot.plugin_latest('imu', 'imu/data/bias')['angular_velocity'][0]) > 0, 'a drift of 5 mrad/s drawn at load'
    assert imu_bot()[1].plugin_latest('imu', 'imu/data') == first, 'the same seed: the same readings'
    world, robot = imu_bot(gaussianNoise=0.1)
    assert robot.plugin_latest('imu', 'imu/data')['angular_velocity_covariance'] == pytest.approx([0.01] * 3), \
        'the legacy <gaussianNoise> sets both noises'


def test_hector_imu_services_set_the_biases_and_calibrate_draws_the_rate_drift_anew():
    world, robot = imu_bot(accelGaussianNoise=None, rateGaussianNoise=None, yawGaussianNoise=None, accelDrift=None)
    assert robot.plugin_call('imu', 'imu/data/set_accel_bias', (0.3, -0.1, 0.0))
    assert robot.plugin_call('imu', 'imu/data/set_rate_bias', (0.0, 0.0, 0.02))
    world.step(40)
    imu, bias = robot.plugin_latest('imu', 'imu/data'), robot.plugin_latest('imu', 'imu/data/bias')
    assert bias['linear_acceleration'] == pytest.approx([0.3, -0.1, 0.0], abs=1e-4) and imu['linear_acceleration'] == \
        pytest.approx([0.3, -0.1, 9.8], abs=1e-3), 'set_accel_bias: the drift now (fading at its drift frequency)'
    assert bias['angular_velocity'][2] == pytest.approx(0.02, abs=1e-3)
    assert robot.plugin_call('imu', 'imu/data/calibrate')
    world.step(40)
    calibrated = robot.plugin_latest('imu', 'imu/data/bias')['angular_velocity'][2]
    assert calibrated != pytest.approx(0.02, abs=1e-3) and abs(calibrated) < 0.03, 'a new drift drawn, N(0, 5 mrad/s)'
    world, robot = imu_bot(serviceName='')
    assert 'imu/data/calibrate' not in robot.plugin_topics('imu')['serves'], 'an empty serviceName: no calibrate'


def test_hector_magnetometer_reads_the_reference_field_in_the_body_frame():
    horizontal, vertical = 49.0 * math.cos(math.radians(65)), -49.0 * math.sin(math.radians(65))
    north = (horizontal * math.cos(math.radians(-2)), horizontal * math.sin(math.radians(-2)), vertical)
    for yaw in (0.0, math.pi / 2):
        world = bullet_plant.World()
        world.echo = False
        robot = world.spawn(skid_bot(), 'skid_bot', namespace='/', pose=(0, 0, 0, 0, 0, yaw))
        world.step(300)
        field = robot.plugin_latest('magnetic', 'magnetic')
        assert field['frame_id'] == 'base_link' and world.time - field['stamp'] <= 0.1 + 1e-9, 'updateRate 10'
        c, s = math.cos(yaw), math.sin(yaw)
        expected = [c * north[0] + s * north[1], -s * north[0] + c * north[1], north[2]]  # R^T of the world field
        assert field['vector'] == pytest.approx(expected, abs=1e-3), f'yaw {yaw}'


# hector's libgazebo_ros_force_based_move.so on the holonomic base (force_based_bot).

def test_force_based_move_pushes_the_base_to_the_commanded_twist():
    world, robot = spawned(force_based_bot(), name='force_based_bot', namespace='/')
    assert robot.plugin_topics('force_based_move') == {'subscribes': ['cmd_vel'], 'publishes': ['odom', '/tf']}
    robot.plugin_send('force_based_move', 'cmd_vel', (0.2, 0.1, 0.3))
    world.step(3000)
    linear, angular = robot.base_twist()
    heading = yaw_of(robot.base_pose())
    forward = math.cos(heading) * linear[0] + math.sin(heading) * linear[1]
    sideways = math.cos(heading) * linear[1] - math.sin(heading) * linear[0]
    assert forward == pytest.approx(0.2, abs=0.01) and sideways == pytest.approx(0.1, abs=0.01)
    assert angular[2] == pytest.approx(0.3, abs=0.02)
    odom = robot.plugin_latest('force_based_move', 'odom')
    assert world.time - odom['stamp'] <= 0.041, 'odometryRate 25'
    assert odom['twist'][:2] == pytest.approx([forward, 0.0], abs=0.01), 'forward speed only, as upstream'
    assert odom['angular'] == pytest.approx(0.3, abs=0.02)
    assert odom['heading'] == pytest.approx(math.remainder(heading, 2 * math.pi), abs=0.05), 'the yaw rate integrated'
    assert odom['pose_covariance'] == pytest.approx([0.001, 0.001, 1e12, 1e12, 1e12, 100.0]), 'turning: yaw 100'
    world, robot = spawned(force_based_bot(publishOdometryTf='false', robotBaseFrame='chassis'), name='force_based_bot')
    assert robot.model_plugins == []
    assert any("<robotBaseFrame> names 'chassis', which is no link" in m for m in logged(world, 'ERROR'))


# gazebo_plugins' libgazebo_ros_force.so: a Wrench on a topic pushes a link every step.

def test_force_plugin_applies_the_last_wrench_every_step():
    world, robot = spawned(force_bot(), name='pushed', namespace='/')
    assert robot.plugin_topics('push') == {'subscribes': ['force'], 'publishes': []}
    z0 = robot.base_pose()[2]
    assert robot.plugin_send('push', 'force', (0, 0, 60.0, 0, 0, 0)), '(fx, fy, fz, tx, ty, tz)'
    world.step(500)
    # 60 N up on 5 kg against 49 N of weight: 2.2 m/s^2 for 0.5 s.
    assert robot.base_pose()[2] - z0 == pytest.approx(0.5 * (60 / 5 - 9.8) * 0.5 ** 2, rel=0.05)
    assert not robot.plugin_send('push', 'force', (math.nan, 0, 0, 0, 0, 0)), 'a NaN wrench is refused'
    world.step(100)
    assert robot.base_twist()[0][2] > 1.0, 'still pushed by the last good wrench'
    world, robot = spawned(force_bot(topicName=None), name='pushed')
    assert robot.model_plugins == [] and any("plugin 'push' (libgazebo_ros_force.so) has no <topicName>" in m
                                             for m in logged(world, 'ERROR'))


# gazebo_plugins' libgazebo_ros_f3d.so: the wrench added to a link before it in the step, every step.

def test_f3d_reports_the_wrench_pushed_on_its_link_but_neither_gravity_nor_contacts():
    world, robot = spawned(f3d_bot(), name='pushed', namespace='/')
    assert robot.plugin_topics('f3d') == {'subscribes': [], 'publishes': ['force_truth']}
    world.step(200)  # resting on its wheels: weight and contacts act, nothing is added
    at_rest = robot.plugin_latest('f3d', 'force_truth')
    assert at_rest['frame_id'] == 'world' and at_rest['stamp'] == pytest.approx(world.time - 0.001, abs=1e-9)
    assert at_rest['force'] == [0, 0, 0] and at_rest['torque'] == [0, 0, 0]
    assert robot.plugin_send('push', 'force', (1.0, -2.0, 30.0, 0.0, 0.0, 0.5))
    world.step(3)
    pushed = robot.plugin_latest('f3d', 'force_truth')
    assert pushed['force'] == pytest.approx([1.0, -2.0, 30.0]) and pushed['torque'] == pytest.approx([0, 0, 0.5])
    world, robot = spawned(f3d_bot(frameName='/map', bodyName='nowhere'), name='pushed')
    assert robot.model_plugins == ['push'] and any("plugin 'f3d' (libgazebo_ros_f3d.so)" in m and "'nowhere'" in m
                                                  for m in logged(world, 'ERROR'))
    world, robot = spawned(f3d_bot(frameName='/map'), name='pushed')
    world.step(2)
    assert robot.plugin_latest('f3d', 'force_truth')['frame_id'] == 'map', 'tf::resolve drops the leading slash'


# ------------------------------------------------------------------------------------------------
# libgazebo_ros_tricycle_drive.so (tricycle_bot.urdf: every default fits it; wheelbase 0.4 m).

TRICYCLE_RADIUS, TRICYCLE_WHEELBASE = 0.075, 0.4


def test_tricycle_drives_its_front_wheel_and_steers_it_by_angle():
    world, robot = spawned(tricycle_bot(), name='tricycle_bot', namespace='/')
    assert robot.model_plugins == ['tricycle_drive']
    assert robot.plugin_send('tricycle_drive', 'cmd_vel', (0.5, 0.0))
    world.step(2000)
    assert robot.joint_state('front_wheel_joint')[1] == pytest.approx(0.5 / TRICYCLE_RADIUS, rel=0.01)
    assert robot.base_twist()[0][0] == pytest.approx(0.5, rel=0.03), 'front-wheel drive at 0.5 m/s'
    assert robot.plugin_send('tricycle_drive', 'cmd_vel', (0.5, 0.4))  # angular.z is the steering ANGLE
    world.step(2000)
    assert robot.joint_state('front_steering_joint')[0] == pytest.approx(0.4, abs=0.01), 'set by position'
    yaw_rate = robot.base_twist()[1][2]
    assert yaw_rate == pytest.approx(0.5 * math.sin(0.4) / TRICYCLE_WHEELBASE, rel=0.08), \
        'the rear axle turns about the point the steered wheel points around'
    odometry = robot.plugin_latest('tricycle_drive', 'odom')
    assert (odometry['frame_id'], odometry['child_frame_id']) == ('odom', 'base_link')
    assert odometry['angular'] == pytest.approx(yaw_rate, rel=0.02) and odometry['pose_covariance'][5] == 0.001
    joints = robot.plugin_latest('tricycle_drive', 'joint_states')
    assert joints['name'] == ['front_steering_joint', 'front_wheel_joint', 'left_wheel_joint', 'right_wheel_joint']
    assert robot.plugin_send('tricycle_drive', 'cmd_vel', (0.0, 3.0))
    world.step(500)
    assert 1.0 < robot.joint_state('front_steering_joint')[0] < 1.21, \
        'set to pi/2 (the plugin holds 3 rad there), pushed back within the URDF limit 1.2'


def test_tricycle_steering_speed_and_wheel_acceleration():
    world, robot = spawned(tricycle_bot(steeringSpeed=1.0, wheelAcceleration=1.0), name='tricycle_bot', namespace='/')
    assert robot.plugin_send('tricycle_drive', 'cmd_vel', (0.0, 0.3))
    world.step(150)
    assert robot.joint_state('front_steering_joint')[0] == pytest.approx(0.15, abs=0.02), 'turning at 1 rad/s'
    world.step(500)
    assert robot.joint_state('front_steering_joint')[0] == pytest.approx(0.3, abs=0.015), 'within steeringAngleTolerance'
    assert robot.plugin_send('tricycle_drive', 'cmd_vel', (0.3, 0.0))
    world.step(1000)
    # 1 rad/s^2 of wheel rate (upstream ramps the rate, not the speed): 4 rad/s target reached after 4 s
    assert robot.joint_state('front_wheel_joint')[1] == pytest.approx(1.0, abs=0.1)


def test_tricycle_encoder_odometry_keeps_upstreams_heading_sign():
    world, robot = spawned(tricycle_bot(odometrySource='encoder'), name='tricycle_bot', namespace='/')
    assert robot.plugin_send('tricycle_drive', 'cmd_vel', (0.4, 0.5))
    world.step(3000)
    odometry = robot.plugin_latest('tricycle_drive', 'odom')
    turned = yaw_of(robot.base_pose())
    assert turned > 0.3, 'a left turn'
    assert odometry['heading'] == pytest.approx(-turned, abs=0.05), \
        "gazebo_ros_tricycle_drive integrates left minus right: its heading runs the other way"
