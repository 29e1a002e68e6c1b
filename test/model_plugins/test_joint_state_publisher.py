"""gazebo_plugins' libgazebo_ros_joint_state_publisher.so on the plant, through its Python module,
on the four-wheeled skid_bot (test/fixtures/urdf/skid_bot.urdf)."""
import pytest

from plant_helpers import SKID_RADIUS, logged, skid_bot, spawned


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
