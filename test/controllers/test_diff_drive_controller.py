"""ros_controllers' diff_drive_controller on the plant, through its Python module: the diff_bot
(test/fixtures/urdf/diff_bot.urdf) driven as Husky and Jackal drive, through gazebo_ros_control, its
wheel separation and radius read from the URDF."""
import math

import pytest

from plant_helpers import DIFF_DRIVE_CONTROLLERS, DIFF_RADIUS, DIFF_SEPARATION, diff_bot_with_gazebo_ros_control, yaw_of
from tianracer_description import bullet_plant


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
    assert left == pytest.approx((0.2 - 0.5 * DIFF_SEPARATION / 2) / DIFF_RADIUS, rel=0.02), 'separation 0.3 m'
    assert right == pytest.approx((0.2 + 0.5 * DIFF_SEPARATION / 2) / DIFF_RADIUS, rel=0.02), 'radius 35 mm'
    odometry = manager.odometry('mobile_base_controller')
    assert odometry['linear'] == pytest.approx(0.2, rel=0.03) and odometry['angular'] == pytest.approx(0.5, rel=0.03)
    # The wheels' odometry against the plant's pose, both from where the controller started.
    pose = robot.base_pose()
    moved = math.hypot(pose[0] - start[0], pose[1] - start[1])
    assert math.hypot(odometry['x'], odometry['y']) == pytest.approx(moved, rel=0.05)
    assert odometry['heading'] == pytest.approx(math.remainder(yaw_of(pose) - yaw_of(start), 2 * math.pi), abs=0.05)
    assert (odometry['frame_id'], odometry['child_frame_id']) == ('odom', 'base_footprint')
    world.step(600)  # 0.65 s after the last Twist: braking since 0.5 s, at 1 m/s^2 from 0.2 m/s
    assert robot.joint_state('wheel_left_joint')[1] * DIFF_RADIUS == pytest.approx(0.05, abs=0.01)
    world.step(100)
    assert abs(robot.joint_state('wheel_left_joint')[1]) < 0.05, 'cmd_vel_timeout 0.5 s, then the ramp down: stopped'
