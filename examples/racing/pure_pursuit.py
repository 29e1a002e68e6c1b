"""Pure pursuit beside follow the gap on a map of f1tenth's: the worked example, a program of its own
(examples/, as f1tenth_gym keeps its examples), run with the workspace sourced:

    /usr/bin/python3 examples/racing/pure_pursuit.py                        # worlds/peanut_map.yaml
    /usr/bin/python3 examples/racing/pure_pursuit.py --map Spielberg/Spielberg_map.yaml --max-speed 4

drives one episode with each policy from the same seeded start and prints, for each, the laps
driven, each lap's time, whether it touched a wall, and the CPU time an environment step took.
Pure pursuit follows the map's race line (<name>_raceline.csv beside it; its centre line where
there is none) at the race line's speeds times --speed-scale.
"""
import argparse
import time

import gymnasium
import numpy as np

import tianracer_description.racing  # noqa: F401  registers the environments
from tianracer_description.racing.follow_the_gap import FollowTheGap
from tianracer_description.racing.pure_pursuit import PurePursuit
from tianracer_description.tianracer import PEANUT_MAP


def drive(env, policy, seed, steps):
    """(laps, lap times (s), crashed, CPU seconds an env step) of an episode of `policy`."""
    observation, info = env.reset(seed=seed)
    lap_times, started, taken = [], time.process_time(), 0
    for taken in range(1, steps + 1):
        observation, _, terminated, truncated, info = env.step(policy(observation))
        if info['laps'] >= len(lap_times) + 1:
            lap_times.append(info['time'] - sum(lap_times))
        if terminated or truncated:
            break
    return info['laps'], lap_times, bool(info['crashed']), (time.process_time() - started) / taken


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('--map', default=PEANUT_MAP, help="a map_server YAML of f1tenth's (default: %(default)s)")
    parser.add_argument('--max-speed', type=float, default=2.0, help='m/s an action of 1 asks for')
    parser.add_argument('--speed-scale', type=float, default=1.0, help="times the race line's speeds")
    parser.add_argument('--steps', type=int, default=2000, help='env steps of 10 ms at most (default: 20 s)')
    parser.add_argument('--seed', type=int, default=0)
    args = parser.parse_args()
    env = gymnasium.make('Tianracer-Map-v0', map=args.map, max_speed=args.max_speed, observe_pose=True,
                         max_episode_steps=args.steps)
    track = env.unwrapped.track
    print('%s: %.1f m a lap (centre line), race line of %d points' % (args.map, track.centerline.length,
                                                                      len(track.raceline)))
    policies = {'pure pursuit': PurePursuit.for_env(env, speed_scale=args.speed_scale),
                'follow the gap': FollowTheGap.for_env(env)}
    for name, policy in policies.items():
        laps, lap_times, crashed, step_cost = drive(env, policy, args.seed, args.steps)
        print('%-15s %.2f laps, lap times %s s, %s, %.0f us of CPU an env step'
              % (name, laps, np.round(lap_times, 2).tolist(), 'touched a wall' if crashed else 'no wall touched',
                 step_cost * 1e6))


if __name__ == '__main__':
    main()
