"""Gazebo worlds and models as their users ship them, read without a ROS master: model:// through
GAZEBO_MODEL_PATH and through a package's gazebo_model_path export on ROS_PACKAGE_PATH, <include>
with name, pose and static overrides, model.config's newest SDF, nested includes, mesh URIs relative
to the file naming them, and what is left out with one warning instead of stopping the world.

Each test builds its own model and package directories in tmp_path. Mesh physics is not checked here
(the meshes are never collided with): a mesh's description is checked through static_collisions()."""
import math
import re

import pytest

from plant_helpers import logged, yaw_of
from suite_paths import REPOSITORY
from tianracer_description import bullet_plant

WALL_SDF = """<?xml version="1.0"?>
<sdf version="{version}"><model name="{name}"><static>{static}</static><pose>{pose}</pose>
  <link name="link">{collisions}</link>
</model></sdf>"""

BOX_COLLISION = """<collision name="{name}"><pose>{pose}</pose>
  <geometry><box><size>{size}</size></box></geometry></collision>"""

MESH_COLLISION = """<collision name="{name}">
  <geometry><mesh><uri>{uri}</uri><scale>{scale}</scale></mesh></geometry></collision>"""

STL = "solid part\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid part\n"


def write(path, text):
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text)
    return path


def make_model(models_dir, name, collisions, pose='0 0 0 0 0 0', static='true', config=None):
    """A Gazebo model directory: model.config naming model.sdf, and model.sdf with one link."""
    model_dir = models_dir / name
    write(model_dir / 'model.config', config or f"""<?xml version="1.0"?>
<model><name>{name}</name><version>1.0</version><sdf version="1.6">model.sdf</sdf></model>""")
    write(model_dir / 'model.sdf', WALL_SDF.format(version='1.6', name=name, static=static, pose=pose,
                                                   collisions=collisions))
    return model_dir


def wall(name='collision', pose='0 0 0 0 0 0', size='0.1 2 1'):
    return BOX_COLLISION.format(name=name, pose=pose, size=size)


def world_sdf(body):
    return f"""<?xml version="1.0"?>
<sdf version="1.6"><world name="users_world">
  <include><uri>model://ground_plane</uri></include>
  <include><uri>model://sun</uri></include>
{body}
</world></sdf>"""


def include(uri, pose=None, name=None, static=None):
    parts = [f'<uri>{uri}</uri>']
    if pose is not None:
        parts.append(f'<pose>{pose}</pose>')
    if name is not None:
        parts.append(f'<name>{name}</name>')
    if static is not None:
        parts.append(f'<static>{static}</static>')
    return '<include>' + ''.join(parts) + '</include>'


def load(path):
    world = bullet_plant.World.from_file(str(path))
    world.echo = False
    return world


def collisions(world):
    return {c['name']: c for c in world.static_collisions()}


def range_along_x(world, y=0.0, z=0.25):
    # z within the 1 m walls' height (they span z -0.5 .. 0.5), not along a face's edge
    return world.cast_ray([0.0, y, z], [1.0, 0.0, 0.0], 20.0)


@pytest.fixture
def model_path(tmp_path, monkeypatch):
    """An empty GAZEBO_MODEL_PATH directory and no packages: each test adds what it needs."""
    models = tmp_path / 'models'
    models.mkdir()
    monkeypatch.setenv('GAZEBO_MODEL_PATH', str(tmp_path / 'not_there') + ':' + str(models))
    monkeypatch.setenv('ROS_PACKAGE_PATH', str(tmp_path / 'no_packages'))
    return models


def test_include_from_gazebo_model_path_takes_the_includes_name_and_pose(tmp_path, model_path):
    make_model(model_path, 'brick_wall', wall(), pose='9 9 9 0 0 0')
    world = load(write(tmp_path / 'w.world', world_sdf(
        include('model://brick_wall', pose='3 0 0 0 0 0', name='north_wall'))))
    found = collisions(world)
    assert 'north_wall::link::collision' in found
    assert not any(name.startswith('brick_wall') for name in found)
    assert found['north_wall::link::collision']['pose'][:3] == pytest.approx([3, 0, 0])
    # The box is where the include puts it: a ray along x stops at its near face (3 - 0.05).
    assert range_along_x(world) == pytest.approx(2.95, abs=1e-3)
    assert range_along_x(world, y=1.5) == math.inf  # past the 2 m wall's end
    assert logged(world, 'WARN') == []


