"""Racing for learning (tianracer_description.racing): the Gymnasium environment on the race track
passes gymnasium's check_env, rewards progress along the centre line, ends on a wall, replays bit for
bit from a seed and actions, renders a chase camera; follow the gap drives laps; the vector
environment (N worlds stepped in one C++ call) gives what N single environments give, on one thread
or two; the centre line's arithmetic."""
import math
import os
import sys

import gymnasium
import numpy as np
import pytest
from gymnasium.utils.env_checker import check_env
from gymnasium.utils.passive_env_checker import env_render_passive_checker

from suite_paths import REPOSITORY
import tianracer_description.racing  # noqa: F401  registers the environments
from tianracer_description.racing.env import RaceEnv
from tianracer_description.racing.follow_the_gap import FollowTheGap
from tianracer_description.racing.track import Centerline, centerline_file
from tianracer_description.racing.vector_env import RaceVectorEnv
from tianracer_description.tianracer import RACE_TRACK_WORLD

ENV_ID = 'Tianracer-RaceTrack-v0'


def rollout(env, actions, seed):
    """The observations, rewards and ends of a seeded episode under a fixed list of actions."""
    observation, _ = env.reset(seed=seed)
    trace = [observation]
    for action in actions:
        observation, reward, terminated, truncated, _ = env.step(action)
        trace.append((observation, reward, terminated, truncated))
        if terminated or truncated:
            break
    return trace


def identical(a, b):
    if isinstance(a, dict):
        return a.keys() == b.keys() and all(identical(a[k], b[k]) for k in a)
    if isinstance(a, (tuple, list)):
        return len(a) == len(b) and all(identical(x, y) for x, y in zip(a, b))
    return np.array_equal(np.asarray(a), np.asarray(b))


@pytest.fixture(scope='module')
def actions():
    rng = np.random.default_rng(7)
    return [np.array([math.sin(k / 15.0), 0.4 + 0.2 * rng.random()], np.float32) for k in range(150)]


def test_gymnasiums_check_env_passes_with_the_chase_camera():
    env = gymnasium.make(ENV_ID, render_mode='rgb_array')
    # check_env's own render check makes the env in every declared mode, and "human" refuses without a
    # display (test_race_views.py shows it under Xvfb): the rgb_array render is checked here
    check_env(env.unwrapped, skip_render_check=True)
    env_render_passive_checker(env.unwrapped)
    assert env.spec.max_episode_steps == tianracer_description.racing.MAX_EPISODE_STEPS
    assert env.observation_space['scan'].shape == (1081,), "the Tianracer's lidar"


def test_the_same_seed_and_actions_give_bit_identical_observations(actions):
    first = rollout(gymnasium.make(ENV_ID), actions, seed=11)
    again = rollout(gymnasium.make(ENV_ID), actions, seed=11)
    env = gymnasium.make(ENV_ID)
    rollout(env, actions[:40], seed=3)  # an episode before changes nothing
    reused = rollout(env, actions, seed=11)
    assert identical(first, again) and identical(first, reused)
    other = rollout(gymnasium.make(ENV_ID), actions, seed=12)
    assert not identical(first[0], other[0]), 'another seed, another start'


def test_the_seed_seeds_the_lidars_noise_too():
    """From the same pose, the same seed gives the same noisy scan, another seed another one (the
    lidar's 1 cm noise), while what it measures stays the same within the noise."""
    env = RaceEnv(RACE_TRACK_WORLD)
    pose = {'pose': (0.0, 0.0, 0.0)}
    first, again, other = (env.reset(seed=seed, options=pose)[0]['scan'] for seed in (4, 4, 5))
    assert np.array_equal(first, again)
    assert np.mean(first != other) > 0.9, 'most rays drew other noise'
    assert np.max(np.abs(first - other)) < 0.12, 'the same walls, within the noise'


def test_a_seed_starts_near_the_start_line_and_options_pose_puts_the_car_there():
    env = RaceEnv(RACE_TRACK_WORLD, observe_pose=True)
    starts = [env.reset(seed=seed)[0]['pose'] for seed in range(20)]
    assert all(abs(x) <= 0.21 and abs(y) <= 0.11 and abs(yaw) <= 0.11 for x, y, yaw in starts)
    assert len({tuple(p) for p in starts}) == 20
    observation, info = env.reset(options={'pose': (3.0 + 1.5, 1.5, math.pi / 2)})
    assert observation['pose'] == pytest.approx([4.5, 1.5, math.pi / 2], abs=2e-3)
    assert info['progress'] == pytest.approx(3.0 + math.pi / 2 * 1.5, abs=0.01), 'a quarter into the east bend'


