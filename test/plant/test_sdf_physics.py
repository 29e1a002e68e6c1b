"""SDF models that move, checked against the physics they stand for: a pendulum's period, a block on
an incline (sticking below atan(mu), sliding at g (sin - mu cos) above), a <surface>'s friction (mu
along fdir1, mu2 across it), contact stiffness (m g / kp per point at rest), min_depth and max_vel, a
prismatic joint's limit, a box dropped on the ground landing flat and resting, a stack of boxes
standing, a ball's <bounce> (to e^2 h, Gazebo's smaller-of-two restitution and threshold), a joint's
<spring_stiffness> (at sqrt(k / I), and stable when stiff); SDF 1.8's capsule and ellipsoid resting at
their half height, met by rays on their surfaces, a capsule rolling at v0 / (1 + I / (m r^2));
<gravity>false (a floating box, a pendulum's period from its other mass), <kinematic> (moved by its
velocity alone), <self_collide> (an arm folding onto its own base), <allow_auto_disable>, and the
world's ODE <iters>, <sor> and <contact_surface_layer> against one Gauss-Seidel sweep's arithmetic.
Models are SDF text spawned into the plant's default world (ground plane at z = 0, 1 ms steps,
g = 9.8) or an SDF world of their own."""
import math

import numpy as np
import pytest

from tianracer_description import bullet_plant as bp

G = 9.8


def sdf(body, name='m'):
    return f'<?xml version="1.0"?><sdf version="1.7"><model name="{name}">{body}</model></sdf>'


def inertial(mass, i):
    return (f'<inertial><mass>{mass}</mass><inertia><ixx>{i}</ixx><iyy>{i}</iyy><izz>{i}</izz>'
            '<ixy>0</ixy><ixz>0</ixz><iyz>0</iyz></inertia></inertial>')


def box_link(name, size, mass, pose='0 0 0 0 0 0', mu=None):
    surface = f'<surface><friction><ode><mu>{mu}</mu><mu2>{mu}</mu2></ode></friction></surface>' if mu is not None else ''
    sx, sy, sz = size
    i = mass * (sy * sy + sz * sz) / 12
    return (f'<link name="{name}"><pose>{pose}</pose>{inertial(mass, i)}'
            f'<collision name="c"><geometry><box><size>{sx} {sy} {sz}</size></box></geometry>{surface}</collision>'
            '</link>')


def tilt(pose):
    """The tilt of a base pose (x y z qx qy qz qw) from upright, degrees."""
    return math.degrees(2 * math.acos(min(1.0, abs(pose[6]))))


def crossings(t, x):
    """Times where x crosses its mean upwards, linearly interpolated."""
    x = np.asarray(x) - np.mean(x)
    i = np.nonzero((x[:-1] < 0) & (x[1:] >= 0))[0]
    return t[i] + (t[i + 1] - t[i]) * (-x[i]) / (x[i + 1] - x[i])


def test_a_pendulum_swings_at_two_pi_root_l_over_g():
    # A point mass (inertia 1e-6) on a 1 m massless rod, hinged to the world, 0.05 rad from hanging.
    length, angle = 1.0, 0.05
    x, z = length * math.sin(angle), 2.0 - length * math.cos(angle)
    model = sdf(f"""
<link name="bob"><pose>{x} 0 {z} 0 0 0</pose>{inertial(1.0, 1e-6)}</link>
<joint name="hinge" type="revolute"><parent>world</parent><child>bob</child>
  <pose>{-x} 0 {2.0 - z} 0 0 0</pose><axis><xyz>0 1 0</xyz></axis></joint>""", 'pendulum')
    w = bp.World()
    p = w.spawn(model, 'pendulum', [0, 0, 0, 0, 0, 0])
    t, q = [], []
    for _ in range(10000):
        w.step(1)
        t.append(w.time)
        q.append(p.joint_state('hinge')[0])
    assert max(q) - min(q) == pytest.approx(2 * angle, rel=0.02)  # it swings, and keeps its amplitude
    periods = np.diff(crossings(np.array(t), q))
    expected = 2 * math.pi * math.sqrt(length / G) * (1 + angle ** 2 / 16)
    assert np.mean(periods) == pytest.approx(expected, rel=0.005), periods


def incline_world(slope_deg, mu):
    """A 6 x 2 m plank 3 m up, tilted by slope_deg about y (down towards +x; fixed: <static>), a 0.2 m
    cube resting on it."""
    slope = math.radians(slope_deg)
    w = bp.World()
    w.spawn(sdf(box_link('plank', (6, 2, 0.2), 100.0, mu=mu) + '<static>true</static>', 'plank'), 'plank',
            [0, 0, 3.0, 0, slope, 0])
    # the cube's centre 0.2 m above the plank's, along the plank's normal
    nx, nz = math.sin(slope), math.cos(slope)
    block = w.spawn(sdf(box_link('block', (0.2, 0.2, 0.2), 1.0, mu=mu), 'block'), 'block',
                    [0.2001 * nx, 0, 3.0 + 0.2001 * nz, 0, slope, 0])
    return w, block, slope