def test_include_without_pose_or_name_keeps_the_models_own(tmp_path, model_path):
    make_model(model_path, 'brick_wall', wall(), pose='4 0 0 0 0 0')
    world = load(write(tmp_path / 'w.world', world_sdf(include('model://brick_wall'))))
    assert 'brick_wall::link::collision' in collisions(world)
    assert range_along_x(world) == pytest.approx(3.95, abs=1e-3)


def test_include_pose_rotates_the_model(tmp_path, model_path):
    # The wall sits 3 m along the model's -y, turned to lie along the model's x; the include turns the
    # model by +90 deg about z, which brings the wall to 3 m along the world's x, lying along y.
    make_model(model_path, 'offset_wall', wall(pose='0 -3 0 0 0 1.5707963267948966'))
    world = load(write(tmp_path / 'w.world', world_sdf(
        include('model://offset_wall', pose='0 0 0 0 0 1.5707963267948966'))))
    assert range_along_x(world) == pytest.approx(2.95, abs=1e-3)


def test_model_config_names_the_newest_sdf_sdformat_reads(tmp_path, model_path):
    # sdformat's rule (getModelFilePath): the newest <sdf> of model.config that it can read; 1.10 is
    # newer than Debian's sdformat 12 reads (1.9).
    model_dir = make_model(model_path, 'versions', wall(), pose='6 0 0 0 0 0', config="""<model>
  <name>versions</name>
  <sdf version="1.4">model.sdf</sdf><sdf version="1.10">model-1_10.sdf</sdf><sdf version="1.7">model-1_7.sdf</sdf>
</model>""")
    for version, pose in (('1.7', '2 0 0 0 0 0'), ('1.10', '4 0 0 0 0 0')):
        write(model_dir / f"model-{version.replace('.', '_')}.sdf",
              WALL_SDF.format(version=version, name='versions', static='true', pose=pose, collisions=wall()))
    world = load(write(tmp_path / 'w.world', world_sdf(include('model://versions'))))
    assert range_along_x(world) == pytest.approx(1.95, abs=1e-3)


def test_include_through_a_packages_gazebo_model_path_export(tmp_path, monkeypatch):
    monkeypatch.delenv('GAZEBO_MODEL_PATH', raising=False)
    package = tmp_path / 'ws' / 'src' / 'some_dir'
    write(package / 'package.xml', """<?xml version="1.0"?>
<package format="2"><name>my_gazebo_worlds</name><version>0.0.1</version>
  <export><gazebo_ros gazebo_model_path="${prefix}/models"/></export></package>""")
    make_model(package / 'models', 'exported_wall', wall())
    monkeypatch.setenv('ROS_PACKAGE_PATH', str(tmp_path / 'ws' / 'src'))
    world = load(write(tmp_path / 'w.world', world_sdf(include('model://exported_wall', pose='5 0 0 0 0 0'))))
    assert range_along_x(world) == pytest.approx(4.95, abs=1e-3)
    assert logged(world, 'WARN') == []


def test_nested_include_is_placed_in_its_parents_frame(tmp_path, model_path):
    make_model(model_path, 'post', wall(size='0.1 0.1 1'))
    world = load(write(tmp_path / 'w.world', world_sdf(f"""
<model name="fence"><static>true</static><pose>2 1 0 0 0 0</pose>
  {include('model://post', pose='0 -1 0 0 0 0', name='corner')}
  <model name="rail"><pose>0 -1 0 0 0 0</pose><link name="link">{wall(pose='3 0 0 0 0 0', size='0.1 0.1 1')}</link></model>
</model>""")))
    found = collisions(world)
    assert found['fence::corner::link::collision']['pose'][:3] == pytest.approx([2, 0, 0])
    assert found['fence::rail::link::collision']['pose'][:3] == pytest.approx([5, 0, 0])
    assert range_along_x(world) == pytest.approx(1.95, abs=1e-3)


