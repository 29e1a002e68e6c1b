"""SDF models through the node, as Gazebo takes them: spawn_model -sdf from a file, a parameter, the
model database (a model directory of GAZEBO_MODEL_PATH with its model.config) and stdin; the
spawn_sdf_model service itself (the model's own <pose> relative to the initial pose, the request's
name over the SDF's, gazebo_ros's refusals); and a world file's moving models (a free box and a
pendulum, a ball-jointed bob) as models of gazebo_ros: listed, falling, moved, reset, described. One master and one
node for the whole file, started paused: the spawn tests read exact poses, the world test unpauses."""
import math
import os

import pytest

from plant_helpers import sdf_world
from ros_harness import RosSystem, start_plant

pytestmark = pytest.mark.ros


def box_sdf(name, size=0.2, mass=1.0, pose='0 0 0 0 0 0', static=False):
    """A box model of SDF: one link with its inertia, a collision and a visual."""
    i = mass * size * size / 6
    return f"""<model name="{name}"><pose>{pose}</pose><static>{str(static).lower()}</static>
  <link name="body">
    <inertial><mass>{mass}</mass><inertia><ixx>{i}</ixx><iyy>{i}</iyy><izz>{i}</izz></inertia></inertial>
    <collision name="shell"><geometry><box><size>{size} {size} {size}</size></box></geometry></collision>
    <visual name="look"><geometry><box><size>{size} {size} {size}</size></box></geometry></visual>
  </link>
</model>"""


def sdf(model):
    return f'<?xml version="1.0"?>\n<sdf version="1.6">{model}</sdf>'


# A pendulum hung from the world at 1 m: a bar on a revolute joint about y, its bob 0.5 m below,
# started 0.3 rad out.
PENDULUM = """<model name="pendulum"><pose>3 0 1 0 0 0</pose>
  <link name="bar"><pose>0 0 0 0 0.3 0</pose>
    <inertial><pose>0 0 -0.5 0 0 0</pose><mass>0.5</mass>
      <inertia><ixx>0.001</ixx><iyy>0.001</iyy><izz>0.001</izz></inertia></inertial>
    <collision name="bob"><pose>0 0 -0.5 0 0 0</pose><geometry><sphere><radius>0.05</radius></sphere></geometry></collision>
  </link>
  <joint name="hinge" type="revolute"><parent>world</parent><child>bar</child><axis><xyz>0 1 0</xyz></axis></joint>
</model>"""

# A bob hung 0.5 m below a ball joint fixed to the world, 0.2 m out: gazebo_ros lists the joint and
# answers get_joint_properties for it as Gazebo 11's ODE ball joint (position NaN, rate 0).
SWIVEL = """<model name="swivel"><pose>-3 3 1 0 0 0</pose>
  <link name="bob"><pose>0.2 0 -0.5 0 0 0</pose>
    <inertial><mass>0.5</mass><inertia><ixx>0.001</ixx><iyy>0.001</iyy><izz>0.001</izz></inertia></inertial>
    <collision name="ball"><geometry><sphere><radius>0.05</radius></sphere></geometry></collision>
  </link>
  <joint name="socket" type="ball"><parent>world</parent><child>bob</child><pose>-0.2 0 0.5 0 0 0</pose></joint>
</model>"""

# Two boxes of one model that no joint joins (Gazebo's free links), 1 m apart, dropped from 0.5 m.
PAIR = """<model name="pair"><pose>3 3 0.5 0 0 0</pose>""" + "".join(f"""
  <link name="{side}"><pose>{x} 0 0 0 0 0</pose>
    <inertial><mass>1</mass><inertia><ixx>0.0067</ixx><iyy>0.0067</iyy><izz>0.0067</izz></inertia></inertial>
    <collision name="shell"><geometry><box><size>0.2 0.2 0.2</size></box></geometry></collision>
  </link>""" for side, x in (('left', 0), ('right', 1))) + "</model>"

# A world model ROS cannot name a topic of: left out with an error naming it, the node goes on.
BAD_TOPIC = """<model name="badly_named"><pose>-3 0 0.1 0 0 0</pose>
  <link name="body"><inertial><mass>1</mass><inertia><ixx>0.01</ixx><iyy>0.01</iyy><izz>0.01</izz></inertia></inertial>
    <collision name="shell"><geometry><box><size>0.2 0.2 0.2</size></box></geometry></collision>
    <sensor type="ray" name="lidar"><ray><scan><horizontal><samples>3</samples></horizontal></scan>
      <range><min>0.1</min><max>5</max></range></ray>
      <plugin name="lidar_plugin" filename="libgazebo_ros_laser.so"><topicName>bad topic</topicName></plugin>
    </sensor>
  </link>
</model>"""