@pytest.mark.parametrize('slope_deg', [20.0, 35.0])
def test_a_block_on_an_incline_sticks_below_atan_mu_and_slides_at_g_sin_minus_mu_cos(slope_deg):
    mu = 0.5  # atan(0.5) = 26.6 deg
    w, block, slope = incline_world(slope_deg, mu)
    w.step(200)  # settles on the plank
    start = np.array(block.base_pose()[:3])
    w.step(500)
    moved = np.array(block.base_pose()[:3]) - start
    distance = float(np.linalg.norm(moved))
    if math.tan(slope) < mu:
        assert distance < 2e-3, moved
    else:
        # s = v0 t + a t^2 / 2 over the 0.5 s, v0 the speed the first 0.2 s gave it (measured on a
        # second, identical world over one step)
        w2, block2, _ = incline_world(slope_deg, mu)
        w2.step(200)
        p0 = np.array(block2.base_pose()[:3])
        w2.step(1)
        speed0 = float(np.linalg.norm(np.array(block2.base_pose()[:3]) - p0)) / 1e-3
        a = G * (math.sin(slope) - mu * math.cos(slope))
        expected = speed0 * 0.5 + a * 0.5 ** 2 / 2
        assert distance == pytest.approx(expected, rel=0.05), (distance, expected, speed0)
        assert moved[0] > 0 and moved[2] < 0  # down the slope
        assert tilt(block.base_pose()) == pytest.approx(slope_deg, abs=1.0)  # slides, does not tumble


def anisotropic_incline(slope_deg, fdir1, plank_kind, yaw=0.0):
    """The incline above with a block of <mu> 1.0 and <mu2> 0.1 (and `fdir1` in the block's frame, whose
    x runs down the slope unless `yaw` turns the link in its model, or none) on a plank of mu = mu2 = 1 (Gazebo takes the smaller of each: the
    block's). The plank a <static> model spawned (a multibody against another: Bullet's rows) or a
    static model of an SDF world (a body against the static world: the plant's own rows)."""
    slope = math.radians(slope_deg)
    plank = ('<link name="plank"><collision name="c"><geometry><box><size>6 2 0.2</size></box></geometry><surface>'
             '<friction><ode><mu>1</mu><mu2>1</mu2></ode></friction></surface></collision></link>')
    if plank_kind == 'world':
        w = bp.World.from_sdf(f'<?xml version="1.0"?><sdf version="1.7"><world name="w"><model name="plank">'
                              f'<static>true</static><pose>0 0 3 0 {slope} 0</pose>{plank}</model></world></sdf>')
    else:
        w = bp.World()
        w.spawn(sdf(plank + '<static>true</static>', 'plank'), 'plank', [0, 0, 3.0, 0, slope, 0])
    direction = f'<fdir1>{fdir1}</fdir1>' if fdir1 else ''
    # 0.3 x 0.3 x 0.1 m: sliding at mu = 1 on a 50 deg slope it stays flat (a cube would tip: friction
    # mu N at its base turns it about its lower edge once mu h / 2 reaches half its width)
    block = sdf(f'<link name="block"><pose>0 0 0 0 0 {yaw}</pose>{inertial(1.0, 0.01)}<collision name="c"><geometry><box><size>0.3 0.3 0.1'
                f'</size></box></geometry><surface><friction><ode><mu>1.0</mu><mu2>0.1</mu2>{direction}</ode></friction>'
                '</surface></collision></link>', 'block')
    nx, nz = math.sin(slope), math.cos(slope)
    return w, w.spawn(block, 'block', [0.1501 * nx, 0, 3.0 + 0.1501 * nz, 0, slope, 0]), slope


# Gazebo's ODE resists sliding along the first friction direction with mu and across it with mu2,
# each bounded by mu N (the pyramid). Down a slope that lies along fdir1 the block sticks while
# tan(slope) < mu = 1 (45 deg) and slides at g (sin - mu cos) above; along the second direction it
# slides once tan(slope) > mu2 = 0.1 (5.7 deg), at g (sin - mu2 cos). Without fdir1 the first
# direction is ODE's dPlaneSpace of the normal (Bullet's btPlaneSpace1, the same vectors): for a
# normal within 45 deg of z it lies in the y-z plane, here across the slope, so mu2 holds down it.
@pytest.mark.parametrize('plank_kind', ['model', 'world'])
@pytest.mark.parametrize('slope_deg, fdir1, mu_down', [
    (20.0, '1 0 0', None), (35.0, '1 0 0', None), (50.0, '1 0 0', 1.0),
    (20.0, '0 1 0', 0.1), (35.0, '0 1 0', 0.1), (20.0, None, 0.1)])
def test_friction_is_mu_along_fdir1_and_mu2_across_it(plank_kind, slope_deg, fdir1, mu_down):
    w, block, slope = anisotropic_incline(slope_deg, fdir1, plank_kind)
    w.step(200)
    p0, v0 = np.array(block.base_pose()[:3]), np.array(block.base_twist()[0])
    w.step(500)
    moved = np.array(block.base_pose()[:3]) - p0
    down = np.array([math.cos(slope), 0, -math.sin(slope)])
    if mu_down is None:
        assert np.linalg.norm(moved) < 1e-4, moved  # it sticks
    else:
        a = (np.array(block.base_twist()[0]) - v0) @ down / 0.5
        assert a == pytest.approx(G * (math.sin(slope) - mu_down * math.cos(slope)), rel=0.02)
        assert abs(moved[1]) < 1e-3, moved  # straight down the slope
    assert tilt(block.base_pose()) == pytest.approx(slope_deg, abs=0.5)


