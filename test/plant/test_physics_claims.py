"""docs/gazebo_compatibility.md's claims about how the plant's physics differs from Gazebo's, each checked through the
Python module (no ROS master): the friction of two surfaces is the smaller one (ODE's rule), the
tutorial's steering gains oscillate when applied explicitly and settle as the plant applies them, the
car at rest creeps less than half a millimetre in 10 s, a moving link's mesh collision is its convex hull.
(The joint-space dynamics against Bullet's own pass: test/cpp/.)"""
import math

import numpy as np
import pytest

from plant_helpers import box_stl, make_world
from tianracer_description import bullet_plant

SLOPE = math.atan(0.45)  # a block stays on this ramp with friction 0.45 or more


def block_urdf(mu=None, collision='<box size="0.1 0.1 0.05"/>'):
    surface = f'<gazebo reference="block"><mu1>{mu}</mu1><mu2>{mu}</mu2></gazebo>' if mu is not None else ''
    return f"""<robot name="block"><link name="block">
  <inertial><mass value="1"/><inertia ixx="0.001" iyy="0.001" izz="0.001" ixy="0" ixz="0" iyz="0"/></inertial>
  <collision><geometry>{collision}</geometry></collision></link>{surface}</robot>"""


def ramp_world(mu):
    return f"""<?xml version="1.0"?><sdf version="1.6"><world name="ramp">
  <model name="ramp"><static>true</static><pose>0 0 0.5 0 {SLOPE} 0</pose><link name="link">
    <collision name="collision"><geometry><box><size>2 1 0.1</size></box></geometry>
      <surface><friction><ode><mu>{mu}</mu><mu2>{mu}</mu2></ode></friction></surface></collision></link></model>
</world></sdf>"""


def slide_on_ramp(block_mu, ramp_mu):
    """How far a block of friction block_mu slides in 1 s on a ramp of ramp_mu (after settling 0.2 s)."""
    world = bullet_plant.World.from_sdf(ramp_world(ramp_mu))
    world.echo = False
    above = 0.05 + 0.025 + 0.0005  # ramp half thickness, block half height, a gap
    block = world.spawn(block_urdf(block_mu), 'block',
                        pose=(above * math.sin(SLOPE), 0, 0.5 + above * math.cos(SLOPE), 0, SLOPE, 0))
    world.step(200)
    start = block.base_pose()[:3].copy()
    world.step(1000)
    return float(np.linalg.norm(block.base_pose()[:3] - start))


@pytest.mark.parametrize('block_mu, ramp_mu', [(0.5, 0.8), (0.8, 0.5)])
def test_contact_friction_is_the_smaller_of_the_two_not_their_product(block_mu, ramp_mu):
    # min 0.5 holds the block on a 0.45 slope; Bullet's own product (0.4) would let it slide ~0.3 m.
    assert slide_on_ramp(block_mu, ramp_mu) < 1e-3


@pytest.mark.parametrize('block_mu, ramp_mu', [(0.3, 0.9), (0.9, 0.3)])
def test_contact_friction_is_the_smaller_of_the_two_not_the_larger(block_mu, ramp_mu):
    # min 0.3 lets the block slide (a = g (sin - 0.3 cos) = 1.3 m/s^2); the larger, 0.9, would hold it.
    assert slide_on_ramp(block_mu, ramp_mu) > 0.5


def steering_response(world, robot, explicit):
    """The left hinge's angle over 2 s after a step to 0.3 rad with the tutorial's p 4, d 1 (the
    steering controllers' gains), applied as a plain effort each step or as the plant applies them."""
    joint = 'left_steering_hinge_joint'
    for hinge in ('left_steering_hinge_joint', 'right_steering_hinge_joint'):
        robot.set_effort_law(hinge, stiffness=4.0, position_target=0.0, damping=1.0)
    world.step(500)
    angles = []
    for _ in range(2000):
        q, qd, _ = robot.joint_state(joint)
        if explicit:
            robot.set_command(joint, 4.0 * (0.3 - q) - 1.0 * qd)  # control_toolbox's PD on the state now
        else:
            robot.set_effort_law(joint, stiffness=4.0, position_target=0.3, damping=1.0)
        world.step()
        angles.append(robot.joint_state(joint)[0])
    return np.array(angles)


def test_the_tutorials_steering_gains_oscillate_explicitly_and_settle_implicitly(urdf_xml, control_config):
    """The hinge's inertia is ~3e-5 kg m^2: d dt / I = 33, so an explicit derivative term overshoots
    33-fold every step and the hinge chatters at its effort limit; evaluated at the end of the step
    (the plant's way) the same gains give a first-order lag of d/p = 0.25 s."""
    explicit = make_world(control_config)
    explicit_angles = steering_response(explicit, explicit.spawn(urdf_xml, 'tianracer'), explicit=True)
    implicit = make_world(control_config)
    implicit_angles = steering_response(implicit, implicit.spawn(urdf_xml, 'tianracer'), explicit=False)
    tail = slice(1500, None)  # the last half second
    assert np.abs(implicit_angles[tail] - 0.3).max() < 0.01, 'implicit: settled at the target'
    assert np.abs(explicit_angles[tail] - 0.3).max() > 0.05, 'explicit: never settles'
    assert np.count_nonzero(np.diff(np.sign(np.diff(explicit_angles[tail])))) > 100, 'explicit: chatters'


def test_the_car_at_rest_creeps_less_than_half_a_millimetre_in_10_s(urdf_xml, control_config):
    world = make_world(control_config)
    robot = world.spawn(urdf_xml, 'tianracer')
    world.step(1000)
    start = robot.base_pose()
    world.step(10000)
    assert np.hypot(*(robot.base_pose()[:2] - start[:2])) < 5e-4


def test_a_moving_mesh_collision_is_its_convex_hull_said_in_the_log(tmp_path):
    mesh = tmp_path / 'slab.stl'
    box_stl(mesh, (-0.1, -0.05, 0.0), (0.1, 0.05, 0.06))  # its bottom at the link origin
    world = bullet_plant.World()
    world.echo = False
    block = world.spawn(block_urdf(collision=f'<mesh filename="file://{mesh}"/>'), 'block', pose=(0, 0, 0.1, 0, 0, 0))
    world.step(1000)
    assert block.base_pose()[2] == pytest.approx(0.0, abs=1e-3), 'a box mesh\'s hull is the box: rests on its bottom'
    lines = [text for level, text in world.messages()]
    assert any('convex hull' in text and 'slab.stl' in text and "'block'" in text for text in lines), lines