def test_mesh_uris_resolve_against_the_file_that_names_them(tmp_path, model_path):
    model_dir = make_model(model_path, 'statue', MESH_COLLISION.format(name='body', uri='meshes/statue.stl',
                                                                       scale='2 2 2'))
    write(model_dir / 'meshes' / 'statue.stl', STL)
    write(model_dir / 'meshes' / 'base.stl', STL)
    write(tmp_path / 'worlds' / 'meshes' / 'rock.stl', STL)
    world = load(write(tmp_path / 'worlds' / 'w.world', world_sdf(f"""
{include('model://statue', pose='0 5 0 0 0 0')}
<model name="rocks"><static>true</static><link name="link">
  {MESH_COLLISION.format(name='rock', uri='meshes/rock.stl', scale='1 1 1')}
  {MESH_COLLISION.format(name='base', uri='model://statue/meshes/base.stl', scale='1 1 1')}
</link></model>""")))
    found = collisions(world)
    statue = found['statue::link::body']
    assert (statue['kind'], statue['mesh_uri'], statue['scale']) == ('mesh', 'meshes/statue.stl', [2, 2, 2])
    assert statue['mesh_file'] == str(model_dir / 'meshes' / 'statue.stl')
    assert found['rocks::link::rock']['mesh_file'] == str(tmp_path / 'worlds' / 'meshes' / 'rock.stl')
    assert found['rocks::link::base']['mesh_file'] == str(model_dir / 'meshes' / 'base.stl')
    assert not [w for w in logged(world, 'WARN') if 'not found' in w or 'not supported' in w]


def test_a_missing_mesh_is_one_warning_and_the_rest_runs(tmp_path, model_path):
    world = load(write(tmp_path / 'w.world', world_sdf(f"""
<model name="ruin"><static>true</static><link name="link">
  {MESH_COLLISION.format(name='lost', uri='meshes/gone.dae', scale='1 1 1')}
  {wall(pose='3 0 0 0 0 0')}
</link></model>""")))
    about_it = [w for w in logged(world, 'WARN') if 'meshes/gone.dae' in w]
    assert len(about_it) == 1, logged(world, 'WARN')
    assert "ruin::link::lost" in about_it[0] and 'w.world' in about_it[0] and 'left out' in about_it[0]
    assert str(tmp_path / 'meshes' / 'gone.dae') in about_it[0]  # where it looked
    assert 'ruin::link::lost' not in collisions(world)
    assert range_along_x(world) == pytest.approx(2.95, abs=1e-3)
    world.step(10)


def test_unsupported_geometry_unknown_includes_and_world_plugins_are_one_warning_each(tmp_path, model_path):
    world = load(write(tmp_path / 'w.world', world_sdf(f"""
{include('model://no_such_model', pose='1 0 0 0 0 0')}
<model name="terrain"><static>true</static><link name="link">
  <collision name="hills"><geometry><heightmap><uri>file://hills.png</uri></heightmap></geometry></collision>
  <collision name="curb"><geometry><polyline><point>0 0</point><height>1</height></polyline></geometry></collision>
  {wall(pose='3 0 0 0 0 0')}
</link></model>
<actor name="walker"/>
<plugin name="rubble" filename="libRubblePlugin.so"/>""")))
    found = logged(world, 'WARN')
    for what in ('no_such_model', 'terrain::link::hills', 'terrain::link::curb', '<actor>', 'libRubblePlugin.so'):
        about_it = [w for w in found if what in w]
        assert len(about_it) == 1, (what, found)
        assert 'w.world' in about_it[0]
    assert [w for w in found if 'heightmap' in w] and [w for w in found if 'polyline' in w]
    assert [w for w in found if 'no_such_model' in w][0].count(str(model_path)) == 1  # says where it looked
    assert set(collisions(world)) == {'ground_plane::link::collision', 'terrain::link::collision'}
    assert range_along_x(world) == pytest.approx(2.95, abs=1e-3)


def test_static_comes_from_the_include_over_the_model(tmp_path, model_path):
    make_model(model_path, 'crate', wall(), static='false')
    world = load(write(tmp_path / 'w.world', world_sdf(
        include('model://crate', pose='3 0 0 0 0 0', name='loose_crate') +
        include('model://crate', pose='3 3 0 0 0 0', name='fixed_crate', static='true'))))
    # The include's <static> decides: the loose crate is a model the world simulates (at the
    # include's pose), the fixed one scenery that never moves.
    assert world.robots == ['loose_crate']
    assert world.robot('loose_crate').base_pose()[:3] == pytest.approx([3, 0, 0])
    assert 'fixed_crate::link::collision' in collisions(world)
    assert not [name for name in collisions(world) if name.startswith('loose_crate')]