MODEL_CONFIG = """<?xml version="1.0"?>
<model><name>Tiny box</name><version>1.0</version><sdf version="1.6">tiny.sdf</sdf>
  <description>a box the tests spawn from the model path</description></model>"""


@pytest.fixture(scope='module')
def sim(tmp_path_factory):
    """The node on a world with a free box at 1 m and a pendulum, paused, with a model path holding
    the model tiny_box (model.config naming tiny.sdf)."""
    work = tmp_path_factory.mktemp('spawn_sdf')
    models = work / 'models'
    (models / 'tiny_box').mkdir(parents=True)
    (models / 'tiny_box' / 'model.config').write_text(MODEL_CONFIG)
    (models / 'tiny_box' / 'tiny.sdf').write_text(sdf(box_sdf('tiny_box', size=0.1, pose='0 0 0.05 0 0 0')))
    (models / 'tiny_post').mkdir()
    (models / 'tiny_post' / 'model.sdf').write_text(sdf(box_sdf('tiny_post', size=0.1, static=True)))
    (models / 'tiny_post' / 'model.config').write_text(  # which Gazebo's include needs (sdformat's rule)
        '<model><name>tiny_post</name><sdf version="1.6">model.sdf</sdf></model>')
    (work / 'box.sdf').write_text(sdf(box_sdf('from_file', pose='0.5 0 0.1 0 0 0')))
    world = work / 'falling.world'
    world.write_text(sdf_world(box_sdf('crate', pose='0 -3 1 0 0 0') + PENDULUM + SWIVEL + PAIR + BAD_TOPIC))
    system = RosSystem(str(work))
    system.env['GAZEBO_MODEL_PATH'] = str(models)
    try:
        system.plant = start_plant(system, str(world), paused=True)
        yield system
    finally:
        system.close()


def spawn_model(sim, *args, input=None):
    return sim.run(['rosrun', 'gazebo_ros', 'spawn_model', *args], timeout=60, input=input)


@pytest.mark.slow
def test_spawn_model_sdf_from_a_file_a_parameter_the_model_path_and_stdin(sim):
    work = sim.workdir
    sim.set_param('/box_sdf', textfile=os.path.join(work, 'box.sdf'))
    runs = {
        'file_box': spawn_model(sim, '-sdf', '-file', os.path.join(work, 'box.sdf'), '-model', 'file_box', '-y', '1'),
        'param_box': spawn_model(sim, '-sdf', '-param', '/box_sdf', '-model', 'param_box', '-y', '2', '-Y', '1.5708'),
        'db_box': spawn_model(sim, '-sdf', '-database', 'tiny_box', '-model', 'db_box', '-x', '2', '-y', '1', '-z', '0.3'),
        'post': spawn_model(sim, '-sdf', '-database', 'tiny_post', '-model', 'post', '-x', '-2', '-z', '0.5'),
        'stdin_box': spawn_model(sim, '-sdf', '-stdin', '-model', 'stdin_box', '-y', '3',
                                 input=sdf(box_sdf('whatever', pose='0 0 0.1 0 0 0'))),
    }
    for name, run in runs.items():
        assert run.returncode == 0, name + ': ' + run.stdout + run.stderr + sim.plant.log()
    out = sim.probe('gazebo_ros/probes/model_poses.py', *runs, timeout=60)
    # The file's model <pose> 0.5 0 0.1, in the frame of -y 1 (and of -Y pi/2 for the parameter's).
    assert out['file_box'] == pytest.approx([0.5, 1.0, 0.1, 0.0], abs=1e-3)
    assert out['param_box'] == pytest.approx([0.0, 2.5, 0.1, math.pi / 2], abs=1e-3)
    # -database: the include's pose is the spawn pose; the model file's own <pose> is not used, as Gazebo.
    assert out['db_box'] == pytest.approx([2.0, 1.0, 0.3, 0.0], abs=1e-3)
    assert out['post'] == pytest.approx([-2.0, 0.0, 0.5, 0.0], abs=1e-3), 'a static model (model.sdf without a model.config), fixed where it is put'
    assert out['static']['post'] is True and out['static']['db_box'] is False
    assert out['stdin_box'] == pytest.approx([0.0, 3.0, 0.1, 0.0], abs=1e-3)
    assert out['bodies']['db_box'] == ['body'] and out['geoms']['db_box'] == ['shell']

    missing = spawn_model(sim, '-sdf', '-database', 'no_such_model', '-model', 'nothing')
    assert missing.returncode == 1
    assert "model://no_such_model" in missing.stdout + missing.stderr and 'GAZEBO_MODEL_PATH' in missing.stdout + missing.stderr
    urdf_database = spawn_model(sim, '-urdf', '-database', 'tiny_box', '-model', 'nothing')
    assert urdf_database.returncode == 1 and 'give -sdf' in urdf_database.stdout + urdf_database.stderr
    broken = spawn_model(sim, '-sdf', '-stdin', '-model', 'nothing', input='<sdf version="1.6"><model name="x">')
    assert broken.returncode == 1 and 'not well-formed' in broken.stdout + broken.stderr


