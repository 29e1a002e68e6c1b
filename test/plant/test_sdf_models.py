"""SDF models that move (src/plant/description/sdf_model.cpp), held to what sdformat 9 and Gazebo 11 do
with them: the model frame and link poses, joint axes per SDF version (1.4: the model frame; 1.5 and
1.6: <use_parent_model_frame>; 1.7: <xyz expressed_in>), a joint frame apart from its child link, 1.7
<pose relative_to> and <frame attached_to>, nested and included models scoped as Gazebo scopes them,
<static> models as scenery, limits, SDF's defaults (1 kg, unit inertia), Gazebo's collision names;
SDF 1.8's capsule and ellipsoid as scenery, in the viewer's scene and in a depth camera's image; and
bad models refused one by one, naming model, element and value, while the world keeps the others
(bad solver settings and magnetic fields refuse the world). Fixtures are inline but for the model directory test/fixtures/sdf_models/swing_arm."""
import math
import os

import numpy as np
import pytest

from plant_helpers import logged
from suite_paths import FIXTURES
from tianracer_description import bullet_plant as bp

SDF_MODELS = os.path.join(FIXTURES, 'sdf_models')


# Poses: (position, 3x3 rotation), SDF's roll-pitch-yaw (fixed axes x, y, z).

def rpy_matrix(roll, pitch, yaw):
    cr, sr, cp, sp, cy, sy = (math.cos(roll), math.sin(roll), math.cos(pitch), math.sin(pitch), math.cos(yaw),
                              math.sin(yaw))
    return np.array([[cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr],
                     [sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr],
                     [-sp, cp * sr, cp * cr]])


def axis_angle(axis, angle):
    x, y, z = np.asarray(axis, float) / np.linalg.norm(axis)
    k = np.array([[0, -z, y], [z, 0, -x], [-y, x, 0]])
    return np.eye(3) + math.sin(angle) * k + (1 - math.cos(angle)) * k @ k


def pose(x=0, y=0, z=0, roll=0, pitch=0, yaw=0):
    return np.array([x, y, z], float), rpy_matrix(roll, pitch, yaw)


def compose(a, b):
    return a[0] + a[1] @ b[0], a[1] @ b[1]


def from_reported(p):
    """A pose as the plant reports it (x y z qx qy qz qw)."""
    x, y, z, qx, qy, qz, qw = p
    return np.array([x, y, z]), np.array([
        [1 - 2 * (qy * qy + qz * qz), 2 * (qx * qy - qz * qw), 2 * (qx * qz + qy * qw)],
        [2 * (qx * qy + qz * qw), 1 - 2 * (qx * qx + qz * qz), 2 * (qy * qz - qx * qw)],
        [2 * (qx * qz - qy * qw), 2 * (qy * qz + qx * qw), 1 - 2 * (qx * qx + qy * qy)]])


def assert_pose(reported, expected, tol=1e-6):
    position, rotation = from_reported(reported)
    assert np.allclose(position, expected[0], atol=tol), (position, expected[0])
    assert np.allclose(rotation, expected[1], atol=tol), (rotation, expected[1])


def text(p):
    return ' '.join('%.17g' % v for v in p)


# SDF text.

def link(name, pose_text='', size='0.1 0.1 0.1', inertial=True, collision='collision', extra=''):
    pose_element = f'<pose>{pose_text}</pose>' if pose_text and not pose_text.startswith('<') else pose_text
    inertial_element = ('<inertial><mass>1</mass><inertia><ixx>0.01</ixx><iyy>0.01</iyy><izz>0.01</izz></inertia>'
                        '</inertial>') if inertial is True else (inertial or '')
    return f"""<link name="{name}">{pose_element}{inertial_element}
  <collision name="{collision}"><geometry><box><size>{size}</size></box></geometry></collision>{extra}</link>"""


def joint(name, parent, child, type='revolute', axis='<axis><xyz>0 0 1</xyz></axis>', pose_text=''):
    pose_element = f'<pose>{pose_text}</pose>' if pose_text and not pose_text.startswith('<') else pose_text
    return f"""<joint name="{name}" type="{type}"><parent>{parent}</parent><child>{child}</child>{pose_element}
  {axis}</joint>"""


def model(name, body, version='1.6', model_pose='0 0 0 0 0 0', static=False):
    return f"""<?xml version="1.0"?>
<sdf version="{version}"><model name="{name}"><static>{str(static).lower()}</static><pose>{model_pose}</pose>
{body}
</model></sdf>"""


def world(*models, version='1.6'):
    """A world holding the <model>s of model() texts (their <sdf> wrappers dropped)."""
    inner = '\n'.join(m.split('?>', 1)[-1].strip().split('>', 1)[1].rsplit('</sdf>', 1)[0] for m in models)
    return f"""<?xml version="1.0"?>
<sdf version="{version}"><world name="test">
  <include><uri>model://ground_plane</uri></include>
  <physics type="ode"><max_step_size>0.001</max_step_size></physics>
{inner}
</world></sdf>"""