def test_a_model_that_only_wraps_static_models_is_scenery(tmp_path, model_path):
    # AWS RoboMaker's worlds name and place each static model in a <model> of their own that says
    # nothing of <static>: the nested model keeps its own, as in Gazebo, so the shelf stays put.
    make_model(model_path, 'shelf', wall(), static='true')
    make_model(model_path, 'crate', wall(size='0.2 0.2 0.2'), static='false')
    world = load(write(tmp_path / 'w.world', world_sdf(f"""
<model name="shelf_001">{include('model://shelf')}<pose>3 0 0 0 0 0</pose></model>
<model name="stack"><model name="inner"><static>true</static><link name="link">{wall(pose='0 3 0 0 0 0')}</link></model>
  {include('model://shelf', pose='0 -3 0 0 0 0')}</model>
<model name="crate_001">{include('model://crate')}<pose>0 6 1 0 0 0</pose></model>""")))
    found = collisions(world)
    assert found['shelf_001::shelf::link::collision']['pose'][:3] == pytest.approx([3, 0, 0])
    assert {'stack::inner::link::collision', 'stack::shelf::link::collision'} <= set(found)
    assert world.robots == ['crate_001']  # a wrapped model that moves still moves
    world.step(200)
    assert range_along_x(world) == pytest.approx(2.95, abs=1e-3)


def test_ground_plane_and_sun_are_built_in(tmp_path, monkeypatch):
    monkeypatch.setenv('GAZEBO_MODEL_PATH', str(tmp_path / 'empty'))
    monkeypatch.setenv('ROS_PACKAGE_PATH', str(tmp_path / 'empty'))
    world = load(write(tmp_path / 'w.world', world_sdf(include('model://ground_plane', name='floor',
                                                                pose='0 0 0.25 0 0 0'))))
    assert logged(world, 'WARN') == []
    found = collisions(world)
    assert found['ground_plane::link::collision']['kind'] == 'plane'
    assert found['floor::link::collision']['pose'][2] == pytest.approx(0.25)
    assert world.cast_ray([0, 0, 1], [0, 0, -1], 5.0) == pytest.approx(0.75, abs=1e-6)


def test_from_sdf_resolves_model_uris_too(model_path):
    make_model(model_path, 'brick_wall', wall())
    world = bullet_plant.World.from_sdf(world_sdf(include('model://brick_wall', pose='3 0 0 0 0 0')))
    world.echo = False
    assert world.file == ''
    assert range_along_x(world) == pytest.approx(2.95, abs=1e-3)


def test_malformed_world_file_names_the_file_and_line(tmp_path):
    bad = write(tmp_path / 'bad.world', '<?xml version="1.0"?>\n<sdf version="1.6">\n<world name="w">\n'
                                        '<model name="m"><static>true</static>\n</world></sdf>\n')
    with pytest.raises(bullet_plant.DescriptionError, match=r"bad\.world.* line 4"):
        bullet_plant.World.from_file(str(bad))
    with pytest.raises(bullet_plant.DescriptionError, match=r"world file '.*nowhere\.world' not found \(as given, then in GAZEBO_RESOURCE_PATH"):
        bullet_plant.World.from_file(str(tmp_path / 'nowhere.world'))


def test_malformed_model_file_names_the_model_file_and_line(tmp_path, model_path):
    write(model_path / 'broken' / 'model.config', '<model><sdf version="1.6">model.sdf</sdf></model>')
    write(model_path / 'broken' / 'model.sdf', '<sdf version="1.6">\n<model name="broken">\n<link>\n</sdf>\n')
    world = load(write(tmp_path / 'w.world', world_sdf(include('model://broken'))))
    errors = logged(world, 'ERROR')  # the include is left out; the world goes on
    assert len(errors) == 1 and re.search(r"model://broken.*broken/model\.sdf.* line 3", errors[0]), errors


def test_an_include_loop_leaves_out_its_include_and_the_world_runs(tmp_path, model_path):
    make_model(model_path, 'post', wall(pose='3 0 0 0 0 0'))
    loop_a = write(model_path / 'ring_a' / 'model.sdf', '<sdf version="1.6"><model name="ring_a">'
                   '<include><uri>model://ring_b</uri></include></model></sdf>')
    write(model_path / 'ring_b' / 'model.sdf', '<sdf version="1.6"><model name="ring_b">'
          '<include><uri>model://ring_a</uri></include></model></sdf>')
    for name in ('ring_a', 'ring_b'):
        write(model_path / name / 'model.config', f'<model><name>{name}</name><sdf version="1.6">model.sdf</sdf></model>')
    world = load(write(tmp_path / 'w.world', world_sdf(include('model://ring_a') + include('model://post'))))
    errors = logged(world, 'ERROR')
    assert len(errors) == 1 and 'model://ring_a' in errors[0] and 'include loop' in errors[0], errors
    assert str(loop_a) in errors[0] and 'ring_b' in errors[0]  # the chain of files
    assert range_along_x(world) == pytest.approx(2.95, abs=1e-3)  # the post is there


