"""The Bullet plant through its Python module, no ROS master: the car at rest and driving, the rear
wheels' gazebo_ros_control velocity loop with the YAML's pid_gains, determinism, bad input, lidar."""
import math

import numpy as np
import re

import pytest

from plant_helpers import all_state, box_model, hold_steering, make_world, sdf_world, yaw_of
from tianracer_description import bullet_plant
from tianracer_description.tianracer import REAR_WHEEL_JOINTS

COMMAND = 31.25  # rad/s: 1.0 m/s with the 0.032 m wheels


@pytest.fixture
def car(urdf_xml, control_config):
    world = make_world(control_config)
    return world, world.spawn(urdf_xml, 'tianracer')


def test_spawn_reads_the_models_control_block_and_pid_gains(car):
    world, robot = car
    assert robot.namespace == '/tianracer'
    assert robot.handles == ['left_rear_wheel_joint', 'right_rear_wheel_joint', 'left_steering_hinge_joint',
                             'left_front_wheel_joint', 'right_steering_hinge_joint', 'right_front_wheel_joint']
    interfaces = {j: robot.interface(j) for j in robot.handles}
    assert interfaces['left_rear_wheel_joint'] == interfaces['right_rear_wheel_joint'] == \
        'hardware_interface::VelocityJointInterface'
    assert set(interfaces[j] for j in robot.handles[2:]) == {'hardware_interface::EffortJointInterface'}
    assert [robot.has_pid(j) for j in robot.handles] == [True, True, False, False, False, False]
    assert robot.limits('left_steering_hinge_joint')['upper'] == pytest.approx(0.6)
    assert robot.sensors == ['lidar', 'camera', 'depth_camera']


def test_spawn_pose_places_the_root_link(urdf_xml, control_config):
    world = make_world(control_config)
    robot = world.spawn(urdf_xml, 'tianracer', pose=(1.0, -2.0, 0.0, 0.0, 0.0, 1.2))
    pose = robot.base_pose()
    assert pose[:3] == pytest.approx([1.0, -2.0, 0.0], abs=1e-6)
    assert yaw_of(pose) == pytest.approx(1.2, abs=1e-6)


def test_at_rest_the_car_settles_and_stays(car):
    world, robot = car
    world.step(1000)
    start = robot.base_pose()
    heights = []
    for _ in range(100):
        world.step(100)
        heights.append(robot.base_pose()[2])
    end = robot.base_pose()
    assert max(abs(h - start[2]) for h in heights) < 1e-3, 'height drift over 10 s'
    assert np.hypot(*(end[:2] - start[:2])) < 0.01, 'creep over 10 s'
    assert abs(start[2]) < 2e-3, 'the wheels rest on the ground'


def test_both_rear_wheels_at_31_25_rad_s_drive_straight_at_1_m_s(car):
    world, robot = car
    hold_steering(robot)
    for joint in REAR_WHEEL_JOINTS:
        robot.set_command(joint, COMMAND)
    world.step(3000)
    linear, _ = robot.base_twist()
    assert np.hypot(linear[0], linear[1]) == pytest.approx(1.0, abs=0.03)
    start = robot.base_pose()
    heading = yaw_of(start)
    while np.hypot(*(robot.base_pose()[:2] - start[:2])) < 5.0:
        world.step(10)
        assert world.time < 10.0, 'the car did not cover 5 m'
    offset = robot.base_pose()[:2] - start[:2]
    lateral = -math.sin(heading) * offset[0] + math.cos(heading) * offset[1]
    assert abs(lateral) < 0.02, 'lateral drift over 5 m'


def wheel_step_response(world, robot, seconds=1.0):
    """Command both rear wheels to 31.25 rad/s from rest; the left wheel's velocity every step."""
    for joint in REAR_WHEEL_JOINTS:
        robot.set_command(joint, COMMAND)
    velocities = []
    for _ in range(int(round(seconds / world.time_step))):
        world.step()
        velocities.append(robot.joint_state('left_rear_wheel_joint')[1])
    return np.array(velocities)


def check_velocity_loop(velocities, dt):
    within = np.abs(velocities - COMMAND) <= 0.02 * COMMAND
    # the first step from which the velocity stays within 2 %
    settled = len(within) - np.argmin(within[::-1]) if not within.all() else 0
    assert within[-1], 'the wheel never reached the command'
    assert settled * dt <= 0.2, 'took %.3f s to stay within 2 %%' % (settled * dt)
    steady = velocities[int(0.5 / dt):]
    assert np.std(steady) < 0.01 * COMMAND, 'chatter: steady-state std %.4f rad/s' % np.std(steady)


