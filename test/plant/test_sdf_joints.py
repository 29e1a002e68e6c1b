"""SDF's joints beyond a tree of hinges and slides, checked against the physics they stand for and
against Gazebo 11's ODE joints: a ball joint (a spherical pendulum's period in two planes, a conical
pendulum keeping its cone and its energy, the joint state Gazebo reports for it), a screw (advancing
-1 / thread_pitch metres a radian, Gazebo's left-handed sign; falling along a vertical screw at
g m p^2 / (m p^2 + I); turned by a torque at tau / (I + m p^2)), a gearbox (the child gear at
-gearbox_ratio times the parent gear's angle from the reference body; balanced by efforts in that
ratio), and bad ones refused or left out naming model, joint and value. Models are SDF text spawned
into the plant's default world (1 ms steps, g = 9.8)."""
import math

import numpy as np
import pytest

from plant_helpers import logged
from tianracer_description import bullet_plant as bp

G = 9.8


def sdf(body, name='m'):
    return f'<?xml version="1.0"?><sdf version="1.7"><model name="{name}">{body}</model></sdf>'


def inertial(mass, ixx, iyy=None, izz=None):
    iyy = ixx if iyy is None else iyy
    izz = ixx if izz is None else izz
    return (f'<inertial><mass>{mass}</mass><inertia><ixx>{ixx}</ixx><iyy>{iyy}</iyy><izz>{izz}</izz>'
            '<ixy>0</ixy><ixz>0</ixz><iyz>0</iyz></inertia></inertial>')


def spawn(model, name='m'):
    w = bp.World()
    w.echo = False
    return w, w.spawn(model, name, [0, 0, 0, 0, 0, 0])


def crossings(t, x):
    """Times where x crosses its mean upwards, linearly interpolated."""
    x = np.asarray(x) - np.mean(x)
    i = np.nonzero((x[:-1] < 0) & (x[1:] >= 0))[0]
    return t[i] + (t[i + 1] - t[i]) * (-x[i]) / (x[i + 1] - x[i])


def quat_matrix(q):
    qx, qy, qz, qw = q
    return np.array([[1 - 2 * (qy * qy + qz * qz), 2 * (qx * qy - qz * qw), 2 * (qx * qz + qy * qw)],
                     [2 * (qx * qy + qz * qw), 1 - 2 * (qx * qx + qz * qz), 2 * (qy * qz - qx * qw)],
                     [2 * (qx * qz - qy * qw), 2 * (qy * qz + qx * qw), 1 - 2 * (qx * qx + qy * qy)]])


def yaw(pose):
    qx, qy, qz, qw = pose[3:7]
    return math.atan2(2 * (qw * qz + qx * qy), 1 - 2 * (qy * qy + qz * qz))


# Ball joints.

PIVOT = np.array([0.0, 0.0, 2.0])  # where the ball pendulums hang from the world
LENGTH = 1.0


def ball_pendulum(bob, extra=''):
    """A 1 kg point mass (inertia 1e-6) at `bob` on a massless rod from a ball joint at PIVOT: the
    joint's zero is where the bob starts."""
    x, y, z = bob
    return sdf(f"""
<link name="bob"><pose>{x} {y} {z} 0 0 0</pose>{inertial(1.0, 1e-6)}</link>
<joint name="ball" type="ball"><parent>world</parent><child>bob</child>
  <pose>{PIVOT[0] - x} {PIVOT[1] - y} {PIVOT[2] - z} 0 0 0</pose>{extra}</joint>""", 'pendulum')