def test_a_world_read_again_reads_its_included_models_as_they_are_now(tmp_path, model_path):
    # (sdformat's reading is kept for a document read again, unless a file it includes changed)
    model_dir = make_model(model_path, 'post', wall(pose='3 0 0 0 0 0'))
    text = world_sdf(include('model://post'))
    assert range_along_x(bullet_plant.World.from_sdf(text)) == pytest.approx(2.95, abs=1e-3)
    assert range_along_x(bullet_plant.World.from_sdf(text)) == pytest.approx(2.95, abs=1e-3)
    write(model_dir / 'model.sdf', WALL_SDF.format(version='1.6', name='post', static='true', pose='0 0 0 0 0 0',
                                                   collisions=wall(pose='1.5 0 0 0 0 0')))
    assert range_along_x(bullet_plant.World.from_sdf(text)) == pytest.approx(1.45, abs=1e-3)


def test_shipped_worlds_read_by_file_as_by_text():
    import os
    for name in ('compat/gazebo_ros/worlds/empty.world', 'worlds/race_track.world'):
        path = os.path.join(REPOSITORY, name)
        by_file = load(path)
        by_text = bullet_plant.World.from_sdf(open(path).read())
        by_text.echo = False
        assert by_file.file == path
        assert by_file.static_collisions().__repr__() == by_text.static_collisions().__repr__()
        assert len(logged(by_file, 'WARN')) == len(logged(by_text, 'WARN'))
        assert math.isfinite(by_file.time_step)


def test_worlds_made_from_one_parsed_description_are_the_world_file_each_time_and_apart(tmp_path, model_path):
    # WorldDescription: a world file parsed once (a racing environment's every reset makes its
    # world from it). Each world is the one from_file makes, warnings and <model>s included, and
    # worlds made from one description share nothing that moves.
    make_model(model_path, 'wall', BOX_COLLISION.format(name='c', pose='0 0 0.5 0 0 0', size='1 0.1 1'))
    world_file = write(tmp_path / 'w.world', f"""<?xml version="1.0"?>
<sdf version="1.6"><world name="described">
  <include><uri>model://ground_plane</uri></include>
  <include><uri>model://wall</uri><pose>2 0 0 0 0 0.3</pose></include>
  <include><uri>model://nowhere</uri></include>
  <model name="crate"><pose>0 0 1 0 0 0</pose><link name="l"><inertial><mass>1</mass></inertial>
    <collision name="c"><geometry><box><size>0.2 0.2 0.2</size></box></geometry></collision></link></model>
</world></sdf>""")
    description = bullet_plant.WorldDescription.from_file(str(world_file))
    assert (description.name, description.file, description.max_step_size) == ('described', str(world_file), 0.001)
    by_file = load(str(world_file))
    made = [bullet_plant.World(description) for _ in range(2)]
    for world in made:
        world.echo = False
        assert world.file == str(world_file)
        assert repr(world.static_collisions()) == repr(by_file.static_collisions())
        assert logged(world, 'WARN') == logged(by_file, 'WARN') and logged(world, 'WARN'), 'model://nowhere, once'
    made[0].step(500)  # the crate falls in the first world only
    by_file.step(500)
    assert made[0].robot('crate').base_pose() == pytest.approx(by_file.robot('crate').base_pose(), abs=0.0)
    assert made[0].robot('crate').base_pose()[2] < 0.2 and made[1].robot('crate').base_pose()[2] == 1.0


@pytest.mark.ros
def test_node_stops_on_a_malformed_world_naming_file_and_line(ros, tmp_path):
    bad = write(tmp_path / 'bad.world', '<sdf version="1.6">\n<world name="w">\n<model name="m">\n</world></sdf>\n')
    node = ros.start(['rosrun', 'tianracer_description', 'bullet_plant', '_world_name:=' + str(bad)], 'plant')
    assert node.wait(30) == 1, node.log()
    assert re.search(r"bad\.world' is not well-formed XML: line 3", node.log()), node.log()