def load(world_text):
    w = bp.World.from_sdf(world_text)
    w.echo = False
    return w


def spawn(sdf, name='m', at=(0, 0, 0, 0, 0, 0), joints=None):
    w = bp.World()
    w.echo = False
    robot = w.spawn(sdf, name, list(at), joints=joints or {})
    return w, robot


# The model frame and link poses.

def test_the_model_pose_is_the_model_frame_and_a_link_pose_is_relative_to_it():
    model_pose = pose(1, 2, 0.5, 0, 0, 0.3)
    body_pose = pose(0.2, 0, 0.1, 0.4, 0, 0.5)
    w = load(world(model('lifted', link('body', text((0.2, 0, 0.1, 0.4, 0, 0.5)))
                         + link('tail', '-0.3 0 0.1 0 0 0')
                         + joint('tail_joint', 'body', 'tail', type='fixed', axis=''),
                         model_pose='1 2 0.5 0 0 0.3')))
    robot = w.robot('lifted')
    assert_pose(robot.base_pose(), model_pose)
    assert_pose(robot.link_pose('body'), compose(model_pose, body_pose))
    assert_pose(robot.link_pose('tail'), compose(model_pose, pose(-0.3, 0, 0.1)))


def test_spawn_puts_the_model_frame_at_the_spawn_pose():
    at = (0.5, -1, 2, 0.1, 0.2, -0.4)
    w, robot = spawn(model('m', link('body', '0 0 0.3 0 0.5 0')), at=at)
    assert_pose(robot.base_pose(), pose(*at))
    assert_pose(robot.link_pose('body'), compose(pose(*at), pose(0, 0, 0.3, 0, 0.5, 0)))


# Joint axes per SDF version. The arm is turned (roll 90 degrees) so that its frame's z is the model
# frame's -y: an axis "0 0 1" in the joint frame and one in the model frame differ. The model is spawned
# turned too, so that the model frame differs from the world's.

AT = (0.3, -0.2, 1.0, 0.3, 0.0, 0.7)
ARM = (0.0, 0.0, 0.5, math.pi / 2, 0.0, 0.0)
Q = 0.6


def arm_model(version, axis):
    return model('m', link('base') + link('arm', text(ARM), size='0.3 0.05 0.05')
                 + joint('j', 'base', 'arm', axis=axis), version=version)


def assert_arm_turned_about(robot, axis_in_model, pivot_in_model=None, q=Q):
    at = pose(*AT)
    arm0 = compose(at, pose(*ARM))
    axis_world = at[1] @ np.asarray(axis_in_model, float)
    pivot = arm0[0] if pivot_in_model is None else compose(at, (np.asarray(pivot_in_model, float), np.eye(3)))[0]
    turn = axis_angle(axis_world, q)
    expected = (pivot + turn @ (arm0[0] - pivot), turn @ arm0[1])
    assert_pose(robot.link_pose('arm'), expected)
    assert robot.joint_state('j')[0] == pytest.approx(q)


MODEL_Z = (0, 0, 1)
ARM_Z_IN_MODEL = tuple(rpy_matrix(*ARM[3:]) @ np.array([0, 0, 1.0]))  # (0, -1, 0)


@pytest.mark.parametrize('version, axis, in_model', [
    ('1.4', '<axis><xyz>0 0 1</xyz></axis>', MODEL_Z),
    ('1.5', '<axis><xyz>0 0 1</xyz></axis>', ARM_Z_IN_MODEL),
    ('1.5', '<axis><xyz>0 0 1</xyz><use_parent_model_frame>true</use_parent_model_frame></axis>', MODEL_Z),
    ('1.6', '<axis><xyz>0 0 1</xyz><use_parent_model_frame>false</use_parent_model_frame></axis>', ARM_Z_IN_MODEL),
    ('1.6', '<axis><xyz>0 0 1</xyz><use_parent_model_frame>1</use_parent_model_frame></axis>', MODEL_Z),
    ('1.7', '<axis><xyz>0 0 1</xyz></axis>', ARM_Z_IN_MODEL),
    ('1.7', '<axis><xyz expressed_in="__model__">0 0 1</xyz></axis>', MODEL_Z),
    ('1.7', '<axis><xyz expressed_in="arm">0 0 1</xyz></axis>', ARM_Z_IN_MODEL),
])
def test_joint_axis_is_read_in_the_frame_its_sdf_version_says(version, axis, in_model):
    w, robot = spawn(arm_model(version, axis), at=AT, joints={'j': Q})
    assert_arm_turned_about(robot, in_model)


def test_a_17_axis_expressed_in_another_link_turns_with_that_link():
    base_turned = link('base', '0 0 0 0 0 1.5707963267948966')
    sdf = model('m', base_turned + link('arm', text(ARM), size='0.3 0.05 0.05')
                + joint('j', 'base', 'arm', axis='<axis><xyz expressed_in="base">1 0 0</xyz></axis>'), version='1.7')
    w, robot = spawn(sdf, at=AT, joints={'j': Q})
    assert_arm_turned_about(robot, (0, 1, 0))


