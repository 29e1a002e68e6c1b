"""What a viewer draws (bullet_plant/scene.h, World.scene_json; the node publishes it on /gazebo/scene):
the world's static visuals placed in the world, each robot's link visuals in the link's frame named
as /gazebo/link_states names the links, meshes by the files they resolve to with their materials, the
world's lights (each as its file gives it) and the scene colours; robots that come and go."""
import json
import os
import xml.etree.ElementTree as ET

import numpy as np
import pytest

from plant_helpers import TRACK_WORLD, find_fixture_packages
from tianracer_description import bullet_plant
from tianracer_description.tianracer import RACE_TRACK_WORLD


def scene_of(world):
    return json.loads(world.scene_json())


@pytest.fixture
def race_track():
    world = bullet_plant.World.from_file(RACE_TRACK_WORLD)
    world.echo = False
    return world


def test_the_race_tracks_walls_ground_and_light_are_in_the_scene(race_track):
    scene = scene_of(race_track)
    root = ET.parse(RACE_TRACK_WORLD).getroot()
    boxes = {m.get('name'): m for m in root.iter('model') if m.find('link/visual/geometry/box') is not None}
    drawn = {v['link'].split('::')[0]: v for v in scene['visuals'] if v['kind'] == 'box'}
    assert set(drawn) == set(boxes)
    for name, model in boxes.items():
        v = drawn[name]
        assert v['model'] == '' and v['size'] == pytest.approx(list(map(float, model.findtext(
            'link/visual/geometry/box/size').split())))
        assert v['pose'][:3] == pytest.approx(list(map(float, model.findtext('pose').split()[:3])))
        assert v['colour'][:3] == pytest.approx(list(map(float, model.findtext(
            'link/visual/material/diffuse').split()[:3])), abs=1e-6)
        for colour in ('ambient', 'diffuse'):
            assert v['material'][colour][:3] == pytest.approx(list(map(float, model.findtext(
                'link/visual/material/' + colour).split()[:3])), abs=1e-6)
        assert v['material']['specular'][:3] == [0, 0, 0] and v['material']['shininess'] == 0
    planes = [v for v in scene['visuals'] if v['kind'] == 'plane']
    assert [v['normal'] for v in planes] == [[0, 0, 1]]
    # the ground plane's Gazebo/Grey
    assert planes[0]['material']['ambient'][:3] == pytest.approx([0.3] * 3)
    assert planes[0]['material']['diffuse'][:3] == pytest.approx([0.7] * 3)
    assert scene['world'] == 'race_track' and scene['robots'] == []
    # model://sun: Gazebo's sun, the world's only light; SDF's default ambient light
    assert [light['name'] for light in scene['lights']] == ['sun']
    sun = scene['lights'][0]
    assert sun['type'] == 'directional' and sun['cast_shadows'] is True
    assert sun['direction'] == pytest.approx(list(np.array([-0.5, 0.1, -0.9]) / np.linalg.norm([-0.5, 0.1, -0.9])))
    assert sun['diffuse'] == pytest.approx([0.8] * 3) and sun['specular'] == pytest.approx([0.2] * 3)
    assert scene['ambient'] == pytest.approx([0.4] * 3)
    assert scene['shadows'] is True


