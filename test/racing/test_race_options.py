"""The racing environments' options for race teams: laps counted and timed in the info, Frenet
coordinates and the line's curvature ahead as observations, grid and random starts, and each car's
parameters (mass, tyre friction, largest speed and steering) set at reset, in RaceEnv, RaceVectorEnv
and RaceParallelEnv alike."""
import math
import os

import gymnasium
import numpy as np
import pytest
from gymnasium.utils.env_checker import check_env

from suite_paths import REPOSITORY
from tianracer_description import bullet_plant
from tianracer_description.racing.cars import GRID_OFFSET, GRID_SPACING
from tianracer_description.racing.env import RaceEnv
from tianracer_description.racing.parallel_env import RaceParallelEnv
from tianracer_description.racing.pure_pursuit import PurePursuit
from tianracer_description.racing.track import Centerline, centerline_file
from tianracer_description.racing.vector_env import RaceVectorEnv
from tianracer_description.tianracer import PEANUT_MAP, RACE_TRACK_WORLD

ARENA_WORLD = os.path.join(REPOSITORY, 'worlds', 'arena.world')  # an 8 m x 6 m box, nothing inside
CIRCLE_RADIUS = 1.5  # m: a lap of the arena's circle is 9.42 m
CIRCLE = np.array([(CIRCLE_RADIUS * math.cos(a), CIRCLE_RADIUS * math.sin(a))
                   for a in np.linspace(0.0, 2 * math.pi, 120, endpoint=False)])
RACE_TRACK_LINE = Centerline.from_file(centerline_file(RACE_TRACK_WORLD))
BEND_CURVATURE = 1 / 1.5  # the race track's bends: half circles of 1.5 m


def test_laps_are_counted_and_timed_on_a_short_lap():
    env = RaceEnv(ARENA_WORLD, centerline=CIRCLE, observe_pose=True)
    policy = PurePursuit.for_env(env, speed=1.5)
    behind = env.track.centerline.pose_at(-0.3)  # on the line 0.3 m behind the start line: lap 1 is timed
    observation, info = env.reset(seed=0, options={'pose': behind})
    assert info['lap_count'] == 0 and info['last_lap_time'] == info['best_lap_time'] == math.inf, 'none yet'
    crossings = []
    while info['lap_count'] < 2:
        observation, _, terminated, _, info = env.step(policy(observation))
        assert not terminated and info['time'] < 20.0, info
        if info['lap_count'] > len(crossings):
            crossings.append((info['time'], info['laps'], info['last_lap_time']))
    (first_time, first_laps, first_lap), (second_time, second_laps, second_lap) = crossings
    lap_length = env.track.centerline.length
    assert first_laps * lap_length == pytest.approx(lap_length + 0.3, abs=0.03), 'a lap and the 0.3 m to the line'
    assert first_lap == pytest.approx(first_time, abs=0.011), 'lap 1 timed from the start'
    assert second_lap == pytest.approx(second_time - first_time, abs=0.011), 'lap 2 from crossing to crossing'
    assert 9.42 / 1.6 < second_lap < first_lap < 9.72 / 1.2, 'lap 1 starts standing'
    assert info['best_lap_time'] == second_lap


def test_a_car_going_back_over_the_line_and_forward_again_counts_no_lap():
    env = RaceEnv(RACE_TRACK_WORLD)
    _, info = env.reset(seed=0, options={'pose': RACE_TRACK_LINE.pose_at(0.3)})
    for action in [[0.0, -0.5]] * 150 + [[0.0, 0.5]] * 200:  # back to 0.5 m behind the line, then forward past it
        _, _, terminated, _, info = env.step(np.array(action, np.float32))
        assert not terminated
    assert info['progress'] > 0.5 and info['lap_count'] == 0


def test_the_lap_timer_counts_a_lap_once_and_times_it_from_crossing_to_crossing():
    behind, past = bullet_plant.LapTimer(10.0), bullet_plant.LapTimer(10.0)
    behind.restart(-1.0, 0.0)  # behind the line: lap 1 timed from the start
    past.restart(2.0, 0.0)     # past it: lap 1 counted, not timed
    assert (behind.count, behind.last, behind.best) == (0, math.inf, math.inf)
    for time, travelled in [(1.0, (5.0, 5.0)), (2.0, (10.0, 7.0)), (3.0, (12.0, 9.0)), (4.0, (10.5, 10.0)),
                            (5.0, (11.5, 12.0)), (6.0, (20.0, 18.0)), (7.0, (22.0, 20.0))]:
        behind.read(travelled[0], time)
        past.read(travelled[1], time)
    assert (behind.count, past.count) == (2, 2), 'car 0 went back over the line at 4 s and forward again: once'
    # car 0 crossed u = 10 m at 2.5 s (from 9 to 11 m in 2-3 s) and u = 20 m at 6.5 s
    # (lap 1 from the start)
    assert behind.last == pytest.approx(4.0) and behind.best == pytest.approx(2.5)
    # car 1 crossed u = 10 m at 2.5 s (from 9 to 11 m in 2-3 s; untimed) and u = 20 m at 6.0 s
    assert past.last == pytest.approx(3.5) and past.best == pytest.approx(3.5)
    with pytest.raises(ValueError, match='above 0'):
        bullet_plant.LapTimer(0.0)