def test_a_joint_pose_apart_from_its_child_link_is_where_the_child_turns_about():
    # The joint 0.4 m along the arm's own x (its pose is in the child link's frame), axis the arm's z.
    sdf = model('m', link('base') + link('arm', text(ARM), size='0.8 0.05 0.05')
                + joint('j', 'base', 'arm', pose_text='0.4 0 0 0 0 0'))
    w, robot = spawn(sdf, at=AT, joints={'j': Q})
    pivot = compose(pose(*ARM), pose(0.4, 0, 0))[0]
    assert_arm_turned_about(robot, ARM_Z_IN_MODEL, pivot)


def test_a_pendulum_on_a_joint_apart_from_its_link_swings_about_the_joint():
    # Fixed to the world: the bob hangs 0.5 m below its joint (pose 0 0 0.5 in the bob's frame).
    sdf = model('pendulum', link('post', '0 0 2 0 0 0')
                + joint('anchor', 'world', 'post', type='fixed', axis='')
                + link('bob', '0 0 1.5 0 0 0', size='0.1 0.1 0.1')
                + joint('swing', 'post', 'bob', pose_text='0 0 0.5 0 0 0', axis='<axis><xyz>1 0 0</xyz></axis>'))
    w, robot = spawn(sdf, joints={'swing': 0.8})
    pivot = np.array([0, 0, 2.0])
    start = from_reported(robot.link_pose('bob'))[0]
    assert np.linalg.norm(start - pivot) == pytest.approx(0.5, abs=1e-6)
    heights = []
    for _ in range(40):
        w.step(25)
        bob = from_reported(robot.link_pose('bob'))[0]
        assert np.linalg.norm(bob - pivot) == pytest.approx(0.5, abs=5e-3)  # it turns about the joint
        assert abs(bob[0]) < 1e-3  # in the plane across the axis
        heights.append(bob[2])
    assert min(heights) < start[2] - 0.1  # it swings down
    assert robot.joint_names == ['swing']


# SDF 1.7 frames.

def test_17_pose_relative_to_a_link_and_a_frame_attached_to_a_link():
    body = (link('a', '1 0 0 0 0 1.5707963267948966')
            + link('b', '<pose relative_to="a">0.5 0 0 0 0 0</pose>')
            + '<frame name="f" attached_to="a"><pose>0 0 1 0 0 0</pose></frame>'
            + link('c', '<pose relative_to="f">0.2 0 0 0 0 0</pose>')
            + joint('ab', 'a', 'b', type='fixed', axis='') + joint('ac', 'a', 'c', type='fixed', axis=''))
    w, robot = spawn(model('m', body, version='1.7'))
    a = pose(1, 0, 0, 0, 0, math.pi / 2)
    assert_pose(robot.link_pose('b'), compose(a, pose(0.5)))
    assert_pose(robot.link_pose('c'), compose(a, pose(0.2, 0, 1)))


def test_17_joint_pose_relative_to_a_frame():
    body = (link('base') + link('arm', text(ARM), size='0.8 0.05 0.05')
            + '<frame name="hinge_point"><pose>0 0.3 0.5 0 0 0</pose></frame>'
            + joint('j', 'base', 'arm', pose_text='<pose relative_to="hinge_point">0 0 0 0 0 0</pose>',
                    axis='<axis><xyz expressed_in="__model__">1 0 0</xyz></axis>'))
    w, robot = spawn(model('m', body, version='1.7'), at=AT, joints={'j': Q})
    assert_arm_turned_about(robot, (1, 0, 0), (0, 0.3, 0.5))


def test_17_pose_relative_to_a_frame_the_model_lacks_is_refused_naming_it():
    with pytest.raises(bp.DescriptionError, match=r"(?s)'m'.*relative_to.*nowhere"):
        spawn(model('m', link('a', '<pose relative_to="nowhere">0 0 0 0 0 0</pose>'), version='1.7'))


# Nested and included models.

NESTED = model('outer', link('base', '0 0 0.05 0 0 0', size='0.4 0.4 0.1') + """
<model name="inner"><pose>1 0 0.5 0 0 0</pose>""" + link('l1') + link('l2', '0 0 0.3 0 0 0', collision='skin')
               + joint('j', 'l1', 'l2', axis='<axis><xyz>1 0 0</xyz></axis>') + """</model>"""
               + joint('to_inner', 'base', 'inner::l1', axis='<axis><xyz>0 1 0</xyz></axis>',
                       pose_text='-1 0 0 0 0 0'))


