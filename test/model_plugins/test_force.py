"""gazebo_plugins' libgazebo_ros_force.so on the plant, through its Python module: a Wrench on a
topic pushes a link every step."""
import math

import pytest

from plant_helpers import force_bot, logged, spawned


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