def test_frenet_coordinates_and_curvature_ahead_of_a_known_pose():
    env = RaceEnv(RACE_TRACK_WORLD, observe_frenet=True, curvature_ahead=(0.5, 2.0, 6.0))
    assert env.observation_space['frenet'].shape == (3,) and env.observation_space['curvature_ahead'].shape == (3,)
    x, y, yaw = RACE_TRACK_LINE.pose_at(2.0, 0.2)  # on the south straight, 0.2 m left of the line
    observation, _ = env.reset(options={'pose': (x, y, yaw + 0.3)})
    assert observation['frenet'] == pytest.approx([2.0, 0.2, 0.3], abs=2e-3)
    # 2.5 m: the straight; 4.0 m: the east bend (from 3 m on); 8.0 m: the north straight (from 7.7 m)
    assert observation['curvature_ahead'] == pytest.approx([0.0, BEND_CURVATURE, 0.0], abs=0.02)
    x, y, yaw = RACE_TRACK_LINE.pose_at(16.0, -0.15)  # in the west bend, right of the line
    observation, _ = env.reset(options={'pose': (x, y, yaw - 0.2 + 2 * math.pi)})
    assert observation['frenet'] == pytest.approx([16.0, -0.15, -0.2], abs=0.02)
    assert observation['curvature_ahead'][0] == pytest.approx(BEND_CURVATURE, abs=0.02)


def test_frenet_on_the_peanuts_race_line_and_the_observations_pass_check_env():
    env = gymnasium.make('Tianracer-Map-v0', observe_frenet=True, curvature_ahead=(1.0, 2.0), frenet_line='raceline')
    check_env(env.unwrapped, skip_render_check=True)  # its render modes: test_race_views.py
    raceline = Centerline(env.unwrapped.track.raceline)
    x, y, yaw = raceline.pose_at(5.0, -0.1)
    observation, _ = env.reset(options={'pose': (x, y, yaw)})
    assert observation['frenet'] == pytest.approx([5.0, -0.1, 0.0], abs=0.01)
    assert observation['curvature_ahead'] == pytest.approx(raceline.curvature_at(np.array([6.0, 7.0])), abs=1e-4)
    assert RaceEnv(map=PEANUT_MAP).observation_space.spaces.keys() == {'scan', 'speed', 'steering', 'imu'}, \
        'off by default'
    with pytest.raises(ValueError, match='frenet_line is one of centerline, raceline'):
        RaceEnv(RACE_TRACK_WORLD, frenet_line='middle')


def test_random_and_grid_starts_are_on_the_line_and_follow_the_seed():
    env = RaceEnv(RACE_TRACK_WORLD, observe_frenet=True)
    starts = [env.reset(seed=seed, options={'start': 'random'})[0]['frenet'] for seed in (1, 1, 2)]
    assert np.array_equal(starts[0], starts[1]) and not np.array_equal(starts[0], starts[2])
    for s, ey, epsi in starts:
        assert abs(ey) < 2e-3 and abs(epsi) < 2e-3, 'on the line, along it'
    pole = env.reset(seed=3, options={'start': 'grid'})[0]['frenet']
    assert abs(pole[1] - GRID_OFFSET) < 0.03, 'the grid\'s left column'
    with pytest.raises(ValueError, match="options\\['start'\\] is one of None, 'grid', 'random'"):
        env.reset(options={'start': 'pole'})

    envs = RaceVectorEnv(2, RACE_TRACK_WORLD, observe_frenet=True)
    observations, _ = envs.reset(seed=1, options={'start': 'random'})
    assert np.array_equal(observations['frenet'][0], starts[0]), 'car i of the vector env is seed + i\'s'
    assert envs.observation_space.contains(observations)

    race = RaceParallelEnv(RACE_TRACK_WORLD, cars=3, observe_frenet=True)
    grid = [race.reset(seed=4, options={'start': start})[0] for start in ('grid', None, 'random', 'random')]
    assert all(np.array_equal(grid[0][a]['frenet'], grid[1][a]['frenet']) for a in race.possible_agents), \
        'the grid is the default'
    assert all(np.array_equal(grid[2][a]['frenet'], grid[3][a]['frenet']) for a in race.possible_agents)
    for observations in (grid[0], grid[2]):
        s = np.array([observations[a]['frenet'][0] for a in race.possible_agents])
        ey = np.array([observations[a]['frenet'][1] for a in race.possible_agents])
        behind = np.array([RACE_TRACK_LINE.progress(s[k], s[0]) for k in range(3)])
        assert behind == pytest.approx([0.0, GRID_SPACING, 2 * GRID_SPACING], abs=0.06), 'one behind another'
        assert np.sign(ey).tolist() == [1.0, -1.0, 1.0], 'staggered, left and right'
    assert abs(RACE_TRACK_LINE.progress(0.0, grid[2]['car_0']['frenet'][0])) > 1.0, 'the random grid, elsewhere'