def test_wheel_velocity_loop_with_yaml_pid_gains_on_the_ground(car):
    world, robot = car
    hold_steering(robot)
    world.step(200)
    check_velocity_loop(wheel_step_response(world, robot), world.time_step)


def test_wheel_velocity_loop_with_yaml_pid_gains_lifted_off_the_ground(urdf_xml, control_config):
    # A stand under the chassis lifts the wheels 2 cm off the ground.
    stand = box_model('stand', (0.2, 0.08, 0.04), (0.13, 0.0, 0.02))
    world = make_world(control_config, sdf_world(stand))
    robot = world.spawn(urdf_xml, 'tianracer', pose=(0, 0, 0.025, 0, 0, 0))
    hold_steering(robot)
    world.step(500)
    assert robot.base_pose()[2] == pytest.approx(0.02, abs=2e-3), 'the car rests on the stand'
    velocities = wheel_step_response(world, robot)
    check_velocity_loop(velocities, world.time_step)
    assert robot.base_pose()[:2] == pytest.approx([0, 0], abs=0.01), 'lifted wheels do not move the car'


def test_the_worlds_contacts_are_the_four_tyres_on_the_ground_bearing_the_cars_weight(car, urdf_xml):
    """World.contacts (what a viewer's contact overlay draws): at rest, one contact per tyre, each under
    its wheel on the ground with the normal up into the tyre, and their forces bear the car's weight."""
    import xml.etree.ElementTree as ET
    world, robot = car
    world.step(2000)
    contacts = world.contacts()
    wheels = sorted(c['collision1'].split('::')[1] for c in contacts)
    assert wheels == ['left_front_wheel', 'left_rear_wheel', 'right_front_wheel', 'right_rear_wheel'], contacts
    for c in contacts:
        assert c['collision2'] == 'ground_plane::link::collision'
        wheel = robot.link_pose(c['collision1'].split('::')[1])
        assert c['position'][:2] == pytest.approx(wheel[:2], abs=0.005), 'under the wheel\'s axle'
        assert c['position'][2] == pytest.approx(0.0, abs=1e-3)
        assert c['normal'] == pytest.approx([0, 0, 1], abs=1e-6)
    mass = sum(float(m.get('value')) for m in ET.fromstring(urdf_xml).iter('mass'))
    assert sum(c['force'][2] for c in contacts) == pytest.approx(mass * 9.8, rel=1e-3)
    assert np.abs(np.sum([c['force'][:2] for c in contacts], axis=0)).max() < 0.01 * mass * 9.8, 'no net sideways push'


def test_a_car_driving_into_another_pushes_it(urdf_xml, control_config):
    # Contacts between two robots take Bullet's own rows (and its articulated-body response),
    # the rest of the step the joint-space path: both in one step.
    world = make_world(control_config)
    robot = world.spawn(urdf_xml, 'tianracer')
    other = world.spawn(urdf_xml, 'other', pose=(0.9, 0.05, 0.0, 0, 0, 0.4))
    world.step(200)
    parked = other.base_pose()
    hold_steering(robot)
    for joint in REAR_WHEEL_JOINTS:
        robot.set_command(joint, 40.0)
    for _ in range(30):
        world.step(100)
        for r in (robot, other):
            assert np.all(np.isfinite(all_state(world, r)))
            assert abs(r.base_pose()[2]) < 0.02, 'both cars stay on the ground'
    pushed = other.base_pose()[0] - parked[0]
    assert pushed > 0.2, 'the parked car was pushed ahead'
    assert robot.base_pose()[0] > parked[0] - 0.2, 'the driving car got to where the other one was'


def drive_sequence(urdf_xml, control_config):
    world = make_world(control_config)
    robot = world.spawn(urdf_xml, 'tianracer', pose=(0.5, 0.2, 0.0, 0, 0, 0.3))
    trajectory = []
    for step, (speed, steer) in enumerate([(10.0, 0.0), (31.25, 0.3), (-15.0, -0.4), (0.0, 0.0)]):
        for joint in REAR_WHEEL_JOINTS:
            robot.set_command(joint, speed)
        hold_steering(robot, steer)
        for _ in range(50):
            world.step(10)
            trajectory.append(all_state(world, robot))
    return np.array(trajectory)


