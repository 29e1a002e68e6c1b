"""The racing environments' views (racing/views.py): the top-down image (walls where the world file
puts them, the car's rectangle at its pose and heading, its lidar's hits on the walls, the centre
line and a map's race line), its determinism, the chase camera, RaceVectorEnv's and
RaceParallelEnv's frames, a video by gymnasium's RecordVideo, and render_mode "human" (a window
under Xvfb; a clear error without a display)."""
import math
import os
import shutil
import subprocess
import sys

import gymnasium
import numpy as np
import pytest

import tianracer_description.racing  # noqa: F401  registers the environments
from tianracer_description.racing import views
from tianracer_description.racing.env import RaceEnv
from tianracer_description.racing.parallel_env import RaceParallelEnv
from tianracer_description.tianracer import PEANUT_MAP, RACE_TRACK_WORLD


def coloured(image, colour):
    """Where `image` is `colour`: a boolean mask."""
    return np.all(image == np.array(colour, np.uint8), axis=-1)


def colour_at(env, frame, x, y):
    row, column = env.unwrapped._views.top_down.pixel(x, y)
    return tuple(int(v) for v in frame[row, column])


@pytest.fixture(scope='module')
def env():
    env = RaceEnv(RACE_TRACK_WORLD, render_mode='rgb_array', view='top_down')
    yield env
    env.close()


def test_walls_where_the_world_file_puts_them(env):
    env.reset(seed=0)
    frame = env.render()
    assert frame.dtype == np.uint8 and frame.shape[2] == 3
    assert frame.shape[0] % views.TOP_DOWN_ALIGN == 0 and frame.shape[1] % views.TOP_DOWN_ALIGN == 0
    assert env.unwrapped._views.top_down.scale == views.TOP_DOWN_SCALE
    # worlds/race_track.world: the straights' walls are 6.05 m long at y = -0.6 and y = +0.6; in a
    # frame the lidar's hits are drawn over the walls they hit, the background has the walls alone
    background = env.unwrapped._views.top_down.background
    for x in np.linspace(-2.9, 2.9, 12):
        for y in (-0.6, 0.6):
            assert colour_at(env, background, x, y) == views.WALL
            assert colour_at(env, frame, x, y) in (views.WALL, views.SCAN)
    assert colour_at(env, frame, 1.5, -0.3) == views.FLOOR  # between the wall and the centre line
    assert colour_at(env, frame, 0.0, 2.0) == views.FLOOR   # inside the inner walls, off the track
    assert colour_at(env, frame, 1.5, 0.0) == views.CENTERLINE
    centerline = env.unwrapped.track.centerline.points
    far = centerline[np.hypot(centerline[:, 0], centerline[:, 1]) > 1.0]  # away from the car at the start
    drawn = [colour_at(env, frame, x, y) == views.CENTERLINE for x, y in far]
    assert np.mean(drawn) > 0.95


def test_the_car_at_its_pose_and_heading_with_its_scan(env):
    track = env.unwrapped.track
    x, y, yaw = track.centerline.pose_at(track.centerline.length * 0.3, 0.0)  # in the east bend, heading north-west
    env.reset(seed=0, options={'pose': (x, y, yaw)})
    for _ in range(3):
        env.step(np.zeros(2, np.float32))  # the lidar's first scans (40 Hz)
    frame = env.render()
    corners = env.unwrapped._views._footprint
    rear, front = corners[:, 0].min(), corners[:, 0].max()

    def ahead(distance, left=0.0):
        return colour_at(env, frame, x + distance * math.cos(yaw) - left * math.sin(yaw),
                         y + distance * math.sin(yaw) + left * math.cos(yaw))

    assert ahead(front - 0.03) == views.NOSE
    assert ahead(rear + 0.03) == views.CAR_COLOURS[0]
    assert ahead(front + 0.1) != views.NOSE and ahead(rear - 0.1) != views.CAR_COLOURS[0]
    assert ahead((front + rear) / 2, left=0.25) != views.CAR_COLOURS[0]  # the car is narrower than that
    # the hits lie on the walls: each within 2 pixels (5 cm) of a wall pixel
    scan = coloured(frame, views.SCAN)
    assert scan.sum() > 200
    walls = coloured(env.unwrapped._views.top_down.background, views.WALL)
    near = np.zeros_like(walls)
    for dr in range(-2, 3):
        for dc in range(-2, 3):
            near |= np.roll(np.roll(walls, dr, axis=0), dc, axis=1)
    assert near[scan].mean() > 0.98


def test_the_same_seed_draws_the_same_frames(env):
    frames = []
    for _ in range(2):
        env.reset(seed=5)
        for _ in range(5):
            env.step(np.array([0.3, 0.5], np.float32))
        frames.append(env.render())
    assert np.array_equal(*frames)


