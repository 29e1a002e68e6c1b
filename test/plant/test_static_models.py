"""A world file's static models are models, as Gazebo has them: listed with their links, moved by
set_model_state as Gazebo moves a static model (a teleport: its collisions, what lidars and cameras see
of it following), removed with everything of theirs, put back by reset_world; the world's static scene
is made again once a change, and what rested on a static model that went falls."""
import json

import numpy as np
import pytest

from plant_helpers import box_model, sdf_world
from tianracer_description import bullet_plant

WALL = box_model('wall', (0.2, 2.0, 1.0), (2.0, 0.0, 0.5))          # 1.8 m in front of a ray from x = 0
MARKER = box_model('marker', (0.2, 0.2, 0.2), (-2.0, 0.0, 0.1))     # a goal marker behind it
CRATE = """<model name="crate"><pose>2 0 1.2 0 0 0</pose><link name="body">
  <inertial><mass>1</mass><inertia><ixx>0.0067</ixx><iyy>0.0067</iyy><izz>0.0067</izz></inertia></inertial>
  <collision name="shell"><geometry><box><size>0.2 0.2 0.2</size></box></geometry></collision></link></model>"""


@pytest.fixture
def world():
    w = bullet_plant.World.from_sdf(sdf_world(WALL + MARKER + CRATE))
    w.echo = False
    return w


def ray(world, direction):
    return world.cast_ray((0, 0, 0.1), direction, 10.0)


def test_static_models_are_listed_with_their_links(world):
    names = [m['name'] for m in world.static_models]
    assert names == ['ground_plane', 'wall', 'marker']
    wall = world.static_models[1]
    np.testing.assert_allclose(wall['pose'][:3], (2.0, 0.0, 0.5))
    assert list(wall['links']) == ['link']
    assert world.robots == ['crate'], 'the moving model is a robot; static ones are not'
    with pytest.raises(bullet_plant.DescriptionError, match="'wall' is already in the world"):
        world.spawn(CRATE.replace('crate', 'x'), 'wall', pose=(0, 5, 1, 0, 0, 0))


def test_the_viewers_scene_draws_a_static_model_where_it_is_and_not_once_removed():
    sign = MARKER.replace('</collision>', '</collision><visual name="look"><geometry><box><size>0.2 0.2 0.2</size>'
                                          '</box></geometry></visual>')
    world = bullet_plant.World.from_sdf(sdf_world(sign))
    world.echo = False

    def drawn():
        return {v['link']: v['pose'][:3] for v in json.loads(world.scene_json())['visuals'] if v['link'].startswith('marker')}

    assert drawn() == {'marker::link::look': pytest.approx([-2.0, 0.0, 0.1])}
    world.move_static_model('marker', [4.0, 1.0, 0.1, 0, 0, 0, 1])
    assert drawn() == {'marker::link::look': pytest.approx([4.0, 1.0, 0.1])}
    world.remove('marker')
    assert drawn() == {}


def test_a_static_model_moved_is_where_rays_and_bodies_meet_it(world):
    world.step(1000)  # the crate rests on the wall's top
    assert world.robot('crate').base_pose()[2] == pytest.approx(1.1, abs=2e-3)
    assert ray(world, (-1, 0, 0)) == pytest.approx(1.9, abs=1e-3)
    world.move_static_model('marker', [-1.0, 0.0, 0.1, 0, 0, 0, 1])
    assert ray(world, (-1, 0, 0)) == pytest.approx(0.9, abs=1e-3), 'the marker where it was put'
    np.testing.assert_allclose(world.static_models[2]['links']['link'][:3], (-1.0, 0.0, 0.1))
    # The wall slides 3 m sideways: the crate that rested on it falls to the ground, rays pass.
    world.move_static_model('wall', [2.0, 3.0, 0.5, 0, 0, 0, 1])
    assert np.isinf(ray(world, (1, 0, 0)))
    world.step(1000)
    assert world.robot('crate').base_pose()[2] == pytest.approx(0.1, abs=2e-3), 'fell where the wall was'
    # reset_world puts the static models back where the file put them.
    world.reset_world()
    assert ray(world, (1, 0, 0)) == pytest.approx(1.9, abs=1e-3)
    assert ray(world, (-1, 0, 0)) == pytest.approx(1.9, abs=1e-3)


def test_a_static_model_removed_takes_its_collisions_and_what_sensors_see(world):
    world.step(1000)
    assert world.remove('wall')
    assert [m['name'] for m in world.static_models] == ['ground_plane', 'marker']
    assert np.isinf(ray(world, (1, 0, 0))), 'the lidar sees through where it was'
    world.step(1000)
    assert world.robot('crate').base_pose()[2] == pytest.approx(0.1, abs=2e-3), 'what rested on it fell'
    world.reset_world()
    assert 'wall' not in [m['name'] for m in world.static_models], 'a removed model stays removed'
    assert not world.remove('wall')
    assert world.remove('ground_plane')
    world.step(1000)  # reset_world put the crate back up at 1.2 m
    assert world.robot('crate').base_pose()[2] < -1.0, 'nothing under it now'
    with pytest.raises(KeyError, match="no static model named 'wall'"):
        world.move_static_model('wall', [0, 0, 0, 0, 0, 0, 1])


def test_cameras_see_a_static_model_where_it_is_and_not_once_removed():
    # A depth camera 1 m up looking along x at a static sign 3 m off (its visual's near face 2.9 m).
    eye = """<model name="eye"><static>true</static><pose>0 0 1 0 0 0</pose><link name="eye">
      <sensor name="depth" type="depth"><update_rate>100</update_rate><camera><horizontal_fov>0.3</horizontal_fov>
        <image><width>32</width><height>32</height><format>R8G8B8</format></image><clip><near>0.1</near><far>20</far></clip>
      </camera></sensor></link></model>"""
    sign = """<model name="sign"><static>true</static><pose>3 0 1 0 0 0</pose><link name="board">
      <visual name="face"><geometry><box><size>0.2 2 2</size></box></geometry>
        <material><diffuse>1 0 0 1</diffuse></material></visual></link></model>"""
    world = bullet_plant.World.from_sdf(sdf_world(eye + sign))
    world.echo = False
    camera = world.robot('eye')
    camera.enable_sensor('depth')

    def centre_depth():
        world.step(10)
        frame = camera.image('depth')
        assert frame is not None, [text for _, text in world.messages() if 'cameras' in text]
        return float(frame['depth'][16, 16])

    assert centre_depth() == pytest.approx(2.9, abs=0.01)
    world.move_static_model('sign', [6.0, 0.0, 1.0, 0, 0, 0, 1])
    assert centre_depth() == pytest.approx(5.9, abs=0.02), 'seen where it was moved'
    world.reset_world()
    assert centre_depth() == pytest.approx(2.9, abs=0.01)
    world.remove('sign')
    assert not np.isfinite(centre_depth()), 'nothing where it was'
