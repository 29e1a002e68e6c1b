"""f1tenth's tracks (tianracer_description.racing.f1tenth_map): a map_server map becomes a world whose
boxes stand on the occupied cells, at their metric place and turned by the origin's yaw, under
map_server's thresholds and negate; f1tenth's centre line and race line CSVs are read and found
beside the map; the map drives RaceEnv, RaceVectorEnv and RaceParallelEnv; pure pursuit drives a
lap of worlds/peanut_map.yaml on its race line without touching a wall."""
import math
import os

import gymnasium
import numpy as np
import pytest

import tianracer_description.racing  # noqa: F401  registers the environments
from tianracer_description import bullet_plant
from tianracer_description.racing import f1tenth_map
from tianracer_description.racing.env import RaceEnv
from tianracer_description.racing.parallel_env import RaceParallelEnv
from tianracer_description.racing.pure_pursuit import PurePursuit
from tianracer_description.racing.vector_env import RaceVectorEnv
from tianracer_description.tianracer import PEANUT_MAP

PEANUT_BOXES = 232  # docs/racing.md states it: the peanut's 1,518 occupied cells merged


@pytest.fixture(scope='module', autouse=True)
def own_cache(tmp_path_factory):
    """Converted worlds go to a folder of this module's, not the user's ~/.cache."""
    with pytest.MonkeyPatch.context() as patch:
        patch.setenv('XDG_CACHE_HOME', str(tmp_path_factory.mktemp('cache')))
        yield


def write_map(folder, pixels, resolution=0.5, origin=(1.0, 2.0, 0.0), negate=0, occupied=0.65, free=0.196,
              name='small', extra=''):
    """A map of hand-made pixels (top row first) as a PGM and its YAML; the YAML's path."""
    pixels = np.asarray(pixels, np.uint8)
    with open(os.path.join(folder, name + '.pgm'), 'wb') as f:
        f.write(b'P5\n# hand-made\n%d %d\n255\n' % (pixels.shape[1], pixels.shape[0]) + pixels.tobytes())
    path = os.path.join(folder, name + '_map.yaml')
    with open(path, 'w') as f:
        f.write('image: %s.pgm\nresolution: %r\norigin: [%r, %r, %r]\nnegate: %d\noccupied_thresh: %r\n'
                'free_thresh: %r\n%s' % (name, resolution, *origin, negate, occupied, free, extra))
    return path


def test_a_pixel_is_occupied_as_map_server_reads_it(tmp_path):
    values = [[0, 89, 90, 205, 254]]  # p = (255 - v) / 255: 1.0, 0.651, 0.647, 0.196, 0.004
    spec = f1tenth_map.MapSpec(write_map(str(tmp_path), values))
    assert f1tenth_map.occupied_cells(f1tenth_map.read_image(spec.image), spec).tolist() == [[True, True, False,
                                                                                               False, False]]
    spec = f1tenth_map.MapSpec(write_map(str(tmp_path), values, negate=1))  # p = v / 255
    assert f1tenth_map.occupied_cells(np.array(values), spec).tolist() == [[False, False, False, True, True]]
    spec = f1tenth_map.MapSpec(write_map(str(tmp_path), values, occupied=0.1))
    assert f1tenth_map.occupied_cells(np.array(values), spec).tolist() == [[True, True, True, True, False]]
    # RGBA: trinary averages alpha in, as map_server does; scale leaves it out
    png = pytest.importorskip('PIL.Image')  # a PNG map (f1tenth_gym's own are PNGs) reads the same
    png.fromarray(np.array(values, np.uint8)).save(str(tmp_path / 'small.png'))
    assert np.array_equal(f1tenth_map.read_image(str(tmp_path / 'small.png')), values)
    grey_opaque = np.array([[[60, 60, 60, 255]]])  # trinary: p = 1 - 108.75 / 255 = 0.57; scale: 0.76
    assert not f1tenth_map.occupied_cells(grey_opaque, f1tenth_map.MapSpec(write_map(str(tmp_path), values)))[0, 0]
    scale = f1tenth_map.MapSpec(write_map(str(tmp_path), values, extra='mode: scale\n'))
    assert f1tenth_map.occupied_cells(grey_opaque, scale)[0, 0]