def test_same_commands_twice_give_bit_identical_trajectories(urdf_xml, control_config):
    first = drive_sequence(urdf_xml, control_config)
    second = drive_sequence(urdf_xml, control_config)
    assert np.array_equal(first, second)
    assert np.abs(first[-1, :2] - first[0, :2]).max() > 0.3, 'the car moved'


@pytest.mark.parametrize('value', [math.nan, math.inf, -math.inf])
def test_non_finite_commands_are_rejected_and_counted(car, value):
    world, robot = car
    robot.set_command('left_rear_wheel_joint', 5.0)
    assert robot.set_command('left_rear_wheel_joint', value) is False
    assert robot.set_command('left_steering_hinge_joint', value) is False
    assert robot.rejected_commands('left_rear_wheel_joint') == 1
    assert robot.command('left_rear_wheel_joint') == 5.0, 'the last good command stays'
    world.step(500)
    assert np.isfinite(all_state(world, robot)).all()
    assert robot.joint_state('left_rear_wheel_joint')[1] == pytest.approx(5.0, rel=0.02)


def test_huge_commands_are_held_to_the_urdf_limits(car):
    world, robot = car
    hold_steering(robot)
    robot.set_command('left_rear_wheel_joint', 1e30)
    robot.set_command('right_rear_wheel_joint', 1e30)
    robot.set_command('left_steering_hinge_joint', -1e30)
    world.step(1000)
    state = all_state(world, robot)
    assert np.isfinite(state).all()
    # The command is clamped to the limit and driven by a rigid velocity row; the friction rows
    # solved after it in each pass leave a residual of a few 1e-5 of the speed (10 passes).
    limit = robot.limits('left_rear_wheel_joint')['velocity']
    assert robot.joint_state('left_rear_wheel_joint')[1] <= limit * (1 + 1e-4)
    assert abs(robot.joint_state('left_steering_hinge_joint')[2]) <= 1.0 + 1e-6, 'effort clamped to the limit'
    assert robot.joint_state('left_steering_hinge_joint')[0] >= -0.6 - 0.01, 'position limit holds'


def test_malformed_urdf_names_the_problem_and_the_world_goes_on(car):
    world, robot = car
    with pytest.raises(bullet_plant.DescriptionError, match='not well-formed'):
        world.spawn('<robot name="x"><link name="a">', 'broken')
    with pytest.raises(bullet_plant.DescriptionError, match='URDF parser'):
        world.spawn('<robot name="x"><joint name="j" type="revolute"><parent link="a"/><child link="b"/></joint></robot>',
                    'broken')
    before = world.time
    world.step(100)
    assert world.time == pytest.approx(before + 0.1)
    assert world.robots == ['tianracer']
    assert np.isfinite(all_state(world, robot)).all()


def test_transmission_naming_a_missing_joint_is_an_error_naming_it(car, urdf_xml):
    world, robot = car
    broken = urdf_xml.replace('<joint name="left_rear_wheel_joint">', '<joint name="no_such_joint">', 1)
    assert broken != urdf_xml
    with pytest.raises(bullet_plant.DescriptionError, match="no_such_joint"):
        world.spawn(broken, 'second')
    assert world.robots == ['tianracer']
    world.step(10)


def test_malformed_sdf_names_the_problem():
    with pytest.raises(bullet_plant.DescriptionError, match='not well-formed'):
        bullet_plant.World.from_sdf('<sdf><world name="w">')
    # a value sdformat cannot read leaves its model out, naming it; the world goes on
    world = bullet_plant.World.from_sdf(sdf_world(box_model('wall', ('1', 'x', '1'), (0, 0, 0))))
    errors = [text for level, text in world.messages() if level == 'ERROR']
    assert len(errors) == 1 and re.search(r"model 'wall' link '\w+' collision '\w+' <size> '1 x 1'", errors[0]), errors
    assert not [c for c in world.static_collisions() if c['name'].startswith('wall')]
    with pytest.raises(bullet_plant.DescriptionError, match='max_step_size'):
        bullet_plant.World.from_sdf(sdf_world(step=-1))


def test_world_physics_comes_from_the_sdf(urdf_xml, control_config):
    world = make_world(control_config, sdf_world(step=0.002))
    assert world.time_step == pytest.approx(0.002)
    world.step(10)
    assert world.time == pytest.approx(0.02)