def test_fdir1_turns_with_its_collision():
    # The block's link yawed a quarter turn in its model: its fdir1 (x) now lies across the slope, and
    # mu2 holds it down the slope, as fdir1 "0 1 0" does unturned.
    w, block, slope = anisotropic_incline(20.0, '1 0 0', 'world', yaw=math.pi / 2)
    w.step(200)
    v0 = np.array(block.base_twist()[0])
    w.step(500)
    down = np.array([math.cos(slope), 0, -math.sin(slope)])
    a = (np.array(block.base_twist()[0]) - v0) @ down / 0.5
    assert a == pytest.approx(G * (math.sin(slope) - 0.1 * math.cos(slope)), rel=0.01)


def soft_body(shape, mass, contact):
    """A body (a 0.2 m box or a 0.1 m ball) with <surface><contact><ode>`contact`, its bottom at z = 0
    on the default world's ground."""
    surface = f'<surface><contact><ode>{contact}</ode></contact></surface>' if contact else ''
    geometry = '<box><size>0.2 0.2 0.2</size></box>' if shape == 'box' else '<sphere><radius>0.1</radius></sphere>'
    w = bp.World()
    w.echo = False
    body = w.spawn(sdf(f'<link name="l">{inertial(mass, mass * 0.004)}<collision name="c"><geometry>{geometry}'
                       f'</geometry>{surface}</collision></link>', shape), shape, [0, 0, 0.1, 0, 0, 0])
    return w, body


# ODE's contact joint is a spring-damper for a given kp and kd (erp = dt kp / (dt kp + kd),
# cfm = 1 / (dt kp + kd)), one per contact point; the ground, which says nothing, adds SDF's
# defaults in series (kp 1e12) and in sum (kd 1). At rest the points carry m g together: a ball on
# its one point sinks m g / kp, a box on its four corners m g / (4 kp), as in Gazebo.
@pytest.mark.parametrize('shape, points', [('ball', 1), ('box', 4)])
@pytest.mark.parametrize('kp, kd', [(2e4, 50.0), (2e5, 200.0), (2e4, None)])
def test_a_soft_contact_sinks_m_g_over_kp_per_point(shape, points, kp, kd):
    mass = 2.0
    damping = f'<kd>{kd}</kd>' if kd is not None else ''
    w, body = soft_body(shape, mass, f'<kp>{kp}</kp>{damping}')
    w.step(3000)
    sink = 0.1 - body.base_pose()[2]
    assert sink == pytest.approx(mass * G / (points * kp), rel=0.03)
    assert len(w.contacts()) == points


def test_a_contact_without_kp_stays_rigid():
    for shape in ('ball', 'box'):
        w, body = soft_body(shape, 2.0, '')
        w.step(3000)
        assert abs(0.1 - body.base_pose()[2]) < 1e-6, shape


def test_min_depth_is_a_depth_the_contact_does_not_push_out_of():
    # A box started 1.5 mm into the ground: pushed out without min_depth, left there with 2 mm (ODE
    # corrects depth - min_depth, nothing below it).
    for contact, depth in [('', 0.0), ('<min_depth>0.002</min_depth>', 0.0015)]:
        w = bp.World()
        w.echo = False
        box = w.spawn(sdf(box_link('l', (0.2, 0.2, 0.2), 2.0).replace(
            '</geometry>', f'</geometry><surface><contact><ode>{contact}</ode></contact></surface>')), 'box',
            [0, 0, 0.1 - 0.0015, 0, 0, 0])
        w.step(1000)
        assert 0.1 - box.base_pose()[2] == pytest.approx(depth, abs=2e-5), contact


def test_max_vel_caps_the_speed_a_contact_pushes_out_at():
    # A box started 8 mm into the ground: the plant's contact (erp 0.2) throws it out at 1.6 m/s; with
    # <max_vel> 0.01 it rises at 1 cm/s and is out in 0.8 s.
    for contact, fastest in [('', 1.0), ('<max_vel>0.01</max_vel>', 0.01)]:
        w = bp.World()
        w.echo = False
        box = w.spawn(sdf(box_link('l', (0.2, 0.2, 0.2), 2.0).replace(
            '</geometry>', f'</geometry><surface><contact><ode>{contact}</ode></contact></surface>')), 'box',
            [0, 0, 0.1 - 0.008, 0, 0, 0])
        speeds = []
        for _ in range(1000):
            w.step(1)
            speeds.append(box.base_twist()[0][2])
        if contact:
            assert max(speeds) == pytest.approx(fastest, rel=0.01)
            assert box.base_pose()[2] == pytest.approx(0.1, abs=1e-4)
        else:
            assert max(speeds) > fastest


def test_surface_values_that_mean_nothing_are_left_out_with_a_warning():
    w = bp.World()
    w.echo = False
    box = w.spawn(sdf(box_link('l', (0.2, 0.2, 0.2), 2.0).replace(
        '</geometry>', '</geometry><surface><friction><ode><mu>0.5</mu></ode></friction><contact><ode>'
        '<kp>0</kp><kd>-3</kd><min_depth>-0.5</min_depth></ode></contact></surface>')), 'box', [0, 0, 0.1, 0, 0, 0])
    said = [t for level, t in w.messages() if level == 'WARN' and "collision 'c'" in t]
    assert any('<kp> 0 is not above 0; left out' in t for t in said), said
    assert any('<kd> -3 is negative; left out' in t for t in said), said
    assert any('<min_depth> -0.5 is negative; left out' in t for t in said), said
    w.step(1000)
    assert box.base_pose()[2] == pytest.approx(0.1, abs=1e-5)  # the rigid contact, as without them


