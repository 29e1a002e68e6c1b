"""The fuzz cases of test_fuzz.py: mutated URDFs, mutated SDF worlds and random sequences of Python API
calls and worlds of SDF models that move, each made from (kind, seed) alone, so a failing case is reproduced by its seed:

    /usr/bin/python3 test/helpers/fuzz_cases.py urdf 1234 1     # kind, first seed, number of cases

Run as a script it runs the cases in this process and prints one JSON line per case:
{"seed", "outcome" ('ran' or 'refused'), "detail", "seconds", "non_finite"}. A crash or a hang shows as
the process dying or not answering; the test then reruns the batch case by case to name the seed.
"""
import json
import math
import os
import random
import re
import sys
import time

NASTY_NUMBERS = ['nan', 'inf', '-inf', '-1', '0', '1e30', '-1e30', '1e-30', '1e308', '-1e308', '1e-45', '3e38',
                 '', 'abc', '1 2', '0x10', '99999999999999999999', '-0', '1e6', '-5']
NASTY_NAMES = ['', ' ', 'a b', '../../etc', '~x', '1abc', '/', '//', 'x/', '\u00e9', 'tianracer', 'a' * 300]
NUMBER = re.compile(r'-?\d+(\.\d+)?(e-?\d+)?')
STEPS_PER_CASE = 150


def mutate_xml(text, rng, mutations):
    """`mutations` random edits of XML text: a number replaced by a nasty one, an attribute value
    replaced by a nasty name, an element removed or doubled, or the text cut short."""
    for _ in range(mutations):
        choice = rng.random()
        if choice < 0.45:
            numbers = list(NUMBER.finditer(text))
            if numbers:
                m = rng.choice(numbers)
                text = text[:m.start()] + rng.choice(NASTY_NUMBERS) + text[m.end():]
        elif choice < 0.6:
            values = list(re.finditer(r'="([^"]*)"', text))
            if values:
                m = rng.choice(values)
                text = text[:m.start(1)] + rng.choice(NASTY_NAMES + NASTY_NUMBERS) + text[m.end(1):]
        elif choice < 0.8:
            elements = list(re.finditer(r'<(\w+)[^<>]*?(/>|>[^<]*</\1>)', text))
            if elements:
                m = rng.choice(elements)
                text = text[:m.start()] + (m.group(0) * 2 if rng.random() < 0.5 else '') + text[m.end():]
        elif choice < 0.95:
            texts = list(re.finditer(r'>([^<>]+)<', text))
            if texts:
                m = rng.choice(texts)
                text = text[:m.start(1)] + rng.choice(NASTY_NAMES + NASTY_NUMBERS) + text[m.end(1):]
        else:
            text = text[:rng.randrange(len(text))]
    return text


BASE_WORLD = """<?xml version="1.0"?>
<sdf version="1.6"><world name="fuzz">
  <include><uri>model://ground_plane</uri></include>
  <include><uri>model://sun</uri></include>
  <physics type="ode"><max_step_size>0.001</max_step_size><real_time_factor>1</real_time_factor>
    <ode><constraints><contact_max_correcting_vel>100</contact_max_correcting_vel></constraints></ode></physics>
  <gravity>0 0 -9.8</gravity>
  <light name="lamp" type="directional"><direction>-0.5 0.1 -0.9</direction></light>
  <model name="crate"><static>true</static><pose>1.5 0 0.25 0 0 0.3</pose>
    <link name="link"><collision name="c"><geometry><box><size>0.5 0.5 0.5</size></box></geometry>
      <surface><friction><ode><mu>0.8</mu></ode></friction></surface></collision>
      <visual name="v"><geometry><box><size>0.5 0.5 0.5</size></box></geometry>
      <material><diffuse>0.8 0.1 0.1 1</diffuse></material></visual></link></model>
  <model name="post"><static>true</static><pose>0 1.2 0.5 0 0 0</pose>
    <link name="link"><collision name="c"><geometry><cylinder><radius>0.1</radius><length>1</length></cylinder>
      </geometry></collision></link></model>
  <model name="ball"><static>true</static><pose>-1 -1 0.2 0 0 0</pose>
    <link name="link"><pose>0 0 0.1 0 0 0</pose><collision name="c"><geometry><sphere><radius>0.2</radius></sphere>
      </geometry></collision></link></model>
</world></sdf>"""


def finite_state(world):
    for name in world.robots:
        robot = world.robot(name)
        values = list(robot.base_pose())
        linear, angular = robot.base_twist()
        values += list(linear) + list(angular)
        for joint in robot.joint_names:
            values += list(robot.joint_state(joint))
        if not all(math.isfinite(v) for v in values):
            return False
    return math.isfinite(world.time)


