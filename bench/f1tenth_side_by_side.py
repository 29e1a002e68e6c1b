"""Env steps per CPU second of f1tenth_gym v1.0.0 and of RaceEnv side by side, on the same map: our
peanut track in f1tenth's format (worlds/peanut_map.yaml, its centre line and race line CSVs), pure
pursuit on the race line from the start line, 10 ms steps, only env.step timed, a warm-up round
first (numba compiles f1tenth's at its first calls). Issue 42's comparison, by hand:
f1tenth_gym is not on a registry, and its maps download at run time.

    git clone -b v1.0.0 https://github.com/f1tenth/f1tenth_gym F1 && python3 -m venv F1/venv
    F1/venv/bin/pip install gymnasium==0.29.1 numpy scipy pillow numba pyyaml pygame \\
        opencv-python-headless yamldataclassconfig==1.5.0 requests shapely
    F1/venv/bin/pip install --no-deps -e F1
    mkdir -p F1/maps/peanut && cp worlds/peanut_* F1/maps/peanut/
    python3 bench/f1tenth_side_by_side.py --f1tenth-python F1/venv/bin/python [--rounds 3 --steps 1500 --runs 2]
        [--physics-dt 0.005]   # ours with a larger physics step (RaceEnv's physics_dt; default: the world's 1 ms)
        [--cars 4]             # N cars in one world (f1tenth's num_agents, our RaceParallelEnv), 1.5 m apart

Each run starts both, one after the other, each in a process of its own; prints each one's median
of ROUNDS rounds and ours over f1tenth's."""
import argparse
import json
import math
import os
import statistics
import subprocess
import sys
import time

import numpy as np

RACELINE = os.path.join(os.path.dirname(os.path.abspath(__file__)), os.pardir, 'worlds', 'peanut_raceline.csv')


def steer_to(waypoints, speeds, x, y, yaw, lookahead, wheelbase):
    """f1tenth's car's pure pursuit (its own geometry): (steering angle, speed)."""
    offsets = waypoints - (x, y)
    distances = np.hypot(offsets[:, 0], offsets[:, 1])
    nearest = int(np.argmin(distances))
    order = np.roll(np.arange(len(waypoints)), -nearest)
    beyond = np.flatnonzero(distances[order] >= lookahead)
    dx, dy = offsets[order[beyond[0]] if len(beyond) else order[-1]]
    ahead, left = math.cos(yaw) * dx + math.sin(yaw) * dy, -math.sin(yaw) * dx + math.cos(yaw) * dy
    reach = math.hypot(ahead, left)
    return math.atan2(2.0 * wheelbase * left / reach, reach), speeds[nearest]


def timed(env, reset, step, policy, rounds, steps):
    """Env steps per CPU second of each round but the first (env.step and its resets timed)."""
    rates = []
    for _ in range(rounds + 1):
        observation, cpu = reset(), 0.0
        for _ in range(steps):
            action = policy(observation)
            start = time.process_time()
            observation, _, terminated, truncated, _ = env.step(step(action))
            if terminated or truncated:
                observation = reset()
            cpu += time.process_time() - start
        rates.append(steps / cpu)
    return rates[1:]


def f1tenth(rounds, steps, poses):
    import gymnasium
    env = gymnasium.make('f1tenth_gym:f1tenth-v0', config={'map': 'peanut', 'num_agents': len(poses), 'timestep': 0.01,
                                                           'observation_config': {'type': 'original'}})
    line = np.loadtxt(RACELINE, delimiter=';')
    wheelbase = 0.15875 + 0.17145  # f1tenth_gym's lf + lr
    start = np.array(poses)
    return timed(env, lambda: env.reset(options={'poses': start})[0], np.array,
                 lambda o: [steer_to(line[:, 1:3], line[:, 5], o['poses_x'][i], o['poses_y'][i], o['poses_theta'][i],
                                     0.6, wheelbase) for i in range(len(poses))], rounds, steps)


class ParallelSteps:
    """A PettingZoo race stepped as timed() steps an env: one call moves every car, done when any is."""

    def __init__(self, env):
        self.env = env

    def step(self, actions):
        observations, rewards, terminations, truncations, infos = self.env.step(actions)
        return observations, rewards, any(terminations.values()), any(truncations.values()), infos


