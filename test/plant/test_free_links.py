"""A model as Gazebo makes it: links that no joint joins are free bodies of that one model (a robot
maker's race track of a floor link and a wall link, a pile of boxes in one <model>), each moving on
its own, listed, moved, reset and removed with the model; and a moving link's mesh collides where its
triangles are (its hull where it is convex, its convex pieces' hulls, or the triangles themselves)."""
import gymnasium
import numpy as np
import pytest

import tianracer_description.racing  # noqa: F401  (registers the environments)
from mesh_models import (FLOOR_THICKNESS, RACE_TRACK_CENTERLINE, TRACK_LINK_MASS, box_triangles,
                         u_channel_triangles, write_mesh_race_track, write_stl)
from plant_helpers import sdf_world
from tianracer_description import bullet_plant
from tianracer_description.racing.follow_the_gap import FollowTheGap

BOX = 0.2  # m, the free boxes' side


def free_boxes_model(name='boxes', self_collide=False):
    """One model, not static, of three 1 kg boxes that no joint joins, dropped from 0.5, 1 and 1.5 m
    above the ground, 1 m apart (link poses in the model frame, which the model's pose moves)."""
    links = ''.join(f"""
      <link name="box_{i}"><pose>{i} 0 {0.5 * (i + 1)} 0 0 0</pose>
        <inertial><mass>1</mass><inertia><ixx>0.0067</ixx><iyy>0.0067</iyy><izz>0.0067</izz></inertia></inertial>
        <collision name="collision"><geometry><box><size>{BOX} {BOX} {BOX}</size></box></geometry></collision>
        <visual name="visual"><geometry><box><size>{BOX} {BOX} {BOX}</size></box></geometry></visual>
      </link>""" for i in range(3))
    return f"""<model name="{name}"><pose>1 2 0 0 0 0</pose>
      <self_collide>{'true' if self_collide else 'false'}</self_collide>{links}
    </model>"""


def quiet(world):
    world.echo = False
    return world


def problems(world):
    return [text for level, text in world.messages() if level in ('WARN', 'ERROR')]


def test_three_free_boxes_are_one_model_and_each_falls_and_rests_on_its_own():
    world = quiet(bullet_plant.World.from_sdf(sdf_world(free_boxes_model())))
    assert not problems(world)
    assert world.robots == ['boxes'], 'one model'
    boxes = world.robot('boxes')
    assert sorted(boxes.link_names) == ['box_0', 'box_1', 'box_2']
    # Each falls on its own: after 0.35 s the one dropped from 0.5 m has landed, the others fall on.
    world.step(350)
    heights = [boxes.link_pose(f'box_{i}')[2] for i in range(3)]
    assert heights[0] == pytest.approx(BOX / 2, abs=2e-3)
    assert heights[1] > 0.3 and heights[2] > 0.8, heights
    world.step(2650)
    for i in range(3):
        x, y, z = boxes.link_pose(f'box_{i}')[:3]
        assert (x, y, z) == pytest.approx((1 + i, 2, BOX / 2), abs=2e-3), f'box_{i} rests where it fell'
    # The model frame follows its canonical link (its first), 0.5 m below box_0 as the file has it:
    # what get_model_state reports.
    model, canonical = boxes.base_pose(), boxes.link_pose('box_0')
    np.testing.assert_allclose(model[:3], np.add(canonical[:3], (0, 0, -0.5)), atol=1e-6)
    np.testing.assert_allclose(model[3:], canonical[3:], atol=1e-9)


def test_a_models_free_links_move_reset_and_go_with_it():
    world = quiet(bullet_plant.World.from_sdf(sdf_world(free_boxes_model())))
    boxes = world.robot('boxes')
    world.step(3000)
    # set_model_state moves every link with the model, rigidly.
    boxes.set_model_state([5, 5, BOX / 2 - 0.5, 0, 0, 0, 1])  # the model frame: box_0 0.5 m above it
    for i in range(3):
        assert boxes.link_pose(f'box_{i}')[:3] == pytest.approx((5 + i, 5, BOX / 2), abs=2e-3)
    # set_link_state moves that link alone.
    boxes.set_link_state('box_2', [9, 9, 1, 0, 0, 0, 1])
    assert boxes.link_pose('box_2')[:3] == pytest.approx((9, 9, 1))
    assert boxes.link_pose('box_1')[:3] == pytest.approx((6, 5, BOX / 2), abs=2e-3)
    # reset_world puts each back where the file put it.
    world.reset_world()
    for i in range(3):
        assert boxes.link_pose(f'box_{i}')[:3] == pytest.approx((1 + i, 2, 0.5 * (i + 1)), abs=1e-6)
    # Removing the model takes every link out: rays pass where the boxes were.
    world.step(3000)
    assert world.cast_ray((3, 2, 1), (0, 0, -1), 5.0) == pytest.approx(1 - BOX, abs=2e-3)
    assert world.remove('boxes')
    assert world.robots == []
    world.step(1)
    assert world.cast_ray((3, 2, 1), (0, 0, -1), 5.0) == pytest.approx(1.0, abs=1e-4), 'the ground, not a box'