def drive(world, robot, rng, steps):
    """Random commands on every handle (nasty values included), every sensor on, `steps` steps;
    False when a state read back was not finite."""
    for sensor in robot.sensors:
        robot.enable_sensor(sensor)
    finite = True
    for _ in range(steps // 25):
        for joint in robot.handles:
            robot.set_command(joint, rng.choice([rng.uniform(-50, 50), 0.0, 1e308, -1e308, float('nan')]))
        world.step(25)
        finite = finite and finite_state(world)
    return finite


def mutated_urdf(seed, urdf):
    """The URDF of case `seed`, its spawn pose (x y z roll pitch yaw) and the case's random source."""
    rng = random.Random(seed)
    text = mutate_xml(urdf, rng, rng.randint(1, 4))
    return text, (0, 0, rng.choice([0.0, 0.05, 0.3]), 0, 0, rng.uniform(-3, 3)), rng


def urdf_case(seed, urdf, bullet_plant):
    text, pose, rng = mutated_urdf(seed, urdf)
    world = bullet_plant.World()
    world.echo = False
    robot = world.spawn(text, 'fuzzed', pose=pose)
    return drive(world, robot, rng, STEPS_PER_CASE)


def sdf_case(seed, urdf, bullet_plant):
    rng = random.Random(seed)
    world = bullet_plant.World.from_sdf(mutate_xml(BASE_WORLD, rng, rng.randint(1, 4)))
    world.echo = False
    if world.time_step > 0.01:  # a legal but coarse step: fewer of them
        return finite_state(world)
    robot = world.spawn(urdf, 'car', pose=(rng.uniform(-2, 2), rng.uniform(-2, 2), 0, 0, 0, rng.uniform(-3, 3)))
    return drive(world, robot, rng, STEPS_PER_CASE)


# SDF models that move (test_fuzz.py, kind sdf_model): worlds of them, mutated, and structures a mutation does
# not make: deep nesting, include loops (test/fixtures/sdf_models/loop_a and loop_b), hostile values
# in every number a model has.
SDF_MODELS = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'fixtures', 'sdf_models')
HOSTILE_NUMBERS = ['nan', 'inf', '-inf', '1e300', '-1e300', '0', '-1', '1e-300', '-0.5', '']

MODEL_WORLD = """<?xml version="1.0"?>
<sdf version="{version}"><world name="fuzz">
  <include><uri>model://ground_plane</uri></include>
  <physics type="ode"><max_step_size>0.001</max_step_size>
    <ode><solver><iters>20</iters><sor>1.3</sor></solver><constraints><erp>0.2</erp>
      <contact_surface_layer>0.001</contact_surface_layer></constraints></ode></physics>
  <magnetic_field>5.5645e-6 22.8758e-6 -42.3884e-6</magnetic_field>
  <model name="arm"><pose>0 0 0.5 0 0 0.3</pose><self_collide>true</self_collide>
    <allow_auto_disable>false</allow_auto_disable>
    <link name="base"><inertial><mass>2</mass><inertia><ixx>0.1</ixx><iyy>0.1</iyy><izz>0.1</izz></inertia></inertial>
      <collision name="c"><geometry><box><size>0.3 0.3 0.3</size></box></geometry></collision>
      <visual name="v"><geometry><ellipsoid><radii>0.2 0.15 0.1</radii></ellipsoid></geometry></visual></link>
    <link name="upper"><pose>0 0 0.4 0 0 0</pose>
      <collision name="c"><geometry><cylinder><radius>0.05</radius><length>0.5</length></cylinder></geometry></collision></link>
    <link name="lower"><pose>0.2 0 0.6 0 1.2 0</pose><self_collide>false</self_collide>
      <collision name="c"><geometry><sphere><radius>0.05</radius></sphere></geometry></collision>
      <collision name="pill"><pose>0 0 0.1 0 0 0</pose><geometry><capsule><radius>0.03</radius><length>0.1</length>
        </capsule></geometry></collision></link>
    <frame name="elbow" attached_to="upper"><pose>0 0 0.25 0 0 0</pose></frame>
    <joint name="shoulder" type="revolute"><parent>base</parent><child>upper</child><pose>0 0 -0.25 0 0 0</pose>
      <axis><xyz expressed_in="__model__">0 1 0</xyz><use_parent_model_frame>true</use_parent_model_frame>
        <limit><lower>-1</lower><upper>1</upper><effort>10</effort></limit>
        <dynamics><damping>0.1</damping><spring_stiffness>1</spring_stiffness></dynamics></axis></joint>
    <joint name="elbow" type="universal"><parent>upper</parent><child>lower</child>
      <pose relative_to="elbow">0 0 0 0 0 0</pose>
      <axis><xyz>1 0 0</xyz></axis><axis2><xyz>0 1 0</xyz><limit><lower>-0.5</lower><upper>0.5</upper></limit></axis2></joint>
    <model name="hand"><pose>0.4 0 0.6 0 0 0</pose>
      <link name="palm"><collision name="c"><geometry><box><size>0.1 0.1 0.02</size></box></geometry></collision></link>
      <link name="finger"><pose>0 0.05 0 0 0 0</pose><gravity>false</gravity>
        <collision name="tip"><geometry><ellipsoid><radii>0.02 0.01 0.01</radii></ellipsoid></geometry></collision></link>
      <joint name="slide" type="prismatic"><parent>palm</parent><child>finger</child>
        <axis><xyz>0 1 0</xyz><limit><lower>0</lower><upper>0.04</upper></limit></axis></joint>
    </model>
    <joint name="wrist" type="{wrist}"><parent>lower</parent><child>hand::palm</child><axis><xyz>0 0 1</xyz></axis>
      <axis2><xyz>1 0 0</xyz></axis2></joint>
  </model>
  <include><uri>model://swing_arm</uri><name>swing</name><pose>2 0 0.2 0 0 0</pose></include>
  <model name="loop"><pose>-2 0 1 0 0 0</pose><include><uri>model://loop_a</uri></include></model>
  <include><uri>model://loop_b</uri><pose>-2 2 1 0 0 0</pose></include>
  <model name="crate"><static>{static}</static><pose>0 2 0.2 0 0 0</pose>
    <link name="link"><kinematic>true</kinematic>
      <collision name="c"><geometry><box><size>0.4 0.4 0.4</size></box></geometry></collision>
      <collision name="m"><geometry><mesh><uri>model://nowhere/mesh.stl</uri></mesh></geometry></collision></link></model>
  {extra}
</world></sdf>"""