def test_a_prismatic_joint_stops_at_its_limit():
    # A 1 kg slider on a vertical rail fixed to the world, free to fall 0.3 m to its lower limit.
    model = sdf(f"""
<link name="slider"><pose>0 0 1 0 0 0</pose>{inertial(1.0, 0.01)}</link>
<joint name="rail" type="prismatic"><parent>world</parent><child>slider</child><axis><xyz>0 0 1</xyz>
  <limit><lower>-0.3</lower><upper>0.2</upper></limit></axis></joint>""", 'slider')
    w = bp.World()
    s = w.spawn(model, 'slider', [0, 0, 0, 0, 0, 0])
    lowest = 0.0
    for _ in range(1000):
        w.step(1)
        lowest = min(lowest, s.joint_state('rail')[0])
    q, qd = s.joint_state('rail')[:2]
    assert lowest > -0.3 - 5e-3  # it never went more than 5 mm past the limit
    assert q == pytest.approx(-0.3, abs=2e-3) and abs(qd) < 1e-2  # and rests there
    assert s.link_pose('slider')[2] == pytest.approx(0.7, abs=2e-3)


def test_a_dropped_box_lands_flat_and_rests():
    # From 1 m: 4.4 m/s at the ground, 4.4 mm a step at 1 ms. It used to land on one corner
    # (one contact point), tip over and bounce to 0.24 m.
    w = bp.World()
    box = w.spawn(sdf(box_link('l', (0.2, 0.2, 0.2), 2.0)), 'box', [0, 0, 1, 0, 0, 0])
    highest_after_landing, most_tilt, landed = 0.0, 0.0, False
    for _ in range(2000):
        w.step(1)
        p = box.base_pose()
        landed = landed or p[2] < 0.1005
        if landed:
            highest_after_landing = max(highest_after_landing, p[2])
        most_tilt = max(most_tilt, tilt(p))
    assert landed
    assert highest_after_landing < 0.1 + 2e-3  # no hop
    assert most_tilt < 0.5
    assert box.base_pose()[2] == pytest.approx(0.1, abs=1e-3)
    assert np.linalg.norm(box.base_twist()[0]) < 1e-3  # at rest


@pytest.mark.slow
def test_a_stack_of_ten_boxes_stands_for_a_minute():
    w = bp.World()
    boxes = [w.spawn(sdf(box_link('l', (0.2, 0.2, 0.2), 1.0)), f'box{k}', [0, 0, 0.1 + 0.2 * k + 1e-4 * k, 0, 0, 0])
             for k in range(10)]
    w.step(60000)
    for k, b in enumerate(boxes):
        p = b.base_pose()
        assert math.hypot(p[0], p[1]) < 0.02, (k, p)
        assert p[2] == pytest.approx(0.1 + 0.2 * k, abs=0.01), (k, p)
        assert tilt(p) < 2.0, (k, p)


def ball_world(ground_bounce, ball_bounce, drop):
    """A static ground model with a <plane> and the given <bounce> (restitution, threshold or None),
    and a 0.1 m ball (a robot named 'ball') with its own, its lowest point `drop` m above the ground."""
    def surface(bounce):
        if bounce is None:
            return ''
        e, threshold = bounce
        return (f'<surface><bounce><restitution_coefficient>{e}</restitution_coefficient>'
                f'<threshold>{threshold}</threshold></bounce></surface>')
    radius = 0.05
    world = f"""<?xml version="1.0"?><sdf version="1.7"><world name="w">
<model name="ground"><static>true</static><link name="link"><collision name="c">
  <geometry><plane><normal>0 0 1</normal><size>10 10</size></plane></geometry>{surface(ground_bounce)}</collision></link></model>
<model name="ball"><pose>0 0 {radius + drop} 0 0 0</pose><link name="link">{inertial(0.1, 0.4 * 0.1 * radius ** 2)}
  <collision name="c"><geometry><sphere><radius>{radius}</radius></sphere></geometry>{surface(ball_bounce)}</collision></link></model>
</world></sdf>"""
    w = bp.World.from_sdf(world)
    return w, w.robot('ball'), radius


def rebound_height(w, ball, radius, steps=900):
    """How high the ball's lowest point rises after it first lands (m)."""
    highest, landed, falling = 0.0, False, True
    for _ in range(steps):
        w.step(1)
        z = ball.base_pose()[2] - radius
        vz = ball.base_twist()[0][2]
        landed = landed or z < 2e-3
        if landed:
            falling = falling and vz < 0
            highest = max(highest, z) if not falling else highest
    assert landed
    return highest


@pytest.mark.parametrize('ball_e', [0.5, 0.8])
def test_a_ball_rebounds_to_e_squared_h_with_the_smaller_restitution_of_the_two_surfaces(ball_e):
    # Gazebo's ODE (ODEPhysics::Collide) bounces a contact at the smaller of the two restitutions,
    # above the smaller of the two thresholds. 1 m at 4.4 m/s, the ground's e 0.6.
    drop, ground_e = 1.0, 0.6
    w, ball, radius = ball_world((ground_e, 0.1), (ball_e, 0.1), drop)
    e = min(ground_e, ball_e)
    assert rebound_height(w, ball, radius) == pytest.approx(e * e * drop, rel=0.03)