def test_occupied_cells_become_few_boxes_that_cover_them_exactly():
    ring = np.zeros((8, 10), bool)
    ring[1:7, 1:9] = True
    ring[2:6, 3:7] = False
    boxes = f1tenth_map.occupied_boxes(ring)
    assert len(boxes) == 4
    covered = np.zeros_like(ring, int)
    for r, c, h, w in boxes:
        covered[r:r + h, c:c + w] += 1
    assert np.array_equal(covered, ring.astype(int)), 'every occupied cell once, nothing else'
    assert len(f1tenth_map.occupied_boxes(np.ones((50, 3), bool))) == 1


def ray(world, origin, direction):
    return world.cast_ray((origin[0], origin[1], 0.1), (direction[0], direction[1], 0.0), 20.0)


@pytest.mark.parametrize('yaw', [0.0, math.pi / 2])
def test_the_walls_stand_on_the_occupied_cells_at_their_place_in_the_world(tmp_path, yaw):
    # 4 rows x 6 columns of 0.5 m; one occupied cell: image row 0 (the top), column 4, so in the map's
    # frame x from 2.0 to 2.5 and y from 1.5 to 2.0 above the origin's corner
    pixels = np.full((4, 6), 254)
    pixels[0, 4] = 0
    path = write_map(str(tmp_path), pixels, origin=(1.0, 2.0, yaw))
    world = bullet_plant.World.from_file(f1tenth_map.map_world_file(path))
    c, s = math.cos(yaw), math.sin(yaw)
    to_world = lambda u, v: (1.0 + c * u - s * v, 2.0 + s * u + c * v)  # noqa: E731
    along_u, along_v = (c, s), (-s, c)
    # rays along the map's axes from 1 m outside the cell's faces, at its middle
    assert ray(world, to_world(1.0, 1.75), along_u) == pytest.approx(1.0, abs=1e-3)
    assert ray(world, to_world(3.5, 1.75), (-c, -s)) == pytest.approx(1.0, abs=1e-3)
    assert ray(world, to_world(2.25, 0.5), along_v) == pytest.approx(1.0, abs=1e-3)
    assert ray(world, to_world(2.25, 3.0), (s, -c)) == pytest.approx(1.0, abs=1e-3)
    assert ray(world, to_world(1.0, 1.25), along_u) > 19.0, 'the row below the cell is free'
    height = world.cast_ray((*to_world(2.25, 1.75), 1.0), (0.0, 0.0, -1.0), 2.0)
    assert height == pytest.approx(1.0 - f1tenth_map.WALL_HEIGHT, abs=1e-3)


def test_f1tenths_centre_line_and_race_line_are_read_and_found_beside_the_map(tmp_path):
    path = write_map(str(tmp_path), np.full((4, 6), 254), name='Oval')
    loop = [(math.cos(a), math.sin(a)) for a in np.linspace(0, 2 * math.pi, 40, endpoint=False)]
    with pytest.raises(FileNotFoundError, match='Oval_centerline.csv.*Oval_raceline.csv.*centerline='):
        f1tenth_map.MapTrack(path)
    with open(tmp_path / 'Oval_raceline.csv', 'w') as f:
        f.write('# an id\n# s_m; x_m; y_m; psi_rad; kappa_radpm; vx_mps; ax_mps2\n')
        f.writelines('%f;%f;%f;0;1;%f;0\n' % (k * 0.157, x, y, 1.0 + k / 40) for k, (x, y) in enumerate(loop))
    track = f1tenth_map.MapTrack(path)
    assert track.centerline is track.raceline, 'the race line measures progress where there is no centre line'
    assert track.raceline.vxs[10] == pytest.approx(1.25)
    with open(tmp_path / 'Oval_centerline.csv', 'w') as f:
        f.write('# x_m, y_m, w_tr_right_m, w_tr_left_m\n')
        f.writelines('%f, %f, 0.5, 0.5\n' % (2 * x, 2 * y) for x, y in loop + loop[:1])  # closed: first again
    track = f1tenth_map.MapTrack(path)
    assert len(track.centerline.xs) == 40 and track.centerline.xs[0] == pytest.approx(2.0)
    assert track.raceline.xs[0] == pytest.approx(1.0)
    assert f1tenth_map.MapTrack(path, centerline=str(tmp_path / 'Oval_raceline.csv')).centerline.xs[0] == 1.0
    with open(tmp_path / 'bad.csv', 'w') as f:
        f.write('1;2;3\n4;5;6\n7;8;9\n')
    with pytest.raises(ValueError, match='bad.csv has 3 columns.*s_m; x_m; y_m'):
        f1tenth_map.read_line(str(tmp_path / 'bad.csv'))