def test_a_models_free_links_pass_through_each_other_unless_it_self_collides():
    # Gazebo collides a model's links with each other only where <self_collide> says so: box_2
    # dropped onto box_1 falls through it to the ground, or rests on it.
    for self_collide, height in ((False, BOX / 2), (True, 3 * BOX / 2)):
        model = free_boxes_model(self_collide=self_collide).replace('<pose>2 0 1.5', '<pose>1 0 1.5')
        world = quiet(bullet_plant.World.from_sdf(sdf_world(model)))
        world.step(3000)
        z = world.robot('boxes').link_pose('box_2')[2]
        assert z == pytest.approx(height, abs=5e-3), f'self_collide {self_collide}'


@pytest.fixture(params=[True, False], ids=['may sleep', 'awake'])
def heavy_meshes(tmp_path, request):
    """1665 kg mesh links resting on the ground: a U-shaped channel (no convex shape makes it up), a thin
    slab (convex, but too thin for an exact hull contact) and a block (its convex hull)."""
    write_stl(tmp_path / 'channel.stl', u_channel_triangles())
    write_stl(tmp_path / 'slab.stl', box_triangles((0, 0, 0.025), (2.0, 1.0, 0.05)))
    write_stl(tmp_path / 'block.stl', box_triangles((0, 0, 0.15), (0.6, 0.4, 0.3)))
    inertia = '<inertia><ixx>100</ixx><iyy>100</iyy><izz>100</izz></inertia>'

    def mesh_model(name, mesh, x):
        return f"""<model name="{name}"><pose>{x} 0 0 0 0 0</pose>
          <allow_auto_disable>{str(request.param).lower()}</allow_auto_disable><link name="link">
          <inertial><mass>{TRACK_LINK_MASS}</mass>{inertia}</inertial>
          <collision name="collision"><geometry><mesh><uri>{tmp_path / mesh}</uri></mesh></geometry></collision>
        </link></model>"""

    return sdf_world(mesh_model('channel', 'channel.stl', 0) + mesh_model('slab', 'slab.stl', 3) +
                     mesh_model('block', 'block.stl', 6))


def test_heavy_mesh_bodies_rest_on_the_ground_without_creeping_and_collide_as_their_triangles(heavy_meshes):
    world = quiet(bullet_plant.World.from_sdf(heavy_meshes))
    infos = [text for level, text in world.messages() if level == 'INFO']
    assert any("'channel'" in text and 'GImpact: no convex shapes' in text for text in infos), infos
    assert any("'slab'" in text and 'GImpact: a convex piece of it is too thin' in text for text in infos), infos
    assert any("'block'" in text and 'is convex: collides as its convex hull' in text for text in infos), infos
    names = ('channel', 'slab', 'block')
    start = {name: np.array(world.robot(name).base_pose()) for name in names}
    world.step(60000)  # 60 s
    for name in names:
        moved = np.linalg.norm(np.array(world.robot(name).base_pose())[:3] - start[name][:3])
        assert moved < 1e-3, f'{name} moved {moved * 1000:.2f} mm in 60 s'
    # A box dropped into the channel lands on its floor (0.1 m), between its walls: the channel's
    # hull would hold it up at the walls' tops (0.4 m).
    world.spawn(f"""<sdf version="1.6"><model name="box"><link name="link">
      <inertial><mass>1</mass><inertia><ixx>0.0067</ixx><iyy>0.0067</iyy><izz>0.0067</izz></inertia></inertial>
      <collision name="collision"><geometry><box><size>{BOX} {BOX} {BOX}</size></box></geometry></collision>
      </link></model></sdf>""", 'box', pose=(0, 0, 0.8, 0, 0, 0))
    world.step(2000)
    x, y, z = world.robot('box').base_pose()[:3]
    assert z == pytest.approx(0.1 + BOX / 2, abs=3e-3) and abs(y) < 0.2, (x, y, z)
    assert not problems(world)