def test_a_ball_does_not_bounce_below_the_threshold_nor_off_a_surface_without_bounce():
    drop = 1.0  # it lands at 4.4 m/s
    for ground, ball_bounce in [((0.6, 1e5), (0.8, 5.0)),  # the smaller threshold, 5 m/s, is not reached
                                (None, (0.8, 0.1))]:        # the ground has no <bounce>: restitution 0
        w, ball, radius = ball_world(ground, ball_bounce, drop)
        assert rebound_height(w, ball, radius) < 2e-3, (ground, ball_bounce)
    # while a threshold of the ground's below the ball's lets it bounce (the smaller of the two)
    w, ball, radius = ball_world((0.6, 0.1), (0.8, 5.0), drop)
    assert rebound_height(w, ball, radius) == pytest.approx(0.36 * drop, rel=0.03)


def torsion_pendulum(stiffness, inertia, reference):
    """A rotor on a vertical revolute joint to the world with a <spring_stiffness>, starting at q = 0
    against its spring's reference."""
    w = bp.World()
    model = sdf(f"""
<link name="rotor"><pose>0 0 1 0 0 0</pose>{inertial(1.0, inertia)}</link>
<joint name="spin" type="revolute"><parent>world</parent><child>rotor</child><axis><xyz>0 0 1</xyz>
  <limit><lower>-1e16</lower><upper>1e16</upper></limit>
  <dynamics><spring_stiffness>{stiffness}</spring_stiffness><spring_reference>{reference}</spring_reference></dynamics>
</axis></joint>""", 'rotor')
    return w, w.spawn(model, 'rotor', [0, 0, 0, 0, 0, 0])


def test_a_joint_spring_oscillates_at_root_k_over_i():
    stiffness, inertia, reference = 4.0, 0.01, 0.2  # omega 20 rad/s, period 0.314 s
    w, rotor = torsion_pendulum(stiffness, inertia, reference)
    t, q = [], []
    for _ in range(2000):
        w.step(1)
        t.append(w.time)
        q.append(rotor.joint_state('spin')[0])
    assert max(q) - min(q) == pytest.approx(2 * reference, rel=0.02)  # about the reference, undamped
    periods = np.diff(crossings(np.array(t), q))
    omega = 2 * math.pi / np.mean(periods)
    assert omega == pytest.approx(math.sqrt(stiffness / inertia), rel=0.01), periods


def test_a_stiff_joint_spring_stays_stable_and_settles_at_its_reference():
    # k dt^2 = 10 I: an explicit spring torque would multiply the swing by ~10 a step.
    stiffness, inertia, reference = 1e5, 0.01, 0.2
    w, rotor = torsion_pendulum(stiffness, inertia, reference)
    swing = 0.0
    for _ in range(500):
        w.step(1)
        q, qd = rotor.joint_state('spin')[:2]
        swing = max(swing, abs(q - reference))
    assert swing <= reference + 1e-6
    assert q == pytest.approx(reference, abs=1e-4) and abs(qd) < 1e-2


# SDF 1.8's capsule and ellipsoid.

def shape_link(name, geometry, mass, inertia, pose='0 0 0 0 0 0', extra=''):
    """A link whose collision and visual are `geometry` (SDF text), its principal moments `inertia`."""
    ixx, iyy, izz = inertia
    return (f'<link name="{name}"><pose>{pose}</pose><inertial><mass>{mass}</mass><inertia><ixx>{ixx}</ixx>'
            f'<iyy>{iyy}</iyy><izz>{izz}</izz></inertia></inertial>'
            f'<collision name="c"><geometry>{geometry}</geometry></collision>'
            f'<visual name="v"><geometry>{geometry}</geometry></visual>{extra}</link>')


CAPSULE = '<capsule><radius>0.1</radius><length>0.4</length></capsule>'
ELLIPSOID = '<ellipsoid><radii>0.3 0.2 0.1</radii></ellipsoid>'


@pytest.mark.parametrize('geometry, roll, half_height', [
    (CAPSULE, 0.0, 0.2 + 0.1),            # standing: half its cylinder plus a hemisphere
    (CAPSULE, math.pi / 2, 0.1),          # lying: its radius
    (ELLIPSOID, 0.0, 0.1),                # its smallest radius vertical, the stable way up
], ids=['capsule standing', 'capsule lying', 'ellipsoid'])
def test_a_capsule_and_an_ellipsoid_rest_at_their_half_height(geometry, roll, half_height):
    w = bp.World()
    body = w.spawn(sdf(shape_link('l', geometry, 1.0, (0.01, 0.01, 0.005))), 'shape',
                   [0, 0, half_height + 0.01, roll, 0, 0])
    w.step(1500)
    p = body.base_pose()
    assert p[2] == pytest.approx(half_height, abs=1e-3)
    assert tilt(p) == pytest.approx(math.degrees(roll), abs=0.5)
    assert np.linalg.norm(body.base_twist()[0]) < 1e-3  # at rest