def test_nested_models_are_scoped_as_gazebo_scopes_them():
    w, robot = spawn(NESTED, 'outer', at=(0, 0, 1, 0, 0, 0))
    assert sorted(robot.joint_names) == ['inner::j', 'to_inner']
    assert_pose(robot.link_pose('inner::l2'), pose(1, 0, 1.8))
    assert_pose(robot.link_pose('inner::l1'), pose(1, 0, 1.5))


def test_a_joint_between_an_outer_and_a_nested_link_turns_the_nested_link_about_it():
    w, robot = spawn(NESTED, 'outer', at=(0, 0, 1, 0, 0, 0), joints={'to_inner': 0.5})
    # to_inner's frame is 1 m back from inner::l1 (at the outer origin + 0.5 up); it turns about y.
    pivot = np.array([0, 0, 1.5])
    turn = axis_angle((0, 1, 0), 0.5)
    assert_pose(robot.link_pose('inner::l1'), (pivot + turn @ np.array([1.0, 0, 0]), turn))


def test_contacts_name_nested_collisions_model_link_collision():
    w = load(world(NESTED))
    w.step(1500)
    names = {name for c in w.contacts() for name in (c['collision1'], c['collision2'])}
    assert 'outer::base::collision' in names, names
    assert 'ground_plane::link::collision' in names, names


def test_contacts_name_a_models_collision_model_link_collision():
    w = load(world(model('dropper', link('body', '0 0 0.3 0 0 0', collision='shell'))))
    w.step(800)
    pairs = {frozenset((c['collision1'], c['collision2'])) for c in w.contacts()}
    assert frozenset(('dropper::body::shell', 'ground_plane::link::collision')) in pairs, pairs


@pytest.fixture
def swing_arm_path(monkeypatch):
    monkeypatch.setenv('GAZEBO_MODEL_PATH', SDF_MODELS)


def test_an_included_model_dir_in_a_world_moves_under_the_includes_name_and_pose(swing_arm_path):
    w = load(world().replace('</world>', """<include><uri>model://swing_arm</uri><name>left_arm</name>
      <pose>2 0 0.1 0 0 1.5707963267948966</pose></include></world>"""))
    assert 'left_arm' in w.robots, logged(w, 'ERROR')
    robot = w.robot('left_arm')
    assert robot.joint_names == ['hinge']
    at = pose(2, 0, 0.1, 0, 0, math.pi / 2)
    assert_pose(robot.base_pose(), at)
    assert_pose(robot.link_pose('arm'), compose(at, pose(0.25, 0, 0.2)))
    w.step(500)
    assert -1.05 <= robot.joint_state('hinge')[0] <= 1.05  # the arm falls onto its limit


def test_an_included_model_dir_inside_a_model_is_scoped_by_the_includes_name(swing_arm_path):
    sdf = model('cart', link('deck', size='1 0.5 0.1') + """<include><uri>model://swing_arm</uri><name>crane</name>
      <pose>0.3 0 0.05 0 0 0</pose></include>""" + joint('mount', 'deck', 'crane::base', type='fixed', axis=''))
    w, robot = spawn(sdf, 'cart', at=(0, 0, 1, 0, 0, 0))
    assert robot.joint_names == ['crane::hinge']
    assert_pose(robot.link_pose('crane::arm'), pose(0.55, 0, 1.25))


def test_a_static_model_stays_scenery():
    w = load(world(model('shelf', link('board', '0 0 0.5 0 0 0', size='1 0.3 0.02'), static=True),
                   model('box', link('body', '0 0 0.3 0 0 0'))))
    assert w.robots == ['box']
    names = [c['name'] for c in w.static_collisions()]
    assert 'shelf::board::collision' in names


# Limits and SDF's defaults.

def pendulum(axis_extra, inertial=True):
    """A 0.5 m arm on a hinge about y at 1 m, held horizontal (+x) at the start."""
    return model('p', link('post', '0 0 1 0 0 0') + joint('anchor', 'world', 'post', type='fixed', axis='')
                 + link('arm', '0.25 0 1 0 0 0', size='0.5 0.05 0.05', inertial=inertial)
                 + joint('hinge', 'post', 'arm', pose_text='-0.25 0 0 0 0 0',
                         axis=f'<axis><xyz>0 1 0</xyz>{axis_extra}</axis>'))


def swing(sdf, seconds=1.5, joints=None):
    w, robot = spawn(sdf, 'p', joints=joints)
    positions = []
    for _ in range(int(seconds * 100)):
        w.step(10)
        positions.append(robot.joint_state('hinge')[0])
    return positions


def test_a_revolute_with_limits_stops_at_them():
    positions = swing(pendulum('<limit><lower>-0.3</lower><upper>0.3</upper></limit>'))
    assert max(positions) == pytest.approx(0.3, abs=0.05)
    assert min(positions) >= -0.35


def test_a_revolute_without_limits_turns_freely():
    for extra in ('', '<limit><effort>10</effort></limit>'):
        positions = swing(pendulum(extra))
        assert max(positions) > 2.5, extra  # from horizontal through the bottom and up the other side