def test_a_map_without_what_map_server_needs_names_the_file_and_the_key(tmp_path):
    path = tmp_path / 'broken.yaml'
    path.write_text('image: nowhere.pgm\nresolution: 0.05\norigin: [0, 0, 0]\nnegate: 0\n')
    with pytest.raises(ValueError, match='broken.yaml lacks occupied_thresh, free_thresh'):
        f1tenth_map.MapSpec(str(path))
    path.write_text(path.read_text() + 'occupied_thresh: 0.65\nfree_thresh: 0.196\n')
    with pytest.raises(FileNotFoundError, match='no map image at .*nowhere.pgm'):
        f1tenth_map.map_world_file(str(path))
    with pytest.raises(FileNotFoundError, match='no map at .*absent.yaml'):
        RaceEnv(map=str(tmp_path / 'absent.yaml'))


def test_the_peanuts_walls_are_the_lane_width_apart_along_its_centre_line():
    spec = f1tenth_map.MapSpec(PEANUT_MAP)
    text, boxes = f1tenth_map.map_world_sdf(spec)
    assert boxes == PEANUT_BOXES
    world = bullet_plant.World.from_file(f1tenth_map.map_world_file(PEANUT_MAP))
    line = f1tenth_map.read_centerline(os.path.join(os.path.dirname(PEANUT_MAP), 'peanut_centerline.csv'))
    points = line.points
    for k in range(0, len(points), 20):
        (x, y), (nx, ny) = points[k], points[(k + 1) % len(points)]
        yaw = math.atan2(ny - y, nx - x)
        left = (-math.sin(yaw), math.cos(yaw))
        # 0.6 m to a wall either side: the cells within it are free; a pixel (5 cm) of staircase
        assert ray(world, (x, y), left) == pytest.approx(0.6, abs=0.05), k
        assert ray(world, (x, y), (-left[0], -left[1])) == pytest.approx(0.6, abs=0.05), k


def test_the_map_drives_the_single_the_vector_and_the_parallel_environments():
    env = gymnasium.make('Tianracer-Map-v0', observe_pose=True)  # worlds/peanut_map.yaml by default
    assert env.unwrapped.track.map.name == 'peanut'
    observation, info = env.reset(seed=0)
    assert np.abs(observation['pose'][:2]).max() < 0.25, 'at the centre line\'s start, the origin'
    gained = 0.0
    for _ in range(20):
        observation, reward, terminated, _, info = env.step(np.array([0.0, 0.5], np.float32))
        gained += reward
    assert not terminated and 0.05 < gained < 0.5
    envs = gymnasium.make_vec('Tianracer-Map-v0', num_envs=2, map=PEANUT_MAP)
    assert isinstance(envs.unwrapped, RaceVectorEnv)
    envs.reset(seed=1)
    for _ in range(20):
        _, rewards, terminated, _, _ = envs.step(np.tile([0.0, 0.5], (2, 1)).astype(np.float32))
    assert not terminated.any() and (rewards > 0).all()
    race = RaceParallelEnv(map=PEANUT_MAP, cars=2)
    observations, _ = race.reset(seed=2)
    for _ in range(20):
        observations, rewards, terminations, _, _ = race.step({a: np.array([0.0, 0.5], np.float32) for a in race.agents})
    assert not any(terminations.values()) and all(r > 0 for r in rewards.values())
    with pytest.raises(ValueError, match='world_file= or map=, not both'):
        RaceEnv(world_file=env.unwrapped.track.world_file, map=PEANUT_MAP)


def test_pure_pursuit_drives_a_lap_of_the_peanut_on_its_race_line():
    env = gymnasium.make('Tianracer-Map-v0', observe_pose=True)
    policy = PurePursuit.for_env(env)
    assert policy.speeds is not None and len(policy.waypoints) > 300, 'the race line, with its speeds'
    observation, info = env.reset(seed=0)
    while info['laps'] < 1.0:
        observation, reward, terminated, truncated, info = env.step(policy(observation))
        assert not terminated, 'touched a wall at %s' % observation['pose']
        assert not truncated, 'no lap in 20 s: %s' % info
    assert info['time'] < 15.0, 'a 19 m lap at 1.5-2 m/s'
    with pytest.raises(ValueError, match='observe_pose=True'):
        PurePursuit.for_env(gymnasium.make('Tianracer-Map-v0'))