def test_a_race_track_of_two_free_mesh_links_stays_put_and_follow_the_gap_laps_it(tmp_path):
    """A robot maker's race track as its Gazebo world has it: one model that is not static, its floor and
    its walls two 1665 kg mesh links that no joint joins. The car stands on the floor link, its lidar
    sees the walls, follow the gap laps it for 60 s without touching one, and the track stays where
    its file and <state> put it."""
    world_file = write_mesh_race_track(str(tmp_path))
    env = gymnasium.make('Tianracer-RaceTrack-v0', world_file=world_file, centerline=RACE_TRACK_CENTERLINE,
                         max_episode_steps=6000)  # 60 s of 10 ms steps
    policy = FollowTheGap.for_env(env)
    observation, _ = env.reset(seed=0)
    world = env.unwrapped._cars.worlds[0]
    assert not problems(world), 'the track is simulated whole'
    infos = [text for level, text in world.messages() if level == 'INFO']
    assert any("'wall_link'" in text and 'walls.stl' in text and 'GImpact' in text for text in infos), infos
    track = world.robot('race_track')
    assert sorted(track.link_names) == ['base_link', 'wall_link']
    start = {link: np.array(track.link_pose(link)) for link in ('base_link', 'wall_link')}
    assert world.robot('car').base_pose()[2] == pytest.approx(FLOOR_THICKNESS, abs=1e-3), 'stands on the floor link'
    nearest = np.inf
    while True:
        observation, _, terminated, truncated, info = env.step(policy(observation))
        nearest = min(nearest, float(np.min(observation['scan'])))
        if terminated or truncated:
            break
    assert truncated and not terminated, 'the time limit, not a wall: %s' % info
    assert info['laps'] > 3.0, info
    assert nearest < 0.6, 'the lidar sees the walls (the lane is 1.2 m wide): nearest %.2f m' % nearest
    for link in ('base_link', 'wall_link'):
        moved = np.linalg.norm(np.array(track.link_pose(link))[:3] - start[link][:3])
        assert moved < 0.01, f'{link} moved {moved * 1000:.1f} mm in 60 s'
        assert track.link_pose(link)[:3] == pytest.approx((0, 0, 0), abs=0.01), 'where the file put it'


def test_a_link_with_a_mesh_of_convex_pieces_names_their_contacts_by_its_collision(tmp_path):
    # Two 0.2 m cubes 1 m apart in one STL (two convex pieces: a compound of two hulls) beside a
    # handle box on top, in one link: each contact with the ground names the mesh's collision.
    write_stl(tmp_path / 'feet.stl', box_triangles((-0.5, 0, 0.1), (0.2, 0.2, 0.2)) +
              box_triangles((0.5, 0, 0.1), (0.2, 0.2, 0.2)))
    tray = f"""<model name="tray"><pose>0 0 0.05 0 0 0</pose><link name="link">
      <inertial><mass>2</mass><inertia><ixx>0.2</ixx><iyy>0.2</iyy><izz>0.2</izz></inertia></inertial>
      <collision name="feet"><geometry><mesh><uri>{tmp_path / 'feet.stl'}</uri></mesh></geometry></collision>
      <collision name="handle"><pose>0 0 0.3 0 0 0</pose><geometry><box><size>1.2 0.1 0.1</size></box></geometry></collision>
    </link></model>"""
    world = quiet(bullet_plant.World.from_sdf(sdf_world(tray)))
    infos = [text for level, text in world.messages() if level == 'INFO']
    assert any('feet.stl' in text and 'is 2 convex pieces' in text for text in infos), infos
    world.step(500)
    assert world.robot('tray').base_pose()[2] == pytest.approx(0.0, abs=2e-3), 'rests on its feet'
    names = {c['collision1'] for c in world.contacts()} | {c['collision2'] for c in world.contacts()}
    assert names == {'tray::link::feet', 'ground_plane::link::collision'}, names