def test_a_link_without_inertial_has_sdfs_1_kg_and_unit_inertia():
    # A compound pendulum about a hinge 0.25 m from the link's origin (its centre of mass): small
    # swings' period 2 pi sqrt((I + m d^2) / (m g d)), 4.2 s for SDF's defaults (m 1, I 1).
    positions = swing(pendulum('', inertial=None), seconds=3, joints={'hinge': 1.5707963267948966 - 0.05})
    times = [i * 0.01 for i in range(len(positions))]
    crossing = next(t for t, q, q_next in zip(times, positions, positions[1:])
                    if q < math.pi / 2 <= q_next or q > math.pi / 2 >= q_next)
    expected_quarter = 2 * math.pi * math.sqrt((1 + 0.25 ** 2) / (9.8 * 0.25)) / 4
    assert crossing == pytest.approx(expected_quarter, rel=0.05)


def test_a_link_without_inertial_weighs_1_kg_on_the_ground():
    w = load(world(model('light', link('body', '0 0 0.05 0 0 0', inertial=None)),
                   model('heavy', link('body', '2 0 0.05 0 0 0',
                                       inertial='<inertial><mass>3</mass><inertia><ixx>1</ixx><iyy>1</iyy><izz>1</izz>'
                                                '</inertia></inertial>'))))
    w.step(1000)

    def weight(model_name):
        total = 0.0
        for c in w.contacts():
            if c['collision1'].startswith(model_name + '::'):
                total += c['force'][2]
            elif c['collision2'].startswith(model_name + '::'):
                total -= c['force'][2]
        return total

    assert weight('light') == pytest.approx(9.8, rel=0.05)
    assert weight('heavy') == pytest.approx(3 * 9.8, rel=0.05)


# Bad models: one DescriptionError naming model, element and value; the world keeps the others.

BAD_INERTIAL = '<inertial><mass>{}</mass><inertia><ixx>1</ixx><iyy>1</iyy><izz>1</izz></inertia></inertial>'
BAD = {
    'zero mass': (link('body', inertial=BAD_INERTIAL.format('0')), r"link 'body'.*<mass> 0"),
    'negative mass': (link('body', inertial=BAD_INERTIAL.format('-2')), r"link 'body'.*<mass> -2"),
    'nan mass': (link('body', inertial=BAD_INERTIAL.format('nan')), r"link 'body'.*<mass>.*nan"),
    'inertia not positive definite': (
        link('body', inertial='<inertial><mass>1</mass><inertia><ixx>1</ixx><iyy>1</iyy><izz>1</izz><ixy>2</ixy>'
                              '</inertia></inertial>'), r"link 'body'.*<inertia>.*ixy 2.*not positive definite"),
    'inertia against the triangle inequality': (  # as sdformat's MassMatrix3::IsValid
        link('body', inertial='<inertial><mass>1</mass><inertia><ixx>1</ixx><iyy>1</iyy><izz>5</izz></inertia>'
                              '</inertial>'), r"link 'body'.*<inertia>.*izz 5.*not a body's inertia"),
    'limits the wrong way round': (link('body') + link('arm') + joint(
        'j', 'body', 'arm', axis='<axis><xyz>1 0 0</xyz><limit><lower>1</lower><upper>-1</upper></limit></axis>'),
        r"joint 'j' <axis><limit>: lower 1 and upper -1"),
    'joint naming a missing link': (link('body') + joint('j', 'body', 'ghost'), r"joint 'j'.*<child> 'ghost'"),
    'zero axis': (link('body') + link('arm') + joint('j', 'body', 'arm', axis='<axis><xyz>0 0 0</xyz></axis>'),
                  r"joint 'j'.*<axis><xyz> 0 0 0"),
    'unknown joint type': (link('body') + link('arm') + joint('j', 'body', 'arm', type='hinge'),
                           r"joint 'j'.*type 'hinge'"),
    'duplicate link names': (link('body') + link('body'), r"link 'body' is given twice"),
    'capsule of negative radius': (
        link('body', extra='<collision name="cap"><geometry><capsule><radius>-0.1</radius><length>0.2</length>'
                           '</capsule></geometry></collision>'), r"link 'body' collision 'cap'.*<capsule> radius -0.1"),
    'capsule of nan length': (
        link('body', extra='<collision name="cap"><geometry><capsule><radius>0.1</radius><length>nan</length>'
                           '</capsule></geometry></collision>'), r"link 'body' collision 'cap'.*<capsule><length>.*'nan'"),
    'ellipsoid with a nan radius': (
        link('body', extra='<visual name="egg"><geometry><ellipsoid><radii>0.1 nan 0.1</radii></ellipsoid></geometry>'
                           '</visual>'), r"link 'body' visual 'egg'.*<radii> '0.1 nan 0.1'"),
    'ellipsoid with a zero radius': (
        link('body', extra='<collision name="egg"><geometry><ellipsoid><radii>0.1 0.1 0</radii></ellipsoid>'
                           '</geometry></collision>'), r"link 'body' collision 'egg'.*<ellipsoid><radii> 0.1 0.1 0"),
    'ellipsoid with two radii': (
        link('body', extra='<collision name="egg"><geometry><ellipsoid><radii>0.1 0.1</radii></ellipsoid>'
                           '</geometry></collision>'), r"link 'body' collision 'egg'.*<radii> '0.1 0.1'"),
    'gravity that is no boolean': (link('body', extra='<gravity>maybe</gravity>'),
                                   r"link 'body'.*<gravity> 'maybe'.*Invalid boolean"),
    'kinematic that is no boolean': (link('body', extra='<kinematic>2</kinematic>'),
                                     r"link 'body'.*<kinematic> '2'.*Invalid boolean"),
    'self_collide that is no boolean': ('<self_collide>yes</self_collide>' + link('body'),
                                        r"<self_collide> 'yes'.*Invalid boolean"),
    'allow_auto_disable that is no boolean': ('<allow_auto_disable>nan</allow_auto_disable>' + link('body'),
                                              r"<allow_auto_disable> 'nan'.*Invalid boolean"),
    'four-bar loop': (link('ground') + link('crank') + link('coupler') + link('rocker')
                      + joint('j1', 'ground', 'crank') + joint('j2', 'crank', 'coupler')
                      + joint('j3', 'ground', 'rocker') + joint('j4', 'rocker', 'coupler'),
                      r"joint 'j4' closes a kinematic loop.*'coupler'.*'j2'"),
    'a loop of two links beside a free one': (link('free') + link('a') + link('b') + joint('j1', 'a', 'b')
                                              + joint('j2', 'b', 'a'), r"joints above link '[ab]' close a loop"),
}