def test_the_rays_of_lidars_meet_a_capsule_and_an_ellipsoid_on_their_surfaces():
    # Straight down onto each, off its centre: the capsule's hemisphere at x = 0.25 (0.05 beyond its
    # cylinder) is sqrt(r^2 - 0.05^2) above the end's centre; the ellipsoid at x = 0.2 is
    # c sqrt(1 - (x/a)^2) above its own.
    w = bp.World()
    w.spawn(sdf(shape_link('l', CAPSULE, 1.0, (0.01, 0.01, 0.005), pose='0 0 0 0 1.5707963267948966 0') +
                '<static>true</static>', 'capsule'), 'capsule', [0, 0, 1, 0, 0, 0])
    w.spawn(sdf(shape_link('l', ELLIPSOID, 1.0, (0.01, 0.01, 0.005)) + '<static>true</static>', 'ellipsoid'),
            'ellipsoid', [0, 3, 1, 0, 0, 0])
    assert w.cast_ray([0.0, 0, 2], [0, 0, -1], 5.0) == pytest.approx(1 - 0.1, abs=1e-6)
    assert w.cast_ray([0.25, 0, 2], [0, 0, -1], 5.0) == pytest.approx(1 - math.sqrt(0.1 ** 2 - 0.05 ** 2), abs=1e-6)
    assert w.cast_ray([0.2, 3, 2], [0, 0, -1], 5.0) == pytest.approx(1 - 0.1 * math.sqrt(1 - (0.2 / 0.3) ** 2), abs=1e-6)
    assert w.cast_ray([-1, 3, 1], [1, 0, 0], 5.0) == pytest.approx(1 - 0.3, abs=1e-6)


def test_a_capsule_lying_down_rolls_at_v0_over_one_plus_i_over_m_r_squared():
    # Pushed at v0 across its axis without spin, friction brings it to rolling at
    # v = v0 / (1 + I / (m r^2)) (angular momentum about the contact line is kept), then it rolls on
    # at v with omega = v / r. Its axis along y; I about it 0.5 m r^2: v = v0 / 1.5.
    m, r, v0 = 1.0, 0.1, 1.0
    axis_inertia = 0.5 * m * r * r
    w = bp.World()
    capsule = w.spawn(sdf(shape_link('l', CAPSULE, m, (0.004, 0.004, axis_inertia))), 'capsule',
                      [0, 0, r, math.pi / 2, 0, 0])
    w.step(10)
    capsule.set_link_state('l', list(capsule.link_pose('l')), [v0, 0, 0], [0, 0, 0])
    w.step(500)
    linear, angular = capsule.base_twist()
    v = v0 / (1 + axis_inertia / (m * r * r))
    assert linear[0] == pytest.approx(v, rel=0.02)
    assert angular[1] == pytest.approx(v / r, rel=0.02)  # rolling: about +y for +x
    x0 = capsule.base_pose()[0]
    w.step(1000)
    assert capsule.base_pose()[0] - x0 == pytest.approx(v * 1.0, rel=0.02)  # and keeps rolling
    assert capsule.base_pose()[2] == pytest.approx(r, abs=1e-3)


# <link><gravity> and <kinematic>.

def test_a_link_without_gravity_floats_where_it_is():
    w = bp.World()
    box = w.spawn(sdf(box_link('l', (0.2, 0.2, 0.2), 1.0).replace('</link>', '<gravity>false</gravity></link>')),
                  'floating', [0, 0, 1, 0, 0, 0])
    w.step(2000)
    assert box.base_pose()[:3] == pytest.approx([0, 0, 1], abs=1e-9)
    # and moves as a free body when pushed: 1 N on 1 kg for 0.5 s, s = a t^2 / 2 (none of it down)
    box.apply_link_wrench('l', [1, 0, 0], start=w.time, duration=0.5)
    w.step(500)
    p = box.base_pose()
    assert p[0] == pytest.approx(0.125, rel=0.01)
    assert p[2] == pytest.approx(1, abs=1e-9)


def two_mass_pendulum(weight_gravity):
    """A rod hinged to the world at z = 2 (axis y) holding two point masses fixed to it: 1 kg at
    0.5 m (the rod's link) and 2 kg at 1 m (a link of its own, fixed to the rod, with
    <gravity>weight_gravity</gravity>); 0.05 rad from hanging."""
    angle = 0.05
    s, c = math.sin(angle), math.cos(angle)
    gravity = '' if weight_gravity else '<gravity>false</gravity>'
    model = sdf(f"""
<link name="rod"><pose>{0.5 * s} 0 {2 - 0.5 * c} 0 {angle} 0</pose>{inertial(1.0, 1e-6)}</link>
<link name="weight"><pose>{1.0 * s} 0 {2 - 1.0 * c} 0 {angle} 0</pose>{inertial(2.0, 1e-6)}{gravity}</link>
<joint name="hinge" type="revolute"><parent>world</parent><child>rod</child>
  <pose>0 0 0.5 0 0 0</pose><axis><xyz>0 1 0</xyz></axis></joint>
<joint name="weld" type="fixed"><parent>rod</parent><child>weight</child></joint>""", 'pendulum')
    w = bp.World()
    p = w.spawn(model, 'pendulum', [0, 0, 0, 0, 0, 0])
    t, q = [], []
    for _ in range(15000):  # three periods and more
        w.step(1)
        t.append(w.time)
        q.append(p.joint_state('hinge')[0])
    return np.mean(np.diff(crossings(np.array(t), q)))


