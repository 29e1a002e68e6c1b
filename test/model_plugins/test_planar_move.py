"""gazebo_plugins' libgazebo_ros_planar_move.so on the plant, through its Python module, on a
holonomic base (test/fixtures/urdf/planar_bot.urdf)."""
import math

import pytest

from plant_helpers import planar_bot, spawned, yaw_of


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