@pytest.mark.parametrize('case', sorted(BAD))
def test_a_bad_model_is_refused_naming_model_element_and_value(case):
    body, expected = BAD[case]
    with pytest.raises(bp.DescriptionError, match='(?s)' + expected) as refused:
        spawn(model('bad', body))
    assert "'bad'" in str(refused.value)


@pytest.mark.parametrize('case', sorted(BAD))
def test_a_world_keeps_its_good_models_when_one_is_bad(case):
    body, expected = BAD[case]
    w = load(world(model('bad', body), model('good', link('body', '0 0 0.5 0 0 0'))))
    assert w.robots == ['good']
    errors = logged(w, 'ERROR')
    assert any("'bad'" in e and __import__('re').search('(?s)' + expected, e) for e in errors), errors


def test_duplicate_model_names_in_a_world_keep_the_first():
    w = load(world(model('twin', link('first', '0 0 0.5 0 0 0')), model('twin', link('second', '1 0 0.5 0 0 0'))))
    assert w.robots == ['twin']
    assert w.robot('twin').link_pose('first') is not None
    errors = logged(w, 'ERROR')
    assert any("'twin'" in e and 'already' in e for e in errors), errors


def test_a_mesh_not_found_is_left_out_with_a_warning():
    mesh = '<collision name="hull"><geometry><mesh><uri>model://no_such_model/hull.stl</uri></mesh></geometry></collision>'
    # (spawned: what World.from_sdf's models log while the world is made reaches stderr, not messages())
    w, robot = spawn(model('boat', link('body', '0 0 0.5 0 0 0', extra=mesh)), 'boat')
    assert w.robots == ['boat']
    warnings = logged(w, 'WARN')
    assert any("boat" in m and "hull" in m and 'no_such_model' in m for m in warnings), warnings


# Two-axis joints: Gazebo reports a universal (or revolute2) joint as one joint of two angles; the
# plant's joint_names show it as two revolutes, '<joint>' about <axis> (carried by the parent) and
# '<joint>::axis2' about <axis2> (carried by the first).

@pytest.mark.parametrize('kind', ['universal', 'revolute2'])
def test_a_two_axis_joint_is_two_revolutes_the_second_turned_by_the_first(kind):
    sdf = model('m', link('base') + link('cross', '0 0 0.5 0 0 0')
                + joint('u', 'base', 'cross', type=kind,
                        axis='<axis><xyz>1 0 0</xyz></axis><axis2><xyz>0 1 0</xyz></axis2>'))
    w, robot = spawn(sdf, joints={'u': 0.4, 'u::axis2': -0.3})
    assert sorted(robot.joint_names) == ['u', 'u::axis2']
    assert robot.joint_state('u')[0] == pytest.approx(0.4)
    assert robot.joint_state('u::axis2')[0] == pytest.approx(-0.3)
    turn = axis_angle((1, 0, 0), 0.4) @ axis_angle((0, 1, 0), -0.3)
    assert_pose(robot.link_pose('cross'), (np.array([0, 0, 0.5]), turn))
    assert [m for m in logged(w, 'WARN') if "'u::axis2'" in m]  # says how it is simulated
    assert 'u::__axis2_frame__' not in robot.joint_names