def nested_models(rng, depth):
    """`depth` models each inside the last, each a link joined to its parent model's."""
    text, closing = '', ''
    for level in range(depth):
        parent = 'l' if level == 0 else 'm%d::l' % (level - 1)
        text += ('<model name="m%d"><pose>0 0 0.1 0 0 %s</pose><link name="l"><collision name="c"><geometry><box>'
                 '<size>0.05 0.05 0.05</size></box></geometry></collision></link>' % (level, rng.choice(['0', '0.1'])))
        closing = '</model>' + closing
    joints = ''.join('<joint name="j%d" type="%s"><parent>%s</parent><child>%s</child><axis><xyz>1 0 0</xyz></axis>'
                     '</joint>' % (level, rng.choice(['revolute', 'fixed', 'ball']),
                                   'l' if level == 0 else '::'.join('m%d' % k for k in range(level)) + '::l',
                                   '::'.join('m%d' % k for k in range(level + 1)) + '::l')
                     for level in range(depth))
    return ('<model name="deep"><pose>0 -2 1 0 0 0</pose><link name="l"/>' + text + closing + joints + '</model>')


def mutated_sdf_models(seed):
    """The world of moving SDF models of case `seed` (its models need GAZEBO_MODEL_PATH=SDF_MODELS) and
    the case's random source."""
    rng = random.Random(seed)
    extra = nested_models(rng, rng.choice([2, 12, 40])) if rng.random() < 0.3 else ''
    text = MODEL_WORLD.format(version=rng.choice(['1.4', '1.5', '1.6', '1.7']), extra=extra,
                              wrist=rng.choice(['revolute', 'continuous', 'universal', 'revolute2', 'ball', 'screw',
                                                'gearbox', 'fixed', 'prismatic', 'hinge']),
                              static=rng.choice(['true', 'false']))
    if rng.random() < 0.3:  # many numbers hostile at once (the physics' step left alone)
        share = rng.choice([0.02, 0.1, 0.3])
        text = re.sub(r'(?<=>)[^<>]*\d[^<>]*(?=</(?!max_step_size))',
                      lambda m: ' '.join(rng.choice(HOSTILE_NUMBERS) for _ in m.group(0).split())
                      if rng.random() < share else m.group(0), text)
    return mutate_xml(text, rng, rng.randint(0, 4)), rng


def sdf_model_case(seed, urdf, bullet_plant):
    os.environ['GAZEBO_MODEL_PATH'] = SDF_MODELS
    text, rng = mutated_sdf_models(seed)
    world = bullet_plant.World.from_sdf(text)
    world.echo = False
    finite = finite_state(world)
    if rng.random() < 0.5:  # the same text's first model through spawn (parseModelXml)
        try:
            world.spawn(text, 'spawned', pose=(0, 0, rng.choice([0.0, 1.0]), 0, 0, 0))
        except bullet_plant.DescriptionError:
            pass
    world.step(STEPS_PER_CASE)
    return finite and finite_state(world)


