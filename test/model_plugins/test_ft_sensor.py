"""gazebo_plugins' libgazebo_ros_ft_sensor.so on the plant: the three-joint arm
(test/fixtures/urdf/arm.urdf, held by its position trajectory controller) with force/torque sensors
on the elbow and the wrist, as UR and Robotiq users put one on a wrist joint. Held still, each joint
reads the weight of what hangs below it, pointing down, and the moment of that weight about the
joint, in the child link's frame (Gazebo 11's sign: JointWrench body2 is what the child passes to
the joint); a push on the hand by gazebo_ros_force adds its force and its moment; the elbow's
reading turns with the forearm. Values computed here from the URDF's masses and centres."""
import math

import numpy as np
import pytest

from plant_helpers import arm, arm_controllers, logged
from tianracer_description import bullet_plant

G = 9.8
FOREARM, HAND = (0.6, np.array([0.15, 0, 0])), (0.2, np.array([0.3, 0, 0]))  # mass, centre from the elbow


def arm_with_ft_sensors_urdf(extra=''):
    """arm.urdf with ft sensors on the elbow ('ft_elbow', topic elbow_ft, every step) and the wrist
    ('ft_wrist', wrist_ft, 100 Hz), gazebo_ros_force on the hand ('push', topic push), and `extra`;
    both joints provideFeedback, as gazebo_ros_ft_sensor's users give them for Gazebo's ODE."""
    plugins = """<gazebo reference="elbow"><provideFeedback>true</provideFeedback></gazebo>
<gazebo reference="wrist"><provideFeedback>true</provideFeedback></gazebo>
<gazebo>
  <plugin name="ft_elbow" filename="libgazebo_ros_ft_sensor.so"><jointName>elbow</jointName><topicName>elbow_ft</topicName></plugin>
  <plugin name="ft_wrist" filename="libgazebo_ros_ft_sensor.so"><jointName>wrist</jointName><topicName>wrist_ft</topicName>
    <updateRate>100</updateRate></plugin>
  <plugin name="push" filename="libgazebo_ros_force.so"><bodyName>hand</bodyName><topicName>push</topicName></plugin>
  %s
</gazebo>
</robot>""" % extra
    return arm().replace('</robot>', plugins)


def arm_with_ft_sensors(extra=''):
    urdf = arm_with_ft_sensors_urdf(extra)
    world = bullet_plant.World()
    world.echo = False
    world.load_params(arm_controllers())
    world.load_params({'arm': {'robot_description': urdf}})
    robot = world.spawn(urdf, 'arm')
    names = ['joint_state_controller', 'arm_controller']
    assert robot.controller_manager.spawn(names) == (names, True), world.messages()
    return world, robot


def expected(push=np.zeros(3), bodies=(FOREARM, HAND)):
    """What hangs below the joint passes to it, held still: its weight and the push, and their
    moments about the joint, world axes."""
    force, torque = np.zeros(3), np.zeros(3)
    for mass, centre in bodies:
        weight = np.array([0, 0, -mass * G])
        force += weight
        torque += np.cross(centre, weight)
    force += push
    torque += np.cross(HAND[1] if len(bodies) == 2 else np.zeros(3), push)
    return force, torque


def test_held_still_each_joint_carries_what_hangs_below_it_and_a_push():
    world, robot = arm_with_ft_sensors()
    world.step(1000)
    elbow, wrist = robot.plugin_latest('ft_elbow', 'elbow_ft'), robot.plugin_latest('ft_wrist', 'wrist_ft')
    assert elbow['frame_id'] == 'forearm' and wrist['frame_id'] == 'hand', "the child link's frame"
    force, torque = expected()
    assert elbow['force'] == pytest.approx(force, abs=0.02) and elbow['torque'] == pytest.approx(torque, abs=0.01)
    assert wrist['force'] == pytest.approx([0, 0, -HAND[0] * G], abs=0.02) and wrist['torque'] == pytest.approx([0, 0, 0], abs=0.01)
    push = np.array([0, 5.0, 0])
    assert robot.plugin_send('push', 'push', (*push, 0, 0, 0))
    world.step(500)
    force, torque = expected(push)
    elbow, wrist = robot.plugin_latest('ft_elbow', 'elbow_ft'), robot.plugin_latest('ft_wrist', 'wrist_ft')
    assert elbow['force'] == pytest.approx(force, abs=0.02) and elbow['torque'] == pytest.approx(torque, abs=0.01)
    assert wrist['force'] == pytest.approx([0, 5.0, -HAND[0] * G], abs=0.02)


def test_the_reading_is_in_the_child_frame_and_the_wrist_reports_at_its_update_rate():
    world, robot = arm_with_ft_sensors()
    manager = robot.controller_manager
    world.step(100)
    elbow_angle = -0.5  # about y: the forearm lifted 0.5 rad
    assert manager.command('arm_controller', {'joint_names': ['shoulder', 'elbow', 'wrist'], 'points': [
        {'positions': [0.0, elbow_angle, 0.0], 'time_from_start': 0.5}], 'stamp': 0.0})
    world.step(1500)
    assert robot.joint_state('elbow')[0] == pytest.approx(elbow_angle, abs=1e-3)
    turn = np.array([[math.cos(elbow_angle), 0, math.sin(elbow_angle)], [0, 1, 0],
                     [-math.sin(elbow_angle), 0, math.cos(elbow_angle)]])  # forearm -> world
    centres = [(m, turn @ c) for m, c in (FOREARM, HAND)]
    force, torque = expected(bodies=centres)
    elbow = robot.plugin_latest('ft_elbow', 'elbow_ft')
    assert elbow['force'] == pytest.approx(turn.T @ force, abs=0.02)
    assert elbow['torque'] == pytest.approx(turn.T @ torque, abs=0.01)
    stamps = []
    for _ in range(50):
        world.step(1)
        stamps.append(robot.plugin_latest('ft_wrist', 'wrist_ft')['stamp'])
    assert len(set(stamps)) == 5, 'updateRate 100: one reading every 10 ms'


def test_a_missing_or_fixed_joint_is_refused_naming_it():
    world, robot = arm_with_ft_sensors(
        '<plugin name="ft_mount" filename="libgazebo_ros_ft_sensor.so"><jointName>mount</jointName>'
        '<topicName>mount_ft</topicName></plugin>')
    assert 'ft_mount' not in robot.model_plugins and 'ft_elbow' in robot.model_plugins
    assert any("plugin 'ft_mount' (libgazebo_ros_ft_sensor.so): jointName: mount does not exist" in m
               for m in logged(world, 'ERROR'))