# ---------------------------------------------------------------------------------------------- lidar

WALL_X = 2.0  # the wall's face, in the world


def lidar_world(urdf_xml, control_config, extra_models=''):
    wall = box_model('wall', (0.2, 6.0, 1.0), (WALL_X + 0.1, 0.0, 0.5))
    world = make_world(control_config, sdf_world(wall + extra_models))
    robot = world.spawn(urdf_xml, 'tianracer')
    world.step(200)  # settle
    return world, robot


def scan_angles(scan):
    return scan['angle_min'] + scan['angle_increment'] * np.arange(len(scan['ranges']))


def test_lidar_sees_a_wall_where_the_geometry_puts_it(urdf_xml, control_config):
    world, robot = lidar_world(urdf_xml, control_config)
    robot.enable_sensor('lidar')
    world.step(25)
    scan = robot.scan('lidar')
    assert scan['frame_id'] == 'laser_link'
    assert len(scan['ranges']) == 1081
    assert scan['angle_min'] == pytest.approx(-2.356) and scan['angle_max'] == pytest.approx(2.356)
    assert scan['range_min'] == pytest.approx(0.1) and scan['range_max'] == pytest.approx(10.0)
    lidar_x = robot.link_pose('laser_link')[0]
    angles = scan_angles(scan)
    # rays that reach the wall's face within its 6 m width and the 10 m range
    facing = np.abs(angles) < np.arctan(2.9 / (WALL_X - lidar_x))
    expected = (WALL_X - lidar_x) / np.cos(angles[facing])
    errors = scan['ranges'][facing] - expected
    assert facing.sum() > 400
    # gaussian noise of stddev 0.01 m around the true distance: unbiased, of that spread, and
    # (for 400+ samples) 99 % of them within 3 sigma
    sigma = 0.01
    assert abs(np.mean(errors)) < 3 * sigma / np.sqrt(len(errors)), 'biased ranges'
    assert 0.8 * sigma < np.std(errors) < 1.2 * sigma
    assert np.mean(np.abs(errors) < 3 * sigma) > 0.99
    assert np.abs(errors).max() < 5 * sigma
    # nothing behind the car within 10 m: +inf (REP 117); and the car never sees itself
    behind = np.abs(angles) > 1.7
    assert np.isposinf(scan['ranges'][behind]).all()


def test_lidar_sees_past_what_is_nearer_than_its_minimum_range_and_sees_other_robots(urdf_xml, control_config):
    # As Gazebo's: the ray lidar's rays start at <range><min> (gpu_ray's near clip plane is there).
    post = box_model('post', (0.02, 0.02, 0.3), (0.2, 0.07, 0.15))  # 6 cm left of the lidar
    side_wall = box_model('side_wall', (6.0, 0.2, 1.0), (0.0, 1.1, 0.5))  # its face at y = 1
    world, robot = lidar_world(urdf_xml, control_config, post + side_wall)
    other = world.spawn(urdf_xml, 'other', pose=(1.2, 0.0, 0.0, 0, 0, math.pi))
    world.step(100)
    robot.enable_sensor('lidar')
    world.step(25)
    scan = robot.scan('lidar')
    angles = scan_angles(scan)
    left = np.argmin(np.abs(angles - math.pi / 2))
    lidar_y = robot.link_pose('laser_link')[1]
    assert scan['ranges'][left] == pytest.approx((1.0 - lidar_y) / math.sin(angles[left]), abs=0.02), \
        'the side wall behind the post'
    ahead = scan['ranges'][np.argmin(np.abs(angles))]
    other_lidar = other.link_pose('laser_link')[0]
    assert 0.5 < ahead < other_lidar - robot.link_pose('laser_link')[0], 'the other car is in front of the wall'


