"""gazebo_plugins' libgazebo_ros_tricycle_drive.so on the plant, through its Python module
(test/fixtures/urdf/tricycle_bot.urdf: every default fits it; wheelbase 0.4 m)."""
import math

import pytest

from plant_helpers import spawned, tricycle_bot, yaw_of


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