@pytest.mark.parametrize('weight_gravity', [True, False])
def test_a_pendulum_whose_weight_feels_no_gravity_swings_at_the_period_of_its_other_mass(weight_gravity):
    # T = 2 pi sqrt(I / (g sum m l)), I = sum m l^2 = 1 * 0.25 + 2 * 1 = 2.25 kg m^2; gravity pulls on
    # 1 * 0.5 + 2 * 1 = 2.5 kg m with the weight's gravity, 0.5 kg m without: the two links are one
    # rigid body in the plant, which feels gravity on the rod's mass alone, at the rod's place.
    inertia = 1.0 * 0.5 ** 2 + 2.0 * 1.0 ** 2
    moment = 1.0 * 0.5 + (2.0 * 1.0 if weight_gravity else 0.0)
    expected = 2 * math.pi * math.sqrt(inertia / (G * moment)) * (1 + 0.05 ** 2 / 16)
    assert two_mass_pendulum(weight_gravity) == pytest.approx(expected, rel=0.005)


def test_a_kinematic_link_moves_only_at_the_velocity_set_on_it():
    # A kinematic 1 x 1 x 0.1 m platform at z = 1: gravity does not pull it, a 5 kg box dropped on it
    # rests on it without pushing it down; set moving at 0.5 m/s along x and 0.2 rad/s about z, it
    # moves 0.5 m and turns 0.2 rad in 1 s.
    w = bp.World()
    platform = w.spawn(sdf(box_link('deck', (1, 1, 0.1), 50.0).replace('</link>', '<kinematic>true</kinematic></link>')),
                       'platform', [0, 0, 1, 0, 0, 0])
    box = w.spawn(sdf(box_link('l', (0.2, 0.2, 0.2), 5.0)), 'box', [0, 0, 1.3, 0, 0, 0])
    w.step(1500)
    assert platform.base_pose()[:3] == pytest.approx([0, 0, 1], abs=1e-9)
    assert box.base_pose()[2] == pytest.approx(1 + 0.05 + 0.1, abs=1e-3)
    box.set_link_state('l', [3, 0, 0.1, 0, 0, 0, 1])  # out of the way
    platform.set_link_state('deck', [0, 0, 1, 0, 0, 0, 1], [0.5, 0, 0], [0, 0, 0.2])
    w.step(1000)
    p = platform.base_pose()
    assert p[:3] == pytest.approx([0.5, 0, 1], abs=1e-4)  # 1000 single-precision steps
    assert 2 * math.atan2(p[5], p[6]) == pytest.approx(0.2, abs=1e-4)
    linear, angular = platform.base_twist()
    assert list(linear) == pytest.approx([0.5, 0, 0], abs=1e-9) and angular[2] == pytest.approx(0.2)


# <self_collide>.

def folding_arm(model_self_collide=None, arm_self_collide=None, base_self_collide=None):
    """A base fixed to the world: a 0.4 m block under the arm's swing; a post on a vertical hinge held
    by its limits, sunk into the base (joined to it, so never touching it); an arm hinged to the top
    of the post at z = 0.6, 0.4 m long along x, released horizontal. Returns the arm's lowest angle
    below horizontal (rad) over 1.5 s."""
    model_flag = '' if model_self_collide is None else f'<self_collide>{str(model_self_collide).lower()}</self_collide>'
    arm_flag = '' if arm_self_collide is None else f'<self_collide>{str(arm_self_collide).lower()}</self_collide>'
    base_flag = '' if base_self_collide is None else f'<self_collide>{str(base_self_collide).lower()}</self_collide>'
    model = sdf(f"""{model_flag}
<link name="base">{inertial(10.0, 1.0)}{base_flag}
  <collision name="slab"><pose>0 0 0.05 0 0 0</pose><geometry><box><size>1 1 0.1</size></box></geometry></collision>
  <collision name="block"><pose>0.35 0 0.2 0 0 0</pose><geometry><box><size>0.3 0.3 0.4</size></box></geometry></collision>
</link>
<link name="post"><pose>0 0 0.3 0 0 0</pose>{inertial(1.0, 0.01)}
  <collision name="c"><geometry><box><size>0.04 0.04 0.6</size></box></geometry></collision></link>
<link name="arm"><pose>0.2 0 0.6 0 0 0</pose>{inertial(1.0, 0.01)}{arm_flag}
  <collision name="c"><geometry><box><size>0.4 0.02 0.02</size></box></geometry></collision></link>
<joint name="anchor" type="fixed"><parent>world</parent><child>base</child></joint>
<joint name="turn" type="revolute"><parent>base</parent><child>post</child><axis><xyz>0 0 1</xyz>
  <limit><lower>-0.001</lower><upper>0.001</upper></limit></axis></joint>
<joint name="elbow" type="revolute"><parent>post</parent><child>arm</child><pose>-0.2 0 0 0 0 0</pose>
  <axis><xyz>0 1 0</xyz></axis></joint>""", 'folding')
    w = bp.World()
    robot = w.spawn(model, 'folding', [0, 0, 0, 0, 0, 0])
    lowest = 0.0
    for _ in range(1500):
        w.step(1)
        lowest = max(lowest, robot.joint_state('elbow')[0])  # +y turns +x down
    return lowest


def test_an_arm_folding_onto_its_own_base_stops_on_it_with_self_collide_and_passes_through_without():
    # With self_collide the arm's lower face rests on the block's top (z = 0.4) where its far end
    # reaches it: 0.6 - 0.4 sin(a) - 0.01 cos(a) = 0.4.
    rest = next(a for a in np.linspace(0, 1, 100001) if 0.6 - 0.4 * math.sin(a) - 0.01 * math.cos(a) <= 0.4)
    # Two links collide where either self-collides (SDF's rule, ODE's spaces): the model's flag is
    # every link's default, a link's own replaces it.
    assert folding_arm(model_self_collide=True) == pytest.approx(rest, abs=0.02)
    assert folding_arm(arm_self_collide=True) == pytest.approx(rest, abs=0.02)
    assert folding_arm(base_self_collide=True) == pytest.approx(rest, abs=0.02)
    assert folding_arm(model_self_collide=True, arm_self_collide=False) == pytest.approx(rest, abs=0.02)
    assert folding_arm() > math.pi / 2 - 0.05  # SDF's default: it swings through
    assert folding_arm(model_self_collide=True, arm_self_collide=False, base_self_collide=False) > math.pi / 2 - 0.05