@pytest.mark.parametrize('plane', ['x', 'y'])
def test_a_ball_jointed_pendulum_swings_at_two_pi_root_l_over_g_in_either_plane(plane):
    angle = 0.05
    offset = LENGTH * math.sin(angle)
    bob = PIVOT + np.array([offset if plane == 'x' else 0.0, offset if plane == 'y' else 0.0, -LENGTH * math.cos(angle)])
    w, p = spawn(ball_pendulum(bob))
    t, s, side = [], [], []
    k, other = (0, 1) if plane == 'x' else (1, 0)
    for _ in range(10000):
        w.step(1)
        position = p.link_pose('bob')[:3]
        t.append(w.time)
        s.append(position[k])
        side.append(position[other])
    assert max(s) - min(s) == pytest.approx(2 * offset, rel=0.02)  # swings, and keeps its amplitude
    assert max(abs(v) for v in side) < 1e-6  # in its plane
    periods = np.diff(crossings(np.array(t), s))
    expected = 2 * math.pi * math.sqrt(LENGTH / G) * (1 + angle ** 2 / 16)
    assert np.mean(periods) == pytest.approx(expected, rel=0.005), periods
    # the rod keeps its length: the joint holds the bob at L from the pivot
    assert np.linalg.norm(np.array(p.link_pose('bob')[:3]) - PIVOT) == pytest.approx(LENGTH, abs=1e-5)


def test_a_conical_pendulum_keeps_its_cone_its_energy_and_turns_at_root_g_over_l_cos():
    # The bob 30 deg out in x, kicked along y to the conical pendulum's speed sqrt(g L sin tan)
    # by one step of force (m v / dt for the step at time 0: a job lasting half a step).
    cone = math.radians(30)
    bob = PIVOT + LENGTH * np.array([math.sin(cone), 0.0, -math.cos(cone)])
    speed = math.sqrt(G * LENGTH * math.sin(cone) * math.tan(cone))
    w, p = spawn(ball_pendulum(bob))
    p.apply_link_wrench('bob', [0, speed / 1e-3, 0], start=0.0, duration=0.5e-3)
    w.step(1)
    t, polar, azimuth, energy = [], [], [], []
    previous = None
    for _ in range(5000):
        w.step(1)
        position = np.array(p.link_pose('bob')[:3])
        r = position - PIVOT
        if previous is not None:
            v = (position - previous) / 1e-3  # over one step: its mean velocity
            middle = r - (position - previous) / 2
            energy.append(0.5 * v @ v + G * middle[2])
        previous = position
        t.append(w.time)
        polar.append(math.acos(-r[2] / np.linalg.norm(r)))
        azimuth.append(math.atan2(r[1], r[0]))
    assert max(abs(a - cone) for a in polar) < 0.01 * cone, (min(polar), max(polar))  # keeps its cone
    assert max(energy) - min(energy) < 1e-3 * (0.5 * speed ** 2 + G * LENGTH * math.cos(cone)), (min(energy), max(energy))
    turns = np.unwrap(azimuth)
    rate = (turns[-1] - turns[0]) / (t[-1] - t[0])
    assert rate == pytest.approx(math.sqrt(G / (LENGTH * math.cos(cone))), rel=0.005)


def test_a_ball_joint_reports_what_gazebos_ode_ball_joint_does():
    # Gazebo 11's ODEBallJoint: Position() NaN, GetVelocity() 0, SetForce not implemented; the plant's
    # joint_names lists the joints that have one position (get_model_properties lists the ball too).
    w, p = spawn(ball_pendulum(PIVOT + np.array([0.1, 0.0, -0.99])))
    w.step(100)
    position, velocity, effort = p.joint_state('ball')
    assert math.isnan(position) and velocity == 0 and effort == 0
    assert 'ball' not in p.joint_names
    assert not [m for m in logged(w, 'WARN') if 'held fixed' in m]


def test_a_ball_joint_goes_back_to_its_spawn_pose_at_reset():
    bob = PIVOT + np.array([0.3, 0.0, -math.sqrt(1 - 0.09)])
    w, p = spawn(ball_pendulum(bob))
    w.step(300)
    assert np.linalg.norm(np.array(p.link_pose('bob')[:3]) - bob) > 0.05
    w.reset_simulation()
    assert np.allclose(p.link_pose('bob')[:3], bob, atol=1e-6)
    w.step(1)
    assert np.linalg.norm(np.array(p.link_pose('bob')[:3]) - bob) < 1e-4  # at rest: only gravity's first step