def test_a_robot_alone_scans_the_world_and_one_that_comes_goes_and_comes_back_is_seen_where_it_is(
        urdf_xml, control_config):
    # Alone, a robot's rays are cast at the static shapes only (its own bodies hidden): the level that
    # holds the robots' bodies is not committed then, and must be when another robot comes, with every
    # body where it is by then, and left again when it goes.
    world, robot = lidar_world(urdf_xml, control_config)
    robot.enable_sensor('lidar')

    def ahead():
        world.step(25)
        scan = robot.scan('lidar')
        return scan['ranges'][np.argmin(np.abs(scan_angles(scan)))]
    lidar_x = robot.link_pose('laser_link')[0]
    wall = ahead()
    assert wall == pytest.approx(WALL_X - lidar_x, abs=0.02), 'alone: the wall'
    for x in (1.2, 0.8):
        other = world.spawn(urdf_xml, 'other', pose=(x, 0.0, 0.0, 0, 0, math.pi))
        world.step(50)
        seen = ahead()
        assert 0.2 < seen < x - lidar_x, 'the other car at x = %g, in front of the wall' % x
        world.remove('other')
        assert ahead() == pytest.approx(wall, abs=0.02), 'gone: the wall again'
        assert robot.link_pose('laser_link')[0] == pytest.approx(lidar_x, abs=1e-3), 'the robot held still'


# A box on the ground with a lidar inside it, 0.3 m up, and a visor 0.4 m in front of it: the lidar
# sees the box's inside and the visor unless it hides its own robot.
VISOR_BOT = """<?xml version="1.0"?>
<robot name="visor_bot">
  <link name="base">
    <inertial><mass value="2.0"/><inertia ixx="0.02" iyy="0.02" izz="0.02" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><origin xyz="0 0 0.2"/><geometry><box size="0.4 0.4 0.4"/></geometry></collision>
    <collision><origin xyz="0.4 0 0.3"/><geometry><box size="0.05 0.3 0.1"/></geometry></collision>
  </link>
  <joint name="lidar_joint" type="fixed">
    <parent link="base"/><child link="lidar_link"/><origin xyz="0 0 0.3"/>
  </joint>
  <link name="lidar_link">
    <inertial><mass value="0.1"/><inertia ixx="1e-4" iyy="1e-4" izz="1e-4" ixy="0" ixz="0" iyz="0"/></inertial>
  </link>
  <gazebo reference="lidar_link">
    <sensor type="ray" name="lidar">
      <update_rate>40</update_rate>
      <ray>
        <scan><horizontal><samples>361</samples><resolution>1</resolution><min_angle>-3.1416</min_angle><max_angle>3.1416</max_angle></horizontal></scan>
        <range><min>0.1</min><max>10.0</max><resolution>0.01</resolution></range>
      </ray>
    </sensor>
  </gazebo>
</robot>
"""


def test_in_a_crowd_every_lidar_hides_its_own_robot_and_sees_the_others(control_config):
    # A lidar's rays pass through its own robot by leaving that robot's mask bit out (29 robots have
    # a bit of their own); the robots beyond share one bit, and one of them is hidden by masking its
    # bodies out and shown again when the next lidar scans. 32 robots in a row 2.5 m apart, every
    # lidar scanning at the same step: none sees its own visor (nothing nearer than 1.5 m), each sees
    # the robots beside it.
    spacing, count = 2.5, 32
    world = make_world(control_config, sdf_world(''))
    robots = [world.spawn(VISOR_BOT, 'bot%d' % k, pose=(0.0, spacing * k, 0.0, 0, 0, 0)) for k in range(count)]
    world.step(100)  # settle
    for robot in robots:
        robot.enable_sensor('lidar')
    world.step(25)
    for k, robot in enumerate(robots):
        scan = robot.scan('lidar')
        ranges, angles = scan['ranges'], scan_angles(scan)
        assert ranges.min() > 1.5, 'bot%d sees itself at %.2f m' % (k, ranges.min())
        for side, neighbour in ((1, k + 1), (-1, k - 1)):
            beside = ranges[np.argmin(np.abs(angles - side * math.pi / 2))]
            if 0 <= neighbour < count:
                assert beside == pytest.approx(spacing - 0.2, abs=0.02), 'bot%d and bot%d beside it' % (k, neighbour)
            else:
                assert np.isposinf(beside), 'bot%d sees something where no robot is' % k


def test_lidar_works_only_while_enabled_at_its_rate_in_sim_time(urdf_xml, control_config):
    world, robot = lidar_world(urdf_xml, control_config)
    world.step(1000)
    assert robot.scan('lidar') is None and robot.sensor_updates('lidar') == 0
    robot.enable_sensor('lidar')
    world.step(1000)
    assert robot.sensor_updates('lidar') == 40
    stamp = robot.scan('lidar')['stamp']
    robot.enable_sensor('lidar', False)
    world.step(1000)
    assert robot.sensor_updates('lidar') == 40
    assert robot.scan('lidar')['stamp'] == stamp