# <allow_auto_disable> and <physics><ode>.

def test_a_model_that_may_not_auto_disable_never_sleeps():
    w = bp.World()
    sleeper = w.spawn(sdf(box_link('l', (0.2, 0.2, 0.2), 1.0)), 'sleeper', [0, 0, 0.1, 0, 0, 0])
    awake = w.spawn(sdf(box_link('l', (0.2, 0.2, 0.2), 1.0) + '<allow_auto_disable>false</allow_auto_disable>'),
                    'awake', [1, 0, 0.1, 0, 0, 0])
    w.step(3000)
    assert sleeper.asleep and not awake.asleep


def physics_world(ode, bodies, gravity='0 0 0'):
    return bp.World.from_sdf(f"""<?xml version="1.0"?><sdf version="1.6"><world name="w">
<gravity>{gravity}</gravity>
<physics type="ode"><max_step_size>0.001</max_step_size><ode>{ode}</ode></physics>
{bodies}</world></sdf>""")


def balls(count):
    """`count` 0.1 m balls of 1 kg in a row along x at z = 1, touching."""
    return ''.join(f'<model name="b{k}"><pose>{0.2 * k} 0 1 0 0 0</pose><link name="l">{inertial(1.0, 0.004)}'
                   '<collision name="c"><geometry><sphere><radius>0.1</radius></sphere></geometry></collision>'
                   '</link></model>' for k in range(count))


def after_one_step_of_a_hit(w, count, v=1.0):
    """The balls' x velocities one step after the first, moving at v, meets the others at rest."""
    w.robot('b0').set_link_state('l', [0, 0, 1, 0, 0, 0, 1], [v, 0, 0], [0, 0, 0])
    w.step(1)
    return [w.robot(f'b{k}').base_twist()[0][0] for k in range(count)]


def test_the_solvers_iters_are_odes_sweeps_over_the_contacts():
    # A ball at 1 m/s meets two resting in a row, no bounce: the exact (many-sweep) solve moves all
    # three at 1/3 m/s; one Gauss-Seidel sweep shares the first pair's speed (1/2 each), then the
    # second ball's with the third, and leaves the first ball at 1/2.
    w = physics_world('<solver><iters>1</iters></solver>', balls(3))
    assert w.solver_iterations == 1
    assert after_one_step_of_a_hit(w, 3)[0] == pytest.approx(0.5, abs=0.01)
    w = physics_world('<solver><iters>200</iters></solver>', balls(3))
    assert w.solver_iterations == 200
    assert after_one_step_of_a_hit(w, 3) == pytest.approx([1 / 3] * 3, abs=0.01)
    assert physics_world('', balls(1)).solver_iterations == 10  # the plant's own without <iters>


@pytest.mark.parametrize('sor', [1.0, 0.5, 1.3])
def test_the_solvers_sor_over_relaxes_each_contact_row(sor):
    # One sweep over one contact between equal balls: the row takes sor times the impulse that stops
    # their approach, m v / 2: the first keeps v (1 - sor / 2), the second gets v sor / 2.
    w = physics_world(f'<solver><iters>1</iters><sor>{sor}</sor></solver>', balls(2))
    assert after_one_step_of_a_hit(w, 2) == pytest.approx([1 - sor / 2, sor / 2], abs=0.01)


@pytest.mark.parametrize('layer', [0.0, 0.005])
def test_contacts_leave_the_contact_surface_layer_of_depth(layer):
    # ODE corrects a contact's depth beyond the layer only: a box rests `layer` deep in the ground.
    box = '<model name="box"><pose>0 0 0.1 0 0 0</pose>' + box_link('l', (0.2, 0.2, 0.2), 1.0) + '</model>'
    w = physics_world(f'<constraints><contact_surface_layer>{layer}</contact_surface_layer></constraints>',
                      '<include><uri>model://ground_plane</uri></include>' + box, gravity='0 0 -9.8')
    w.step(2000)
    assert w.robot('box').base_pose()[2] == pytest.approx(0.1 - layer, abs=3e-4)


def test_erp_and_cfm_are_said_once_as_not_applied_and_the_magnetic_field_is_read():
    w = bp.World.from_sdf("""<?xml version="1.0"?><sdf version="1.6"><world name="w">
<magnetic_field>1e-5 2e-5 -4e-5</magnetic_field>
<physics type="ode"><ode><constraints><erp>0.2</erp><cfm>0.001</cfm></constraints></ode></physics>
</world></sdf>""")
    said = [text for level, text in w.messages() if 'not applied' in text]
    assert len(said) == 1 and '<erp>' in said[0] and '<cfm>' in said[0], said
    assert w.magnetic_field == pytest.approx([1e-5, 2e-5, -4e-5])
    assert bp.World().magnetic_field == pytest.approx([5.5645e-6, 22.8758e-6, -42.3884e-6])  # SDF's default
