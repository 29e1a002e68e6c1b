"""gazebo_plugins' libgazebo_ros_hand_of_god.so on the plant: a floating box (written here) pulled by
the plugin to the pose tf gives for hog_desired in world, directly or through another frame, its
gravity off; hog_actual broadcast; a missing frame reported once while the box floats; a missing
linkName refused."""
import math

import pytest

from plant_helpers import logged
from tianracer_description import bullet_plant

BOX = """<robot name="hog_box"><link name="box">
  <inertial><mass value="2.0"/><inertia ixx="0.02" iyy="0.02" izz="0.02" ixy="0" ixz="0" iyz="0"/></inertial>
  <collision><geometry><box size="0.2 0.2 0.2"/></geometry></collision></link>
  <gazebo><plugin name="hog" filename="libgazebo_ros_hand_of_god.so">%s</plugin></gazebo>
</robot>"""


def floating_box(params='<linkName>box</linkName>'):
    world = bullet_plant.World()
    world.echo = False
    robot = world.spawn(BOX % params, 'hog_box', [0, 0, 1.0, 0, 0, 0])
    return world, robot


def yaw_quaternion(yaw):
    return [0.0, 0.0, math.sin(yaw / 2), math.cos(yaw / 2)]


def test_the_box_is_pulled_to_the_desired_frame_and_its_actual_pose_broadcast():
    world, robot = floating_box()
    assert robot.plugin_topics('hog') == {'subscribes': ['/tf', '/tf_static'], 'publishes': ['/tf']}
    # world -> target (tf_static), target -> hog_desired (tf): the desired pose at (1, 0.5, 2), yaw 0.5
    assert robot.plugin_send('hog', '/tf_static', [
        {'frame_id': 'world', 'child_frame_id': 'target', 'pose': [1.0, 0.5, 0.0, *yaw_quaternion(0.0)]}])
    assert robot.plugin_send('hog', '/tf', [
        {'frame_id': 'target', 'child_frame_id': 'hog_desired', 'pose': [0.0, 0.0, 2.0, *yaw_quaternion(0.5)]}])
    world.step(3000)
    pose = robot.base_pose()
    assert pose[:3] == pytest.approx([1.0, 0.5, 2.0], abs=1e-3), 'held there against gravity'
    yaw = 2 * math.atan2(pose[5], pose[6])
    assert yaw == pytest.approx(0.5, abs=1e-3)
    actual = robot.plugin_latest('hog', '/tf')
    assert actual['frame_id'] == 'world' and actual['child_frame_id'] == 'hog_actual'
    assert list(actual['pose'][:3]) == pytest.approx([1.0, 0.5, 2.0], abs=1e-3)


def test_critically_damped_no_overshoot():
    world, robot = floating_box('<linkName>box</linkName><kl>50</kl>')
    robot.plugin_send('hog', '/tf', [{'frame_id': 'world', 'child_frame_id': 'hog_desired',
                                      'pose': [0.5, 0.0, 1.0, 0, 0, 0, 1]}])
    xs = []
    for _ in range(300):
        world.step(10)
        xs.append(robot.base_pose()[0])
    assert max(xs) <= 0.5 + 1e-3, 'cl = 2 sqrt(kl m): no overshoot'
    # x(t) = 0.5 (1 - (1 + t / tau) e^(-t / tau)), tau = sqrt(m / kl) = 0.2 s
    t, tau = 0.4, math.sqrt(2.0 / 50)
    assert xs[39] == pytest.approx(0.5 * (1 - (1 + t / tau) * math.exp(-t / tau)), abs=0.01)


def test_a_missing_frame_is_reported_once_and_the_box_floats():
    world, robot = floating_box()
    world.step(1000)
    assert robot.base_pose()[2] == pytest.approx(1.0, abs=1e-6), 'gravity off for the hand of god'
    errors = [m for m in logged(world, 'ERROR') if 'lookupTransform' in m]
    assert len(errors) == 1 and '"world" passed to lookupTransform argument target_frame does not exist.' in errors[0], \
        "tf2's words for an empty tree, once"
    robot.plugin_send('hog', '/tf', [{'frame_id': 'world', 'child_frame_id': 'elsewhere', 'pose': [0, 0, 0, 0, 0, 0, 1]}])
    world.step(10)
    assert len([m for m in logged(world, 'ERROR') if 'lookupTransform' in m]) == 1, \
        'another failure before a success is not logged again, as upstream'
    world, robot = floating_box('<frameId>hog</frameId>')
    assert robot.model_plugins == []
    assert any('The hand-of-god plugin requires a `linkName` parameter tag' in m for m in logged(world, 'ERROR'))