def speed_after(env, action, steps, options):
    observation, info = env.reset(seed=0, options=options)
    for _ in range(steps):
        observation, _, _, _, info = env.step(np.array(action, np.float32))
    return float(observation['speed'][0]), info


def test_car_params_change_the_dynamics_and_are_in_the_info():
    env = RaceEnv(RACE_TRACK_WORLD)
    start = {'pose': (-2.5, 0.0, 0.0)}
    default, info = speed_after(env, [0.0, 1.0], 40, start)
    assert info['car_params'] == pytest.approx({'mass': env.model.mass, 'mu': 1.0, 'max_speed': 2.0,
                                                'max_steering': env.model.max_steering})
    capped, info = speed_after(env, [0.0, 1.0], 150, {**start, 'car_params': {'max_speed': 0.8}})
    assert capped == pytest.approx(0.8, abs=0.03) and info['car_params']['max_speed'] == 0.8
    # The speed controllers ramp the speed up at about 5 m/s^2 (2 m/s in 0.4 s) while the rear wheels'
    # torque limit (1 N m each, at 32 mm) can push a car of up to 12 kg that hard; 27 kg it pushes at
    # 2.3 m/s^2. Four tyres of mu 0.05 grip for 0.5 m/s^2.
    heavy, info = speed_after(env, [0.0, 1.0], 40, {**start, 'car_params': {'mass': 10 * env.model.mass}})
    slippery, _ = speed_after(env, [0.0, 1.0], 40, {**start, 'car_params': {'mu': 0.05}})
    assert default == pytest.approx(1.9, abs=0.1) and heavy == pytest.approx(0.4 * 2 * 1.0 / 0.032 / 26.9, rel=0.2)
    assert 0.0 < slippery < 0.4 * 0.05 * 9.81, 'less than the grip of four wheels: the rear two drive'
    assert info['car_params']['mass'] == pytest.approx(10 * env.model.mass)
    again, info = speed_after(env, [0.0, 1.0], 40, start)
    assert again == default and info['car_params']['max_speed'] == 2.0, 'a reset without them: the defaults'
    for params, message in [({'mu': 1.5}, r'mu is in \(0, 1\]'), ({'mass': -1}, r'mass is in \(0, inf\] kg'),
                            ({'max_steering': 2.0}, r'max_steering is in \(0, 0\.\d+\] rad'),
                            ({'grip': 1.0}, 'car_params has no grip')]:
        with pytest.raises(ValueError, match=message):
            env.reset(options={'car_params': params})


def test_car_params_per_car_in_the_vector_and_parallel_envs():
    envs = RaceVectorEnv(2, RACE_TRACK_WORLD)
    envs.reset(seed=0, options={'car_params': [{'max_speed': 0.5}, None]})
    for _ in range(150):
        observations, _, _, _, infos = envs.step(np.tile([0.0, 1.0], (2, 1)).astype(np.float32))
    assert observations['speed'][:, 0] == pytest.approx([0.5, 2.0], abs=0.06)
    assert list(infos['car_params']['max_speed']) == [0.5, 2.0] and infos['_car_params'].all()
    race = RaceParallelEnv(RACE_TRACK_WORLD, cars=2)
    _, infos = race.reset(seed=0, options={'car_params': {'car_1': {'mu': 0.5}}})
    assert infos['car_0']['car_params']['mu'] == 1.0 and infos['car_1']['car_params']['mu'] == 0.5
    _, infos = race.reset(seed=0, options={'car_params': {'mass': 4.0}})
    assert all(infos[a]['car_params']['mass'] == 4.0 for a in race.possible_agents)
    from pettingzoo.test import parallel_api_test
    parallel_api_test(RaceParallelEnv(RACE_TRACK_WORLD, cars=2, observe_frenet=True, curvature_ahead=(1.0,)),
                      num_cycles=20)


def test_randomised_car_params_keep_a_bounded_number_of_urdfs():
    """Domain randomisation draws a new mass and mu at every reset: the URDFs made for them are kept
    for the newest SPAWN_URDFS_KEPT only, and the defaults' is made again byte for byte."""
    from tianracer_description.racing.car import SPAWN_URDFS_KEPT, CarModel
    model = CarModel()
    default = model.spawn_urdf(None)
    for k in range(3 * SPAWN_URDFS_KEPT):
        model.spawn_urdf({'mass': 3.0 + 0.01 * k, 'mu': 0.8}, False)
    assert len(model._urdfs) == SPAWN_URDFS_KEPT
    assert model.spawn_urdf(None) == default