def test_the_scene_carries_each_light_and_material_as_the_world_gives_them():
    world = bullet_plant.World.from_sdf("""<sdf version="1.6"><world name="lit">
<scene><ambient>0.1 0.2 0.3 1</ambient></scene>
<light name="lamp" type="point"><pose>1 2 3 0 0 0</pose><diffuse>0.5 0.4 0.3 1</diffuse><specular>0.2 0.2 0.2 1</specular>
  <attenuation><range>20</range><constant>0.32</constant><linear>0.01</linear><quadratic>0.03</quadratic></attenuation></light>
<light name="spot" type="spot"><pose>0 0 2 0 0 0</pose><direction>0 0 -2</direction>
  <attenuation><range>5</range><constant>1</constant><linear>0</linear><quadratic>0</quadratic></attenuation>
  <spot><inner_angle>0.5</inner_angle><outer_angle>1.0</outer_angle><falloff>2</falloff></spot></light>
<model name="lantern"><static>true</static><link name="link"><visual name="visual"><geometry><sphere><radius>0.1</radius></sphere></geometry>
  <material><diffuse>1 0.9 0.6 0.5</diffuse><specular>0.5 0.5 0.5 1</specular><shininess>30</shininess>
  <emissive>0.8 0.7 0.2 1</emissive></material></visual></link></model>
</world></sdf>""")
    world.echo = False
    scene = scene_of(world)
    assert scene['ambient'] == pytest.approx([0.1, 0.2, 0.3])
    lamp, spot = scene['lights']
    assert (lamp['name'], lamp['type'], spot['name'], spot['type']) == ('lamp', 'point', 'spot', 'spot')
    assert lamp['position'] == pytest.approx([1, 2, 3]) and lamp['diffuse'] == pytest.approx([0.5, 0.4, 0.3])
    assert lamp['specular'] == pytest.approx([0.2] * 3)
    assert lamp['attenuation'] == pytest.approx([20, 0.32, 0.01, 0.03])
    assert spot['direction'] == pytest.approx([0, 0, -1]) and spot['spot'] == pytest.approx([0.5, 1.0, 2])
    assert spot['diffuse'] == pytest.approx([1, 1, 1]) and spot['cast_shadows'] is False  # SDF's defaults
    lantern = next(v for v in scene['visuals'] if v['link'] == 'lantern::link::visual')['material']
    # <diffuse> given: a fresh OGRE pass, its ambient white; its alpha the visual's opacity
    assert lantern['ambient'][:3] == [1, 1, 1] and lantern['diffuse'] == pytest.approx([1, 0.9, 0.6, 0.5])
    assert lantern['specular'][:3] == pytest.approx([0.5] * 3) and lantern['shininess'] == 30
    assert lantern['emissive'][:3] == pytest.approx([0.8, 0.7, 0.2])


def test_a_robots_links_are_in_the_scene_as_link_states_names_them_until_it_goes(race_track, urdf_xml):
    race_track.spawn(urdf_xml, 'tianracer', pose=(0, 0, 0.05, 0, 0, 0))
    scene = scene_of(race_track)
    assert scene['robots'] == ['tianracer']
    assert scene['root_links'] == ['tianracer::base_footprint']  # the URDF's root: its pose is the model's
    car = [v for v in scene['visuals'] if v['model'] == 'tianracer']
    links = {link.get('name') for link in ET.fromstring(urdf_xml).iter('link') if link.find('visual') is not None}
    assert {v['link'] for v in car} == {'tianracer::' + name for name in links}
    # in the link's frame: a wheel's cylinder turned about x, at the link's origin
    wheel = next(v for v in car if v['link'] == 'tianracer::left_rear_wheel')
    assert wheel['kind'] == 'cylinder' and wheel['pose'][:3] == pytest.approx([0, 0, 0])
    assert abs(wheel['pose'][3]) == pytest.approx(2 ** -0.5)
    race_track.remove('tianracer')
    assert [v for v in scene_of(race_track)['visuals'] if v['model']] == [] and scene_of(race_track)['robots'] == []


def test_meshes_are_named_by_the_files_they_resolve_to_with_their_scale(monkeypatch):
    find_fixture_packages(monkeypatch)
    world = bullet_plant.World.from_file(TRACK_WORLD)
    world.echo = False
    meshes = [v for v in scene_of(world)['visuals'] if v['kind'] == 'mesh']
    assert sorted(os.path.basename(v['mesh']) for v in meshes) == ['floor.dae', 'walls.stl']
    for v in meshes:
        assert os.path.isabs(v['mesh']) and os.path.isfile(v['mesh'])
        assert v['scale'] == [1, 1, 1]
        assert v['pose'][2] == pytest.approx(0.5)  # the include's pose lifts the track
    # each named material of a mesh file as the cameras draw it: the Collada floor's effect
    floor = next(v for v in meshes if v['mesh'].endswith('floor.dae'))
    assert [m['material']['diffuse'][:3] for m in floor['mesh_materials']] == [pytest.approx([0.3, 0.3, 0.32])]
