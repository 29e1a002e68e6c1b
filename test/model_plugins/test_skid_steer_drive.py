"""gazebo_plugins' libgazebo_ros_skid_steer_drive.so on the plant, through its Python module, on
a four-wheeled robot (test/fixtures/urdf/skid_bot.urdf: wheels 0.08 m across, 0.26 m apart)."""
import math

import pytest

from plant_helpers import SKID_RADIUS, SKID_SEPARATION, skid_bot, spawned, yaw_of


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