def random_tree(rng, depth=0):
    if depth > 3 or rng.random() < 0.4:
        return rng.choice([1, -1.5, float('nan'), float('inf'), 'text', True, None, [1, 2], 10 ** 30])
    return {rng.choice(NASTY_NAMES + ['p', 'i', 'd', 'type', 'joint', 'pid']): random_tree(rng, depth + 1)
            for _ in range(rng.randint(1, 3))}


def api_case(seed, urdf, bullet_plant):
    """Twenty random calls; the errors the API documents (ValueError, KeyError, TypeError,
    RuntimeError and their subclasses, OSError for a parameter file that is not there) are answers,
    anything else escapes as a failure."""
    from tianracer_description.tianracer import TUTORIAL_CONTROLLERS
    rng = random.Random(seed)
    world = bullet_plant.World()
    world.echo = False
    handles = []
    config = {'tianracer': {'joint_state_controller': {'type': 'joint_state_controller/JointStateController',
                                                       'publish_rate': 50}}}
    names = list(TUTORIAL_CONTROLLERS) + NASTY_NAMES
    nasty = [0.0, 1.0, -1.0, 1e308, float('nan'), float('inf'), 1e-300]
    finite = True

    def some_robot():
        return rng.choice(handles) if handles else world.spawn(urdf, 'car0')

    calls = [
        lambda: handles.append(world.spawn(urdf, rng.choice(['car%d' % rng.randint(0, 3)] + NASTY_NAMES),
                                           pose=[rng.choice(nasty + [0.5]) for _ in range(6)],
                                           joints={rng.choice(['left_steering_hinge_joint', 'x']): rng.choice(nasty)})),
        lambda: world.remove(rng.choice(['car%d' % rng.randint(0, 3)] + NASTY_NAMES)),
        lambda: world.step(rng.choice([0, 1, 17, 200])),
        lambda: world.load_params(rng.choice([config, random_tree(rng)])),
        lambda: some_robot().set_command(rng.choice(some_robot().joint_names + NASTY_NAMES), rng.choice(nasty)),
        lambda: some_robot().set_effort_law(rng.choice(['left_steering_hinge_joint', 'x']),
                                            *[rng.choice(nasty) for _ in range(5)]),
        lambda: some_robot().enable_sensor(rng.choice(['lidar', 'camera', 'depth_camera', 'x']), rng.random() < 0.8),
        lambda: some_robot().controller_manager.load(rng.choice(names)),
        lambda: some_robot().controller_manager.unload(rng.choice(names)),
        lambda: some_robot().controller_manager.switch(rng.sample(names, 2), rng.sample(names, 1), rng.choice([0, 1, 2, 7])),
        lambda: some_robot().controller_manager.command(rng.choice(names), rng.choice(nasty)),
        lambda: some_robot().controller_manager.list(),
        lambda: some_robot().link_pose(rng.choice(['base_link', 'x'] + NASTY_NAMES)),
        lambda: (some_robot().scan('lidar'), some_robot().image('camera')),
        lambda: setattr(some_robot(), 'e_stop', rng.random() < 0.5),
        lambda: setattr(world, 'paused', rng.random() < 0.5),
        lambda: world.reset_world(),
        lambda: world.reset_simulation(),
        lambda: world.cast_ray([rng.choice(nasty) for _ in range(3)], [rng.choice(nasty) for _ in range(3)],
                               rng.choice(nasty + [5.0])),
        lambda: world.robot(rng.choice(['car0', 'car1'] + NASTY_NAMES)),
    ]
    for _ in range(20):
        try:
            rng.choice(calls)()
        except (ValueError, KeyError, TypeError, RuntimeError, OSError):
            pass
        finite = finite and finite_state(world)
    return finite


CASES = {'urdf': urdf_case, 'sdf': sdf_case, 'api': api_case, 'sdf_model': sdf_model_case}


def main(kind, first, count):
    from tianracer_description import bullet_plant
    from tianracer_description.tianracer import tianracer_urdf
    urdf = tianracer_urdf()
    for seed in range(first, first + count):
        start = time.monotonic()
        outcome, detail, finite = 'ran', '', True
        try:
            finite = CASES[kind](seed, urdf, bullet_plant)
        except bullet_plant.DescriptionError as e:
            outcome, detail = 'refused', str(e)[:200]
        print(json.dumps({'seed': seed, 'outcome': outcome, 'detail': detail,
                          'seconds': round(time.monotonic() - start, 3), 'non_finite': not finite}), flush=True)


if __name__ == '__main__':
    main(sys.argv[1], int(sys.argv[2]), int(sys.argv[3]))