def test_the_reward_is_the_distance_gained_along_the_centre_line_and_a_wall_ends_the_episode():
    env = RaceEnv(RACE_TRACK_WORLD, observe_pose=True)
    observation, _ = env.reset(options={'pose': (-2.0, 0.0, 0.0)})
    gained, steps = 0.0, 0
    while True:  # straight ahead at half speed: along the south straight, then into the east bend's wall
        observation, reward, terminated, truncated, info = env.step(np.array([0.0, 0.5], np.float32))
        gained += reward
        steps += 1
        if steps == 300:
            x = observation['pose'][0]
            assert gained == pytest.approx(x + 2.0, abs=0.01), 'on the straight the reward is the way along x'
            assert observation['speed'][0] == pytest.approx(1.0, abs=0.05), 'half of 2 m/s'
        if terminated or truncated or steps > 2000:
            break
    assert terminated and info['crashed'], 'the wall ends it'
    x, y, _ = observation['pose']
    assert x > 3.0 and y < 0.5, 'in the east bend, against its outer wall: %s' % observation['pose']


@pytest.mark.parametrize('env_id', [ENV_ID, 'Tianracer-RaceCircuit-v0'])
def test_follow_the_gap_drives_laps_of_our_tracks_without_touching_a_wall(env_id):
    env = gymnasium.make(env_id)
    lap = env.unwrapped.track.centerline.length
    policy = FollowTheGap.for_env(env)
    observation, _ = env.reset(seed=0)
    returns = 0.0
    while True:
        observation, reward, terminated, truncated, info = env.step(policy(observation))
        returns += reward
        if terminated or truncated:
            break
    assert truncated and not terminated, 'the time limit, not a wall: %s' % info
    assert info['laps'] > 1.0 and returns == pytest.approx(info['laps'] * lap, rel=1e-3)


def test_the_circuits_centre_line_runs_down_the_middle_of_its_lane():
    # tools/make_race_circuit.py builds the walls from the centre line: 0.6 m to either side, in boxes
    # 5 cm thick, so their faces are 0.575 m away (a little more or less in a bend, where the boxes
    # are chords of the curve)
    from tianracer_description import bullet_plant
    from tianracer_description.tianracer import RACE_CIRCUIT_WORLD
    world = bullet_plant.World.from_file(RACE_CIRCUIT_WORLD)
    line = Centerline.from_file(centerline_file(RACE_CIRCUIT_WORLD))
    assert line.length == pytest.approx(32.1, abs=0.05)
    for s in np.arange(0.0, line.length, 0.5):
        x, y, yaw = line.pose_at(s)
        left = (-math.sin(yaw), math.cos(yaw), 0.0)
        distances = [world.cast_ray((x, y, 0.1), (sign * left[0], sign * left[1], 0.0), 5.0) for sign in (1, -1)]
        assert distances == pytest.approx([0.575, 0.575], abs=0.03), 'at s = %.1f m' % s


def test_the_chase_camera_shows_the_blue_car_ahead_of_it():
    env = gymnasium.make(ENV_ID, render_mode='rgb_array')
    env.reset(seed=0)
    for _ in range(40):
        env.step(np.array([0.0, 0.3], np.float32))
    frame = env.render()
    assert frame.shape == (240, 320, 3) and frame.dtype == np.uint8
    r, g, b = (frame[90:140, 140:180, k].astype(int) for k in range(3))
    assert np.mean((b > r + 40) & (b > g + 40)) > 0.15, 'the car (blue) in the middle, below the horizon'
    r, g, b = (frame[:, :100, k].astype(int) for k in range(3))
    assert np.mean((r > g + 60) & (r > b + 60)) > 0.1, 'the inner wall (red) on its left'


def test_make_vec_gives_the_vector_env_and_its_cars_are_the_single_envs_bit_for_bit(actions):
    envs = gymnasium.make_vec(ENV_ID, num_envs=3)
    assert isinstance(envs.unwrapped, RaceVectorEnv)
    assert envs.metadata['autoreset_mode'] == gymnasium.vector.AutoresetMode.SAME_STEP
    singles = [RaceEnv(RACE_TRACK_WORLD) for _ in range(3)]
    observations, _ = envs.reset(seed=20)
    expected = [env.reset(seed=20 + i)[0] for i, env in enumerate(singles)]
    for i in range(3):
        assert identical({k: v[i] for k, v in observations.items()}, expected[i])
    # car 1 turns hard right into the south straight's outer wall
    turns = [np.array([a, [-1.0, 0.8], [0.5 * a[0], a[1]]], np.float32) for a in actions]
    ended = 0
    for step, batch in enumerate(turns):
        observations, rewards, terminated, truncated, infos = envs.step(batch)
        for i, env in enumerate(singles):
            observation, reward, done, _, _ = env.step(batch[i])
            if done:  # SAME_STEP: the ended episode's last observation is final_obs, the next one's first returned
                ended += 1
                assert infos['_final_obs'][i] and identical(infos['final_obs'][i], observation)
                assert rewards[i] == reward and terminated[i]
                continue
            assert identical({k: v[i] for k, v in observations.items()}, observation), (step, i)
            assert rewards[i] == reward and not terminated[i]
        if ended:
            break
    assert ended, 'one of the cars crashed within the actions'


def test_two_threads_step_the_cars_as_one_thread_does(actions):
    traces = []
    for threads in (1, 2):
        envs = RaceVectorEnv(4, RACE_TRACK_WORLD, threads=threads)
        observations, _ = envs.reset(seed=5)
        trace = [observations]
        for action in actions[:100]:
            trace.append(envs.step(np.tile(action, (4, 1)))[:4])
        traces.append(trace)
    assert identical(traces[0], traces[1])