@pytest.mark.ros
def test_node_on_a_world_file_found_nowhere_says_so_and_runs_the_empty_world(ros, tmp_path):
    # Clearpath Jackal's empty_world.launch names $(find gazebo_ros)/worlds/empty_world.world, which no
    # gazebo_ros ships: Gazebo 11's server says it could not open the file and runs worlds/empty.world.
    missing = str(tmp_path / 'worlds' / 'empty_world.world')
    node = ros.start(['rosrun', 'tianracer_description', 'bullet_plant', '_world_name:=' + missing], 'plant')
    assert ros.service('/gazebo/get_world_properties', wait=True, timeout=30)['success'] is True
    log = node.log()
    assert 'Could not open file[%s]' % missing in log and 'Falling back on worlds/empty.world' in log, log
    ros.wait_until(lambda: ros.service('/gazebo/get_world_properties')['sim_time'] > 0, 10, 'the world to run')


@pytest.mark.ros
def test_node_resolves_a_launched_worlds_uris_against_its_file(ros, tmp_path):
    models = tmp_path / 'models'
    model_dir = make_model(models, 'statue', MESH_COLLISION.format(name='body', uri='meshes/statue.stl', scale='1 1 1'))
    write(model_dir / 'meshes' / 'statue.stl', STL)
    write(tmp_path / 'worlds' / 'meshes' / 'rock.stl', STL)
    world = write(tmp_path / 'worlds' / 'w.world', world_sdf(f"""{include('model://statue')}
<model name="rocks"><static>true</static><link name="link">
  {MESH_COLLISION.format(name='rock', uri='meshes/rock.stl', scale='1 1 1')}
  {MESH_COLLISION.format(name='lost', uri='meshes/lost.stl', scale='1 1 1')}
</link></model>"""))
    ros.env['GAZEBO_MODEL_PATH'] = str(models)
    node = ros.start(['rosrun', 'tianracer_description', 'bullet_plant', '_world_name:=' + str(world)], 'plant')
    ros.wait_until(lambda: '/gazebo/pause_physics' in ros.services(), 30, 'the plant node')
    not_found = [line for line in node.log().splitlines() if 'not found' in line]
    assert len(not_found) == 1 and 'rocks::link::lost' in not_found[0], node.log()


def test_a_saved_worlds_state_starts_its_models_where_the_state_puts_them():
    """gzclient's Save World writes each model's pose twice: its <model><pose> as loaded and the
    <state> block's, which Gazebo applies (World::SetState)."""
    box = """<link name="link"><collision name="collision"><geometry><box><size>0.2 0.2 0.2</size></box></geometry></collision></link>"""
    world = bullet_plant.World.from_sdf(f"""<sdf version="1.6"><world name="saved">
<model name="crate"><pose>0 0 0.1 0 0 0</pose>{box}</model>
<model name="still"><pose>5 0 0.1 0 0 0</pose>{box}</model>
<state world_name="saved"><sim_time>12 0</sim_time>
  <model name="crate"><pose>1 2 0.1 0 0 1.5</pose><link name="link"><pose>1 2 0.1 0 0 1.5</pose></link></model>
</state></world></sdf>""")
    world.echo = False
    assert world.robot('crate').base_pose()[:3] == pytest.approx([1, 2, 0.1])
    assert yaw_of(world.robot('crate').base_pose()) == pytest.approx(1.5)
    assert world.robot('still').base_pose()[:3] == pytest.approx([5, 0, 0.1]), 'not in the state: where the file put it'
    assert not [m for level, m in world.messages() if '<state>' in m], 'a one-link model says nothing of its link poses'
    world.step(100)
    world.reset_world()
    assert world.robot('crate').base_pose()[:3] == pytest.approx([1, 2, 0.1], abs=1e-6), 'reset_world: the state pose'


def test_real_time_update_rate_is_the_pace_gazebo_keeps():
    fast = bullet_plant.World.from_sdf("""<sdf version="1.6"><world name="w"><physics type="ode">
<max_step_size>0.002</max_step_size><real_time_update_rate>250</real_time_update_rate></physics></world></sdf>""")
    assert fast.pace == pytest.approx(0.5)
    assert bullet_plant.World().pace == pytest.approx(1.0)
    with pytest.raises(bullet_plant.DescriptionError, match='real_time_update_rate'):
        bullet_plant.World.from_sdf("""<sdf version="1.6"><world name="w"><physics type="ode">
<real_time_update_rate>-5</real_time_update_rate></physics></world></sdf>""")
