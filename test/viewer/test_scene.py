"""What a viewer draws (bullet_plant/scene.h, World.scene_json; the node publishes it on /gazebo/scene):
the world's static visuals placed in the world, each robot's link visuals in the link's frame named
as /gazebo/link_states names the links, meshes by the files they resolve to, the sun and the scene
colours; robots that come and go."""
import json
import os
import xml.etree.ElementTree as ET

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
    assert [v['normal'] for v in scene['visuals'] if v['kind'] == 'plane'] == [[0, 0, 1]]
    assert scene['world'] == 'race_track' and scene['robots'] == []
    assert scene['light_direction'] == pytest.approx([-0.5, 0.1, -0.9])
    assert scene['shadows'] is True


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