def test_the_centre_line_measures_progress_across_the_start_line_and_places_poses_on_it():
    line = Centerline.from_file(centerline_file(RACE_TRACK_WORLD))
    assert line.length == pytest.approx(2 * 6.0 + 2 * math.pi * 1.5, rel=1e-3)
    for s in (0.0, 2.5, 4.0, 10.0, 20.9):
        x, y, yaw = line.pose_at(s, offset=0.3)
        found, offset, _ = line.project(x, y)
        # exact on the straights; in the bends, inside, a neighbouring 5 cm segment may be nearer
        assert found == pytest.approx(s, abs=0.02) and offset == pytest.approx(0.3, abs=0.005)
    assert line.progress(line.length - 0.1, 0.2) == pytest.approx(0.3)
    assert line.progress(0.2, line.length - 0.1) == pytest.approx(-0.3)
    with pytest.raises(FileNotFoundError, match='no centre line at'):
        Centerline.from_file('/nowhere/track.centerline.csv')


def test_the_multi_car_race_passes_pettingzoos_api_and_seed_tests():
    from pettingzoo.test import parallel_api_test, parallel_seed_test
    from tianracer_description.racing.parallel_env import RaceParallelEnv
    parallel_api_test(RaceParallelEnv(RACE_TRACK_WORLD, cars=3), num_cycles=200)
    parallel_seed_test(lambda: RaceParallelEnv(RACE_TRACK_WORLD, cars=3), num_cycles=100)


def test_cars_in_one_race_see_each_other_and_a_collision_ends_both():
    from tianracer_description.racing.parallel_env import RaceParallelEnv
    env = RaceParallelEnv(RACE_TRACK_WORLD, cars=2, observe_pose=True)
    observations, _ = env.reset(options={'poses': {'car_0': (1.2, 0.0, 0.0), 'car_1': (0.0, 0.0, 0.0)}})
    ahead = len(observations['car_1']['scan']) // 2
    # car_1's lidar sees car_0, 1.2 m ahead (what of it stands at the lidar's height, its own lidar);
    # with no car there it would see the east bend's wall, beyond 4 m
    assert 0.8 < observations['car_1']['scan'][ahead] < 1.4
    for _ in range(300):
        observations, rewards, terminations, _, infos = env.step({'car_0': np.zeros(2, np.float32),
                                                                  'car_1': np.array([0.0, 0.5], np.float32)})
        if any(terminations.values()):
            break
    assert terminations == {'car_0': True, 'car_1': True}, 'the one hit and the one hitting'
    assert observations['car_0']['pose'][0] > 1.2, 'pushed ahead'
    assert env.agents == []


def test_three_cars_racing_with_follow_the_gap_stay_off_the_walls_and_each_other():
    from tianracer_description.racing.parallel_env import RaceParallelEnv
    env = RaceParallelEnv(RACE_TRACK_WORLD, cars=3, max_cycles=600)
    policy = FollowTheGap.for_env(env)
    observations, _ = env.reset(seed=2)
    while env.agents:
        observations, _, terminations, _, infos = env.step({a: policy(observations[a]) for a in env.agents})
        assert not any(terminations.values()), infos
    assert all(infos[a]['laps'] * 21.42 > 8.0 for a in env.possible_agents), 'each 8 m along in 6 s'


@pytest.mark.slow
def test_ppo_from_stable_baselines3_trains_on_the_vector_env(tmp_path, monkeypatch):
    """docs/racing.md's example, short: a few thousand PPO steps on two cars of the vector env (PyTorch on
    the CPU), through Sb3VecEnv; the ended episodes' last observations reach SB3 as it expects."""
    # SB3's logger makes a folder of its own (SB3_LOGDIR, or /tmp/SB3-<date> each time) even when it
    # writes nothing: the test's, not /tmp
    monkeypatch.setenv('SB3_LOGDIR', str(tmp_path / 'sb3'))
    sys.path.insert(0, os.path.join(REPOSITORY, 'examples', 'racing'))  # the example is a program, no package
    from train_ppo import Sb3VecEnv, evaluate, model_policy, train
    model = train(RACE_TRACK_WORLD, envs=2, timesteps=2048, n_steps=512)
    assert model.num_timesteps >= 2048
    assert math.isfinite(evaluate(model_policy(model), RACE_TRACK_WORLD, episodes=1, seed=0, steps=200))
    envs = Sb3VecEnv(RaceVectorEnv(2, RACE_TRACK_WORLD, max_episode_steps=5))
    envs.reset()
    for _ in range(4):
        _, _, done, infos = envs.step(np.zeros((2, 2), np.float32))
        assert not done.any()
    observations, _, done, infos = envs.step(np.zeros((2, 2), np.float32))
    assert done.all() and all(info['TimeLimit.truncated'] for info in infos)
    assert all(info['terminal_observation']['scan'].shape == (1081,) for info in infos)