def test_a_universal_joints_second_axis_keeps_its_limits():
    # A pendulum hanging from a universal joint, pushed sideways by gravity about both axes.
    sdf = model('p', link('post', '0 0 1 0 0 0') + joint('anchor', 'world', 'post', type='fixed', axis='')
                + link('bob', '0.3 0.3 1 0 0 0')
                + joint('u', 'post', 'bob', type='universal', pose_text='-0.3 -0.3 0 0 0 0',
                        axis='<axis><xyz>1 0 0</xyz></axis>'
                             '<axis2><xyz>0 1 0</xyz><limit><lower>-0.2</lower><upper>0.2</upper></limit></axis2>'))
    w, robot = spawn(sdf, 'p')
    seen = []
    for _ in range(100):
        w.step(10)
        seen.append(robot.joint_state('u::axis2')[0])
    assert max(abs(q) for q in seen) == pytest.approx(0.2, abs=0.05)
    assert abs(robot.joint_state('u')[0]) > 0.5  # the first axis is free


def test_a_ball_joint_is_simulated_and_reports_as_gazebos_ode_ball_joint():
    # test_sdf_joints.py checks its physics; here: not held fixed, and Gazebo 11's state (NaN, 0).
    sdf = model('m', link('base') + link('arm', '0 0 0.5 0 0 0') + joint('b', 'base', 'arm', type='ball', axis=''))
    w, robot = spawn(sdf)
    assert robot.joint_names == []  # the joints with one position
    position, velocity, _ = robot.joint_state('b')
    assert math.isnan(position) and velocity == 0
    assert not [m for m in logged(w, 'WARN') if "joint 'b'" in m]


def test_a_world_keeps_its_good_models_when_ones_pose_is_not_a_pose():
    w = load(world(model('bad', link('body'), model_pose='0 nan 0 0 0 0'),
                   model('good', link('body', '0 0 0.5 0 0 0'))))
    assert w.robots == ['good']
    assert [e for e in logged(w, 'ERROR') if "'bad'" in e and '<pose>' in e and 'nan' in e], logged(w, 'ERROR')


def test_spawn_puts_an_sdf_models_own_pose_in_the_spawn_pose_as_gazebo_ros_does():
    # gazebo_ros's updateSDFAttributes: the model's <pose> + the initial pose.
    at = (1, 2, 0.5, 0, 0, 0.8)
    w, robot = spawn(model('m', link('body', '0.1 0 0 0 0 0'), model_pose='0 0 0.3 0 0 0.5'), at=at)
    frame = compose(pose(*at), pose(0, 0, 0.3, 0, 0, 0.5))
    assert_pose(robot.base_pose(), frame)
    assert_pose(robot.link_pose('body'), compose(frame, pose(0.1)))


def test_a_joint_spring_the_physics_does_not_simulate_is_said():
    sdf = model('m', link('base') + link('arm', '0 0 0.5 0 0 0') + joint(
        'j', 'base', 'arm', axis='<axis><xyz>1 0 0</xyz><dynamics><spring_stiffness>5</spring_stiffness></dynamics></axis>'))
    w, robot = spawn(sdf)
    assert [m for m in logged(w, 'WARN') if "joint 'j'" in m and 'spring_stiffness> 5' in m and 'not simulated' in m]


# SDF 1.8's capsule and ellipsoid, <link> physics and the world's <physics> as read.

def test_capsules_and_ellipsoids_are_static_scenery_and_what_viewers_draw():
    shapes = ('<collision name="cap"><geometry><capsule><radius>0.1</radius><length>0.3</length></capsule></geometry>'
              '</collision><visual name="egg"><geometry><ellipsoid><radii>0.3 0.2 0.1</radii></ellipsoid></geometry>'
              '</visual>')
    w = load(world(model('shelf', link('board', '0 0 0.5 0 0 0', extra=shapes), static=True),
                   model('toy', link('body', '2 0 0.5 0 0 0', extra=shapes))))
    kinds = {c['name']: c['kind'] for c in w.static_collisions()}
    assert kinds['shelf::board::cap'] == 'capsule'
    import json
    drawn = {v['link']: v for v in json.loads(w.scene_json())['visuals'] if v['kind'] == 'ellipsoid'}
    assert set(drawn) == {'shelf::board::egg', 'toy::body'}
    assert drawn['toy::body']['radii'] == pytest.approx([0.3, 0.2, 0.1])
    assert not [m for m in logged(w, 'WARN') if 'capsule' in m or 'ellipsoid' in m]