def test_spawn_sdf_model_service_names_places_refuses_and_deletes(sim):
    out = sim.probe('gazebo_ros/probes/spawn_sdf_model_service.py', timeout=60)
    assert out['spawn'] == [True, 'SpawnModel: Successfully spawned entity']
    # model <pose> 1 0 0.2 in the initial pose (0, -1, 0, yaw pi/2): at (0, 0, 0.2), turned pi/2
    assert out['at'] == pytest.approx([0.0, 0.0, 0.2, math.pi / 2], abs=1e-3)
    assert out['names_have'] == [True, False], 'the request names the model, not the SDF'
    assert out['again'] == [False, 'SpawnModel: Failure - entity already exists.']
    assert out['bad_mass'][0] is False
    assert "'heavy'" in out['bad_mass'][1] and '<mass>' in out['bad_mass'][1], out['bad_mass']
    assert out['not_sdf'][0] is False and 'not SDF or URDF' in out['not_sdf'][1]
    assert out['urdf_service_refuses_sdf'] == 'call failed', 'spawn_urdf_model fails the call for SDF, as gazebo_ros'
    assert out['delete'] == [True, 'DeleteModel: successfully deleted model']
    assert out['after_delete'] is False
    assert out['still_running'] is True, 'the node answers after every refusal'


def test_world_file_models_are_gazebo_ros_models(sim):
    out = sim.probe('gazebo_ros/probes/world_file_models.py', timeout=90)
    assert {'crate', 'pendulum'} <= set(out['model_states']), out['model_states']
    assert 'ground_plane' in out['model_states'], 'a static model is a model, as in Gazebo'
    assert out['start'] == pytest.approx([0.0, -3.0, 1.0], abs=1e-3)
    assert out['rested'][2] == pytest.approx(0.1, abs=0.005), 'the box fell and rests on the ground'
    assert abs(out['rested_speed']) < 0.01
    assert out['pendulum_swung'] > 0.05, 'the pendulum moved under gravity'
    assert out['set'] == [True, 'SetModelState: set model state done']
    assert out['moved'] == pytest.approx([1.0, -4.0, 0.5], abs=1e-3)
    assert out['reset_crate'] == pytest.approx([0.0, -3.0, 1.0], abs=1e-3), 'reset_world: where the file put it'
    assert out['reset_pendulum'] == pytest.approx(out['pendulum_start'], abs=1e-3)
    assert out['props'] == {'success': True, 'body_names': ['bar'], 'geom_names': ['bob'],
                            'joint_names': ['hinge'], 'is_static': False}
    assert out['crate_props'] == {'success': True, 'body_names': ['body'], 'geom_names': ['shell'],
                                  'joint_names': [], 'is_static': False}
    assert out['swivel_props']['joint_names'] == ['socket']
    success, position, rate = out['socket']
    assert success and len(position) == 1 and math.isnan(position[0]) and rate == [0.0], out['socket']
    assert out['swivel_swung'] > 0.01, 'the bob swung about its ball joint'
    assert out['delete'] == [True, 'DeleteModel: successfully deleted model']
    assert 'crate' not in out['after_delete']
    log = sim.plant.log()
    assert "world model 'crate' loaded" in log and "world model 'pendulum' loaded" in log, log
    assert 'badly_named' not in out['model_states']
    # The free links: one model, each link in link_states, falling on its own, moved with the model.
    assert out['model_states'].count('pair') == 1 and not any('left' in m or 'right' in m for m in out['model_states'])
    assert {'pair::left', 'pair::right'} <= set(out['link_states']), out['link_states']
    assert out['pair_props']['body_names'] == ['left', 'right'], out['pair_props']
    assert out['pair_rested'][0][2] == pytest.approx(0.1, abs=0.005) and out['pair_rested'][1][2] == pytest.approx(0.1, abs=0.005)
    assert out['pair_rested'][1][0] - out['pair_rested'][0][0] == pytest.approx(1.0, abs=0.01)
    assert out['pair_moved'][0] == pytest.approx([-5.0, 5.0, 0.1], abs=0.01)
    assert out['pair_moved'][1] == pytest.approx([-4.0, 5.0, 0.1], abs=0.01), 'the free link moved with its model'
    assert 'pair' not in out['after_pair_delete'] and not out['pair_link_after_delete'], 'every link went with it'
    assert "world model 'badly_named' is left out: sensor 'lidar'" in log and "'bad topic' is not a valid ROS name" in log
