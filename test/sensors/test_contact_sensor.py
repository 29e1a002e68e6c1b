"""Contact sensors (<sensor type="contact">, gazebo_ros_bumper's parent) on the plant, from Python:
what a bumper's users compute from ContactsState. The fixture (test/fixtures/urdf/bumper_bot.urdf)
is a frictionless 4.5 kg box robot whose bumper is lumped into base_link, as Gazebo's URDF converter
lumps it, pushed by gazebo_ros_force into a wall."""
import math
import os

import pytest

from plant_helpers import FIXTURES, box_model, logged, sdf_world
from tianracer_description import bullet_plant

MASS, G = 4.5, 9.8
BUMPER_FACE = 0.24  # the bumper's front face, ahead of base_link's origin


def bumper_bot_before_wall(gap=0.05):
    wall_x = BUMPER_FACE + gap + 0.05
    world = bullet_plant.World.from_sdf(sdf_world(box_model('wall', (0.1, 2.0, 0.5), (wall_x, 0, 0.25))))
    world.echo = False
    with open(os.path.join(FIXTURES, 'urdf', 'bumper_bot.urdf')) as f:
        robot = world.spawn(f.read(), 'bumper_bot', pose=(0, 0, 0.05, 0, 0, 0))
    for name in robot.sensors:
        robot.enable_sensor(name)
    return world, robot


def total(vectors):
    return [sum(v[i] for v in vectors) for i in range(3)]


def test_resting_on_the_ground_the_contacts_carry_the_weight():
    world, robot = bumper_bot_before_wall()
    assert robot.sensors == ['base_contact', 'bumper_sensor'] and logged(world, 'WARN') == []
    world.step(300)
    reading = robot.contacts('base_contact')
    assert reading['frame_id'] == 'world', 'gazebo_ros_bumper\'s default frameName'
    [state] = reading['states']
    assert state['collision1_name'] == 'bumper_bot::base_link::base_link_collision', 'the sensor\'s own, scoped'
    assert state['collision2_name'] == 'ground_plane::link::collision'
    assert len(state['depths']) == 4, 'the box\'s four bottom corners'
    assert total(state['forces']) == pytest.approx([0, 0, MASS * G], abs=1e-3)
    for position, normal, depth in zip(state['contact_positions'], state['contact_normals'], state['depths']):
        assert normal == pytest.approx([0, 0, 1], abs=1e-6), 'out of the ground into the sensor\'s collision'
        assert 0 <= depth < 1e-3
        assert abs(position[0]) == pytest.approx(0.2, abs=1e-4) and abs(position[1]) == pytest.approx(0.15, abs=1e-4)
        assert position[2] == pytest.approx(0, abs=1e-3)
    assert robot.contacts('bumper_sensor')['states'] == [], 'the bumper touches nothing yet'


def test_the_bumper_reports_the_push_it_takes_from_a_wall():
    world, robot = bumper_bot_before_wall()
    world.step(100)
    assert robot.plugin_send('push', 'force', (10.0, 0, 0, 0, 0, 0))
    world.step(1500)  # 5 cm in about 0.2 s, then held against the wall
    assert robot.base_pose()[0] == pytest.approx(0.05, abs=1e-3)
    reading = robot.contacts('bumper_sensor')
    assert reading['frame_id'] == 'bumper'
    [state] = reading['states']
    assert state['collision1_name'] == 'bumper_bot::base_link::base_link_fixed_joint_lump__bumper_collision_1'
    assert state['collision2_name'] == 'wall::link::collision'
    assert total(state['forces']) == pytest.approx([-10.0, 0, 0], abs=1e-3), 'the wall holds the 10 N push'
    com = [0.05 + 0.5 * 0.22 / MASS, 0, 0.05]  # the lumped body's centre of mass
    for position, normal, force, torque in zip(state['contact_positions'], state['contact_normals'],
                                               state['forces'], state['torques']):
        assert normal == pytest.approx([-1, 0, 0], abs=1e-6)
        assert position[0] == pytest.approx(0.05 + BUMPER_FACE, abs=1e-3), 'on the bumper\'s face'
        assert 0.02 - 1e-3 <= position[2] <= 0.08 + 1e-3
        r = [position[i] - com[i] for i in range(3)]
        moment = [r[1] * force[2] - r[2] * force[1], r[2] * force[0] - r[0] * force[2], r[0] * force[1] - r[1] * force[0]]
        assert torque == pytest.approx(moment, abs=1e-5), 'about the body\'s centre of mass'
    # the ground under the pushed robot still carries the weight, and nothing else touches it
    [ground] = robot.contacts('base_contact')['states']
    assert total(ground['forces'])[2] == pytest.approx(MASS * G, abs=1e-2)


def test_a_contact_sensor_names_collisions_as_gazebos_urdf_converter_does():
    # A collision the body does not have (a name written as the link's, not the lumped one) sees
    # nothing, as in Gazebo.
    with open(os.path.join(FIXTURES, 'urdf', 'bumper_bot.urdf')) as f:
        urdf = f.read().replace('base_link_fixed_joint_lump__bumper_collision_1', 'bumper_collision')
    world = bullet_plant.World.from_sdf(sdf_world(box_model('wall', (0.1, 2.0, 0.5), (0.3, 0, 0.25))))
    world.echo = False
    robot = world.spawn(urdf, 'bumper_bot', pose=(0, 0, 0.05, 0, 0, 0))
    robot.enable_sensor('bumper_sensor')
    robot.plugin_send('push', 'force', (10.0, 0, 0, 0, 0, 0))
    world.step(500)
    assert robot.base_pose()[0] < 0.03, 'against the wall'
    assert robot.contacts('bumper_sensor')['states'] == []


def test_a_bumper_plugin_on_a_sensor_that_is_not_a_contact_sensor_is_refused():
    with open(os.path.join(FIXTURES, 'urdf', 'bumper_bot.urdf')) as f:
        urdf = f.read().replace('<sensor type="contact" name="bumper_sensor">', '<sensor type="imu" name="bumper_sensor">')
    world = bullet_plant.World()
    world.echo = False
    robot = world.spawn(urdf, 'bumper_bot')
    assert any("sensor 'bumper_sensor': libgazebo_ros_bumper.so needs a <sensor type=\"contact\">" in m
               for m in logged(world, 'ERROR'))
    world.step(10)
    assert robot.sensor_topic('base_contact') == 'bumper_states'
