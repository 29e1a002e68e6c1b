"""hector's libgazebo_ros_force_based_move.so on the plant, through its Python module, on a
holonomic base (force_based_bot)."""
import math

import pytest

from plant_helpers import force_based_bot, logged, spawned, yaw_of


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