def test_a_map_draws_its_walls_and_race_line():
    env = gymnasium.make('Tianracer-Map-v0', render_mode='rgb_array', view='top_down', control_period=0.04,
                         max_episode_steps=8)
    assert env.metadata['render_fps'] == 25
    try:
        env.reset(seed=0)
        frame = env.render()
        track = env.unwrapped.track
        raceline = track.raceline
        drawn = [colour_at(env, frame, x, y) == views.RACELINE for x, y in raceline[len(raceline) // 3:]]
        assert np.mean(drawn) > 0.8  # the centre line and the car cross it here and there
        # the map's occupied cells are walls: their centres, read from the image, are wall pixels
        background = env.unwrapped._views.top_down.background
        from tianracer_description.racing.f1tenth_map import occupied_cells, read_image
        occupied = occupied_cells(read_image(track.map.image), track.map)
        rows, columns = np.nonzero(occupied)
        height, (ox, oy, _) = occupied.shape[0], track.map.origin
        pick = np.linspace(0, len(rows) - 1, 50).astype(int)
        for r, c in zip(rows[pick], columns[pick]):
            cx, cy = ox + (c + 0.5) * track.map.resolution, oy + (height - r - 0.5) * track.map.resolution
            assert colour_at(env, background, cx, cy) == views.WALL
    finally:
        env.close()


def test_the_chase_camera_is_still_rgb_array():
    env = RaceEnv(RACE_TRACK_WORLD, render_mode='rgb_array')
    assert env.view == 'chase'
    env.reset(seed=0)
    for _ in range(5):
        env.step(np.zeros(2, np.float32))
    frame = env.render()
    env.close()
    assert frame.shape == (240, 320, 3) and frame.dtype == np.uint8 and frame.any()


def test_vector_env_returns_each_envs_frame():
    envs = gymnasium.make_vec('Tianracer-RaceTrack-v0', num_envs=2, render_mode='rgb_array', view='top_down')
    try:
        envs.reset(seed=0, options={'poses': [(0.0, 0.0, 0.0), (1.5, 0.0, 0.0)]})
        frames = envs.render()
        assert isinstance(frames, tuple) and len(frames) == 2
        for frame, x in zip(frames, (0.0, 1.5)):  # each env's own car
            row, column = envs.unwrapped._views.top_down.pixel(x, 0.0)
            assert tuple(frame[row, column]) in (views.CAR_COLOURS[0], views.NOSE)
        assert not np.array_equal(frames[0], frames[1])
    finally:
        envs.close()


def test_parallel_env_draws_every_car_in_one_image():
    env = RaceParallelEnv(RACE_TRACK_WORLD, cars=3, render_mode='rgb_array')
    try:
        env.reset(seed=0)
        frame = env.render()
        for colour in views.CAR_COLOURS[:3]:
            assert coloured(frame, colour).sum() > 20
    finally:
        env.close()


def test_record_video_writes_an_mp4(tmp_path):
    pytest.importorskip('moviepy', reason='RecordVideo writes with MoviePy: `make setup` installs it')
    from gymnasium.wrappers import RecordVideo
    env = gymnasium.make('Tianracer-RaceTrack-v0', render_mode='rgb_array', view='top_down', control_period=0.04,
                         max_episode_steps=10)
    env = RecordVideo(env, str(tmp_path / 'videos'), name_prefix='clip', episode_trigger=lambda episode: True)
    env.reset(seed=0)
    done = False
    while not done:
        _, _, terminated, truncated, _ = env.step(np.array([0.0, 0.5], np.float32))
        done = terminated or truncated
    env.close()
    video = tmp_path / 'videos' / 'clip-episode-0.mp4'
    assert video.is_file() and video.stat().st_size > 1000


def test_bad_render_arguments_are_named():
    with pytest.raises(ValueError, match="view is what render.. draws.*'top'"):
        RaceEnv(RACE_TRACK_WORLD, render_mode='rgb_array', view='top')
    with pytest.raises(ValueError, match="render_mode is None or one of 'human', 'rgb_array'; got 'ansi'"):
        RaceEnv(RACE_TRACK_WORLD, render_mode='ansi')


def test_human_without_a_display_fails_at_once(monkeypatch):
    monkeypatch.delenv('DISPLAY', raising=False)
    with pytest.raises(RuntimeError, match=r"render_mode='human' opens a window and there is no display"):
        RaceEnv(RACE_TRACK_WORLD, render_mode='human', view='top_down')


HUMAN = """
import numpy as np
from tianracer_description.racing.env import RaceEnv
from tianracer_description.tianracer import RACE_TRACK_WORLD
env = RaceEnv(RACE_TRACK_WORLD, render_mode='human', view='top_down', control_period=0.04)
env.reset(seed=0)
for _ in range(3):
    assert env.step(np.zeros(2, np.float32)) is not None
assert env.render() is None
shown = env._views.window._photo
print('shown', shown.width(), shown.height(), shown.get(0, 0))
env.close()
"""


@pytest.mark.skipif(not shutil.which('xvfb-run'), reason='xvfb-run (Debian\'s xvfb) shows the window')
def test_human_shows_the_frames_in_a_window_under_xvfb():
    result = subprocess.run(['xvfb-run', '-a', sys.executable, '-c', HUMAN], capture_output=True, text=True,
                            timeout=60, env=dict(os.environ))
    assert result.returncode == 0, result.stderr[-2000:]
    assert 'shown' in result.stdout and str(views.FLOOR) in result.stdout  # its corner: the floor