def ours(rounds, steps, physics_dt, poses):
    import gymnasium
    import tianracer_description.racing  # noqa: F401  (registers the environments)
    from tianracer_description.racing.parallel_env import RaceParallelEnv
    from tianracer_description.racing.pure_pursuit import PurePursuit
    from tianracer_description.tianracer import PEANUT_MAP
    if len(poses) == 1:
        env = gymnasium.make('Tianracer-Map-v0', observe_pose=True, physics_dt=physics_dt)
        return timed(env, lambda: env.reset(seed=0, options={'pose': poses[0]})[0], lambda a: a,
                     PurePursuit.for_env(env), rounds, steps)
    race = RaceParallelEnv(map=PEANUT_MAP, cars=len(poses), observe_pose=True, physics_dt=physics_dt)
    policy = PurePursuit.for_env(race)
    agents = race.possible_agents
    given = dict(zip(agents, poses))
    return timed(ParallelSteps(race), lambda: race.reset(seed=0, options={'poses': given})[0], lambda a: a,
                 lambda o: {agent: policy(o[agent]) for agent in o}, rounds, steps)


def behind_on_the_race_line(cars, gap=1.5):
    """(x, y, yaw) per car: the first at the start (0, 0, 0), each next one `gap` m behind the one
    before along the race line (closer, f1tenth's 0.58 m long cars on one line touch: its episodes
    end at the first touch, and the resets would be timed)."""
    line = np.loadtxt(RACELINE, delimiter=';')
    s, xy = line[:, 0], line[:, 1:3]
    length = s[-1] + np.hypot(*(xy[0] - xy[-1]))
    poses = [[0.0, 0.0, 0.0]]
    for k in range(1, cars):
        i = int(np.searchsorted(s, (length - k * gap) % length))
        dx, dy = xy[(i + 1) % len(xy)] - xy[i]
        poses.append([float(xy[i, 0]), float(xy[i, 1]), math.atan2(dy, dx)])
    return poses


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('--f1tenth-python', help="the python of f1tenth_gym's venv")
    parser.add_argument('--rounds', type=int, default=3)
    parser.add_argument('--steps', type=int, default=1500)
    parser.add_argument('--runs', type=int, default=2)
    parser.add_argument('--physics-dt', type=float, help="ours: RaceEnv's physics_dt (s; default: the world's)")
    parser.add_argument('--cars', type=int, default=1, help='cars in one world (f1tenth: num_agents)')
    parser.add_argument('--poses', help=argparse.SUPPRESS)
    parser.add_argument('--child', choices=['f1tenth', 'ours'], help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.child:
        poses = json.loads(args.poses)
        rates = (f1tenth(args.rounds, args.steps, poses) if args.child == 'f1tenth'
                 else ours(args.rounds, args.steps, args.physics_dt, poses))
        print(statistics.median(rates))
        return
    if not args.f1tenth_python:
        parser.error('--f1tenth-python: the python of a venv with f1tenth_gym v1.0.0 (see this file\'s text)')
    poses = json.dumps(behind_on_the_race_line(args.cars))
    for run in range(args.runs):
        rates = {}
        for name, python in (('f1tenth', args.f1tenth_python), ('ours', sys.executable)):
            physics_dt = ['--physics-dt', str(args.physics_dt)] if args.physics_dt and name == 'ours' else []
            out = subprocess.run([python, os.path.abspath(__file__), '--child', name, '--rounds', str(args.rounds),
                                  '--steps', str(args.steps), '--poses', poses, *physics_dt],
                                 capture_output=True, text=True, check=True)
            rates[name] = float(out.stdout.split()[-1])
        print('run %d, %d car%s: f1tenth_gym %.0f, ours%s %.0f env steps per CPU second: ours / f1tenth %.2f'
              % (run + 1, args.cars, 's' if args.cars > 1 else '', rates['f1tenth'],
                 ' (physics_dt %g s)' % args.physics_dt if args.physics_dt else '', rates['ours'],
                 rates['ours'] / rates['f1tenth']), flush=True)


if __name__ == '__main__':
    main()