def test_a_ball_joints_axis_and_dynamics_are_said_to_be_ignored_as_gazebo_ignores_them():
    w, p = spawn(ball_pendulum(PIVOT + np.array([0.1, 0.0, -0.99]),
                               '<axis><xyz>0 0 1</xyz><dynamics><damping>1</damping></dynamics></axis>'))
    assert [m for m in logged(w, 'WARN') if "joint 'ball'" in m and '<axis>' in m and 'ignored' in m]


# Screw joints.

def screw(thread_pitch, axis='0 0 1', mass=1.0, inertia=0.0025, pitch_element='thread_pitch', extra=''):
    """A nut (its centre of mass on the screw's axis) at 1 m on a screw fixed to the world."""
    return sdf(f"""
<link name="nut"><pose>0 0 1 0 0 0</pose>{inertial(mass, inertia)}</link>
<joint name="screw" type="screw"><parent>world</parent><child>nut</child>
  <{pitch_element}>{thread_pitch}</{pitch_element}><axis><xyz>{axis}</xyz>{extra}</axis></joint>""", 'screw')


def test_a_nut_falls_down_a_vertical_screw_at_g_m_p2_over_m_p2_plus_i_turning_minus_one_over_thread_pitch():
    # Gazebo 11 (ODEScrewJoint, ODE's screw row): translation = -angle / thread_pitch, in rad/m:
    # a positive thread_pitch is a left-handed thread. Per radian the nut moves p = -1 / thread_pitch;
    # its energy (m p^2 + I) thetadot^2 / 2 against m g p theta: thetadd = -m g p / (m p^2 + I),
    # the fall zdd = p thetadd = -g m p^2 / (m p^2 + I) (an effective mass m + I / p^2).
    thread_pitch, m, inertia = 20.0, 1.0, 0.0025
    p = -1.0 / thread_pitch
    w, robot = spawn(screw(thread_pitch, mass=m, inertia=inertia))
    z0 = robot.link_pose('nut')[2]
    w.step(500)
    angle, rate, _ = robot.joint_state('screw')
    drop = robot.link_pose('nut')[2] - z0
    assert drop < -0.5 and angle > 0  # falls, turning positively: left-handed
    assert drop / angle == pytest.approx(p, rel=1e-3)
    thetadd = -m * G * p / (m * p * p + inertia)
    assert rate == pytest.approx(thetadd * 0.5, rel=5e-3)  # symplectic Euler: the rate is exact for constant acceleration
    assert np.allclose(robot.link_pose('nut')[:2], [0, 0], atol=1e-6)  # stays on the axis
    # the nut turns about the screw's axis only
    assert yaw(robot.link_pose('nut')) == pytest.approx(math.remainder(angle, 2 * math.pi), abs=1e-4)


def test_a_torque_turns_a_screw_at_tau_over_i_plus_m_p2_and_advances_it_a_pitch_a_turn():
    # A horizontal screw (x): gravity pulls across it. A torque tau about x on the nut (the joint's
    # effort, as gazebo_ros's apply_joint_effort on Gazebo's screw joint adds dJointAddScrewTorque).
    thread_pitch, m, inertia, tau = -40.0, 2.0, 0.004, 0.3
    p = -1.0 / thread_pitch  # right-handed here
    w, robot = spawn(screw(thread_pitch, axis='1 0 0', mass=m, inertia=inertia))
    x0 = robot.link_pose('nut')[0]
    robot.apply_link_wrench('nut', [0, 0, 0], [tau, 0, 0])
    w.step(1000)
    angle, rate, _ = robot.joint_state('screw')
    advance = robot.link_pose('nut')[0] - x0
    assert advance / angle == pytest.approx(p, rel=1e-3)
    assert advance > 0 and angle > 0
    assert rate == pytest.approx(tau / (inertia + m * p * p) * 1.0, rel=5e-3)
    assert robot.link_pose('nut')[2] == pytest.approx(1.0, abs=1e-4)  # held on its axis against gravity