def test_a_depth_camera_sees_an_ellipsoid_and_a_capsule_where_they_are():
    # A depth camera 2 m up looking straight down at an ellipsoid (radii 0.3 0.2 0.1) and a standing
    # capsule (radius 0.1, cylinder 0.3), both visuals only, the ellipsoid's link feeling no gravity:
    # every point the camera measures on them lies on their surfaces, and the ellipsoid's top is at
    # 1 + c, the capsule's at 1 + 0.15 + 0.1.
    shapes = model('shapes', """<link name="egg"><pose>0 0 1 0 0 0</pose><gravity>false</gravity>
      <visual name="v"><geometry><ellipsoid><radii>0.3 0.2 0.1</radii></ellipsoid></geometry></visual></link>""")
    pill = model('pill', """<link name="pill"><pose>0.45 0 1 0 0 0</pose>
      <visual name="v"><geometry><capsule><radius>0.1</radius><length>0.3</length></capsule></geometry></visual>
      </link>""", static=True)
    eye = model('eye', """<link name="eye"><pose>0.2 0 3 0 1.5707963267948966 0</pose>
      <sensor name="depth" type="depth"><update_rate>100</update_rate><camera><horizontal_fov>0.6</horizontal_fov>
        <image><width>96</width><height>96</height><format>R8G8B8</format></image><clip><near>0.1</near><far>10</far></clip>
      </camera></sensor></link>""", static=True)
    w = load(world(shapes, pill, eye))
    eye = w.robot('eye')
    eye.enable_sensor('depth')
    w.step(30)
    frame = eye.image('depth')
    if frame is None:
        pytest.skip('no OpenGL: ' + '; '.join(m for m in logged(w, 'WARN') + logged(w, 'INFO') if 'cameras' in m))
    # optical frame: z along the camera's x (down), x along its -y, y along its -z (-x of the world)
    rotation = np.column_stack([[0, -1, 0], [-1, 0, 0], [0, 0, -1]])
    origin = np.array([0.2, 0, 3.0])
    points = frame['points'].reshape(-1, 3) @ rotation.T + origin
    depth = frame['depth'].reshape(-1)
    hit = np.isfinite(depth) & (points[:, 2] > 0.5)
    egg = hit & (points[:, 0] < 0.32)
    pill = hit & (points[:, 0] > 0.33)
    assert egg.sum() > 200 and pill.sum() > 50
    e = points[egg] - [0, 0, 1]
    assert np.abs((e[:, 0] / 0.3) ** 2 + (e[:, 1] / 0.2) ** 2 + (e[:, 2] / 0.1) ** 2 - 1).max() < 0.02
    c = points[pill] - [0.45, 0, 1]
    axis = np.clip(c[:, 2], -0.15, 0.15)
    assert np.abs(np.sqrt(c[:, 0] ** 2 + c[:, 1] ** 2 + (c[:, 2] - axis) ** 2) - 0.1).max() < 2e-3
    assert points[egg][:, 2].max() == pytest.approx(1.1, abs=2e-3)
    assert points[pill][:, 2].max() == pytest.approx(1.25, abs=2e-3)
    assert w.robot('shapes').link_pose('egg')[2] == pytest.approx(1.0, abs=1e-9)  # no gravity: it stays


def test_a_kinematic_link_beyond_the_base_is_said_to_move_by_dynamics():
    w, robot = spawn(model('arm', link('body', '0 0 0.05 0 0 0') + link('tip', '0.3 0 0.05 0 0 0',
                                                                          extra='<kinematic>true</kinematic>')
                           + joint('j', 'body', 'tip')), 'arm')
    warnings = logged(w, 'WARN')
    assert any("'tip'" in m and 'kinematic' in m for m in warnings), warnings


@pytest.mark.parametrize('ode, expected', [
    ('<solver><iters>0</iters></solver>', r'<solver><iters> 0'),
    ('<solver><iters>2.5</iters></solver>', r'<solver><iters> 2.5'),
    ('<solver><iters>nan</iters></solver>', r"<iters> 'nan'.*Unable to set value"),
    ('<solver><sor>2</sor></solver>', r'<solver><sor> 2'),
    ('<solver><sor>-1</sor></solver>', r'<solver><sor> -1'),
    ('<constraints><contact_surface_layer>-0.001</contact_surface_layer></constraints>',
     r'<contact_surface_layer> -0.001'),
    ('<constraints><contact_surface_layer>inf</contact_surface_layer></constraints>', r"<contact_surface_layer>.*'inf'"),
])
def test_a_world_with_a_solver_setting_it_cannot_take_is_refused_naming_it(ode, expected):
    with pytest.raises(bp.DescriptionError, match=expected):
        bp.World.from_sdf(f'<?xml version="1.0"?><sdf version="1.6"><world name="w"><physics type="ode"><ode>{ode}'
                          '</ode></physics></world></sdf>')


@pytest.mark.parametrize('field', ['1 2', 'nan 0 0', '1e-5 inf 0'])
def test_a_world_with_a_magnetic_field_that_is_not_one_is_refused(field):
    with pytest.raises(bp.DescriptionError, match='<magnetic_field>'):
        bp.World.from_sdf(f'<?xml version="1.0"?><sdf version="1.6"><world name="w"><magnetic_field>{field}'
                          '</magnetic_field></world></sdf>')