def test_screw_thread_pitch_of_sdf_1_10_is_metres_a_turn_right_handed():
    # sdformat 13's <screw_thread_pitch> (m/rev, positive right-handed) where <thread_pitch> is absent.
    w, robot = spawn(screw(0.1, pitch_element='screw_thread_pitch'))
    z0 = robot.link_pose('nut')[2]
    w.step(300)
    angle = robot.joint_state('screw')[0]
    assert (robot.link_pose('nut')[2] - z0) / angle == pytest.approx(0.1 / (2 * math.pi), rel=1e-3)


def test_a_screw_lists_one_joint_and_keeps_its_turn_limits():
    w, robot = spawn(screw(20.0, extra='<limit><lower>-1</lower><upper>3</upper></limit>'))
    assert robot.joint_names == ['screw']
    w.step(2000)
    angle = robot.joint_state('screw')[0]
    assert angle == pytest.approx(3.0, abs=0.02)  # stopped at the upper limit of its turn
    assert robot.link_pose('nut')[2] == pytest.approx(1.0 - angle / 20.0, abs=1e-4)


@pytest.mark.parametrize('pitch', ['0', 'nan', 'inf', '1e-9'])
def test_a_screw_without_a_usable_thread_pitch_is_refused_naming_it(pitch):
    with pytest.raises(bp.DescriptionError) as refused:
        spawn(screw(pitch))
    message = str(refused.value)
    assert "model 'screw'" in message and "joint 'screw'" in message and 'thread_pitch' in message, message


# Gearbox joints.

def gears(ratio='2', axis2_sign='', j2_axis='0 0 1', child_joint='revolute', reference='base', extra=''):
    """Two gears on revolute joints from a base fixed to the world, coupled by a gearbox (parent gear1,
    child gear2, about z): gear1 0.01 kg m^2, gear2 0.02 kg m^2 about their axes."""
    return sdf(f"""
<link name="base"><pose>0 0 1 0 0 0</pose>{inertial(5.0, 0.1)}</link>
<joint name="anchor" type="fixed"><parent>world</parent><child>base</child></joint>
<link name="gear1"><pose>0 0 1.1 0 0 0</pose>{inertial(1.0, 0.01)}</link>
<link name="gear2"><pose>0.3 0 1.1 0 0 0</pose>{inertial(1.0, 0.02)}</link>
<joint name="j1" type="revolute"><parent>base</parent><child>gear1</child><axis><xyz>0 0 1</xyz></axis></joint>
<joint name="j2" type="{child_joint}"><parent>base</parent><child>gear2</child><axis><xyz>{j2_axis}</xyz></axis></joint>
<joint name="gb" type="gearbox"><parent>gear1</parent><child>gear2</child>
  <gearbox_reference_body>{reference}</gearbox_reference_body><gearbox_ratio>{ratio}</gearbox_ratio>
  <axis><xyz>0 0 {axis2_sign}1</xyz></axis><axis2><xyz>0 0 1</xyz></axis2>{extra}</joint>""", 'gears')


@pytest.mark.parametrize('j2_axis', ['0 0 1', '0 0 -1'])
def test_driving_one_gear_turns_the_other_at_minus_the_ratio(j2_axis):
    # theta_child = -gearbox_ratio theta_parent (sdformat's joint.sdf; ODE's gearbox row), the angles
    # about the gearbox's axes from the reference body. A torque tau on gear1 meets the inertia
    # I1 + r^2 I2 of the pair.
    ratio, tau = 2.0, 0.5
    w, robot = spawn(gears(str(ratio), j2_axis=j2_axis))
    robot.apply_link_wrench('gear1', [0, 0, 0], [0, 0, tau])
    w.step(1000)
    turn1, turn2 = yaw(robot.link_pose('gear1')), yaw(robot.link_pose('gear2'))
    q1, rate1, _ = robot.joint_state('j1')
    q2, rate2, _ = robot.joint_state('j2')
    sign = 1 if j2_axis == '0 0 1' else -1
    assert q2 == pytest.approx(-ratio * sign * q1, rel=1e-3)
    assert rate2 == pytest.approx(-ratio * sign * rate1, rel=1e-3)
    assert math.remainder(turn2 + ratio * q1, 2 * math.pi) == pytest.approx(0, abs=2e-3)  # physically opposite
    assert turn1 == pytest.approx(math.remainder(q1, 2 * math.pi), abs=1e-4)
    assert rate1 == pytest.approx(tau / (0.01 + ratio ** 2 * 0.02) * 1.0, rel=5e-3)


def test_gears_balanced_by_efforts_in_the_ratio_stay_still():
    # Gazebo's joint_gearbox test: a torque ratio * tau on the parent gear against tau on the child.
    ratio, tau = -1.5, 1.0
    w, robot = spawn(gears(str(ratio)))
    robot.apply_link_wrench('gear1', [0, 0, 0], [0, 0, ratio * tau])
    robot.apply_link_wrench('gear2', [0, 0, 0], [0, 0, tau])
    w.step(1000)
    for joint in ('j1', 'j2'):
        q, rate, _ = robot.joint_state(joint)
        assert abs(q) < 1e-6 and abs(rate) < 1e-6, (joint, q, rate)


def test_a_gearbox_is_no_joint_of_its_own_and_the_gears_are_listed():
    w, robot = spawn(gears())
    assert sorted(robot.joint_names) == ['j1', 'j2']
    assert not logged(w, 'ERROR')


def test_a_gearbox_ratio_of_zero_holds_the_child_gear_saying_so():
    w, robot = spawn(gears('0'))
    assert [m for m in logged(w, 'WARN') if "joint 'gb'" in m and 'gearbox_ratio' in m and '0' in m]
    robot.apply_link_wrench('gear2', [0, 0, 0], [0, 0, 1.0])
    robot.apply_link_wrench('gear1', [0, 0, 0], [0, 0, 1.0])
    w.step(500)
    assert abs(robot.joint_state('j2')[0]) < 1e-4
    assert robot.joint_state('j1')[0] > 1.0


@pytest.mark.parametrize('ratio', ['nan', 'inf', 'two'])
def test_a_gearbox_ratio_that_is_no_number_is_refused_naming_it(ratio):
    with pytest.raises(bp.DescriptionError) as refused:
        spawn(gears(ratio))
    message = str(refused.value)
    assert "model 'gears'" in message and "joint 'gb'" in message and 'gearbox_ratio' in message, message


@pytest.mark.parametrize('case, words', [
    (dict(child_joint='prismatic'), ["'j2'", 'prismatic', 'revolute']),
    (dict(reference='gear1'), ['gearbox_reference_body', "'gear1'"]),
    (dict(reference='nowhere'), ['gearbox_reference_body', "'nowhere'"]),
    (dict(axis2_sign='', extra='', j2_axis='1 0 0'), ["'j2'", 'axis']),
])
def test_a_gearbox_the_plant_cannot_couple_is_left_out_with_an_error_and_the_model_moves_on(case, words):
    w, robot = spawn(gears(**case))
    errors = [m for m in logged(w, 'ERROR') if "joint 'gb'" in m and "'gears'" in m]
    assert errors and all(word in errors[0] for word in words), logged(w, 'ERROR')
    robot.apply_link_wrench('gear1', [0, 0, 0], [0, 0, 0.1])
    w.step(200)  # gear1 turns on its own, and nothing diverges
    assert robot.joint_state('j1')[0] > 0.1
    assert robot.recoveries == 0


def test_a_gearbox_that_is_its_childs_only_joint_holds_it_fixed_saying_why():
    model = sdf(f"""
<link name="base"><pose>0 0 1 0 0 0</pose>{inertial(5.0, 0.1)}</link>
<joint name="anchor" type="fixed"><parent>world</parent><child>base</child></joint>
<link name="gear"><pose>0 0 1.1 0 0 0</pose>{inertial(1.0, 0.01)}</link>
<joint name="gb" type="gearbox"><parent>base</parent><child>gear</child></joint>""", 'lone')
    w, robot = spawn(model)
    assert [m for m in logged(w, 'WARN') if "joint 'gb'" in m and 'held fixed' in m]
    w.step(100)
    assert robot.link_pose('gear')[2] == pytest.approx(1.1, abs=1e-6)
