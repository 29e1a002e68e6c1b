"""A sweep's scenarios: a scenario is a plain dict of SCENARIO_FIELDS (missing ones at
default_scenario()'s values); run_scenario(scenario) drives it with follow the gap in a RaceEnv of its
own and returns a flat row: the scenario's fields and RESULT_FIELDS. It never raises: what goes wrong
in a scenario is in the row's `error`, with its seed. grid() and random_scenarios() make scenario sets."""
import copy
import itertools
import math
import os
import re
import time
import traceback

import numpy as np

from tianracer_description import racing
from tianracer_description.racing.car import tutorial_controllers
from tianracer_description.racing.env import RaceEnv
from tianracer_description.racing.follow_the_gap import FollowTheGap
from tianracer_description.tianracer import STEERING_CONTROLLERS

# A scenario's fields and their types (as the command line and read_results parse them).
FIELD_TYPES = {'track': str, 'seed': int, 'max_speed': float, 'steering_p': float, 'steering_d': float,
               'straight_speed': float, 'turn_speed': float, 'steps': int}
SCENARIO_FIELDS = tuple(FIELD_TYPES)
# What a run adds. steps_run: the env steps driven (fewer than the scenario's `steps` after a crash).
RESULT_TYPES = {'laps': float, 'return': float, 'crashed': bool, 'sim_time': float, 'steps_run': int,
                'lap_time': float, 'wall_seconds': float, 'error': str}
RESULT_FIELDS = tuple(RESULT_TYPES)

# Where random_scenarios draws from unless told otherwise: around the tutorial's car, which follow the
# gap drives round the race track at its defaults.
RANDOM_RANGES = {'seed': (0, 2 ** 31 - 1), 'max_speed': (1.5, 3.5), 'steering_p': (2.0, 8.0),
                 'steering_d': (0.2, 2.0), 'straight_speed': (0.6, 1.0), 'turn_speed': (0.3, 0.7)}

ANSI_ESCAPE = re.compile(r'\x1b\[[0-9;]*m')


def default_scenario():
    """Every field at its default: the race track, seed 0, the environment's top speed, the tutorial's
    steering gains (its YAML gives both steering controllers the same) and follow the gap's speeds."""
    pid = tutorial_controllers()['tianracer'][STEERING_CONTROLLERS[0]]['pid']
    return {'track': 'RaceTrack', 'seed': 0, 'max_speed': 2.0, 'steering_p': float(pid['p']),
            'steering_d': float(pid['d']), 'straight_speed': 1.0, 'turn_speed': 0.5,
            'steps': racing.MAX_EPISODE_STEPS}


def complete(scenario):
    """The scenario with its missing fields at their defaults and a track's world file as an absolute
    path (a Ray worker runs in a folder of its own); ValueError for a field that is not one."""
    unknown = sorted(set(scenario) - set(SCENARIO_FIELDS))
    if unknown:
        raise ValueError('%s %s not a scenario field; the fields are %s'
                         % (', '.join(unknown), 'is' if len(unknown) == 1 else 'are', ', '.join(SCENARIO_FIELDS)))
    scenario = dict(default_scenario(), **scenario)
    if isinstance(scenario['track'], str) and scenario['track'] not in racing.TRACKS:
        scenario['track'] = os.path.abspath(scenario['track'])
    return scenario


def world_file(track):
    """A track's world file: a name of racing.TRACKS, or a world file's path."""
    if track in racing.TRACKS:
        return racing.TRACKS[track]
    if os.path.isfile(track):
        return track
    raise FileNotFoundError('track %r is neither one of racing.TRACKS (%s) nor a world file that exists'
                            % (track, ', '.join(racing.TRACKS)))


def controllers_with_steering_gains(p, d):
    """The tutorial's controller YAML (a deep copy) with both steering controllers' PID p and d set."""
    controllers = copy.deepcopy(tutorial_controllers())
    for name in STEERING_CONTROLLERS:
        controllers['tianracer'][name]['pid'].update(p=float(p), d=float(d))
    return controllers


def drive(scenario):
    """The results of driving a complete scenario (RESULT_FIELDS but wall_seconds and error)."""
    env = RaceEnv(world_file(scenario['track']),
                  controllers=controllers_with_steering_gains(scenario['steering_p'], scenario['steering_d']),
                  max_speed=scenario['max_speed'])
    try:
        policy = FollowTheGap.for_env(env, straight_speed=scenario['straight_speed'],
                                      turn_speed=scenario['turn_speed'])
        observation, info = env.reset(seed=int(scenario['seed']))
        start = info['time']  # the reset holds the car still for one physics step
        total, steps, lap_time = 0.0, 0, math.nan
        while steps < int(scenario['steps']):
            observation, reward, terminated, _, info = env.step(policy(observation))
            total += reward
            steps += 1
            if math.isnan(lap_time) and info['laps'] >= 1.0:
                lap_time = info['time'] - start
            if terminated:  # a crash: RaceEnv has no time limit of its own
                break
        return {'laps': float(info['laps']), 'return': float(total), 'crashed': bool(info['crashed']),
                'sim_time': float(info['time'] - start), 'steps_run': steps, 'lap_time': float(lap_time)}
    finally:
        env.close()


def failure(scenario, error):
    """The error column for an exception of a scenario: its seed, the exception and where it was raised."""
    frames = traceback.extract_tb(error.__traceback__)
    where = ' (%s:%d)' % (os.path.basename(frames[-1].filename), frames[-1].lineno) if frames else ''
    seed = scenario.get('seed') if isinstance(scenario, dict) else None
    # One line for the CSV: of a message of many (Ray's carry the remote traceback), the first (Ray's:
    # the task, its pid and node) and the last (the exception raised).
    text = ANSI_ESCAPE.sub('', str(error))  # Ray colours the task's name
    lines = [line.strip() for line in text.splitlines() if line.strip()] or ['']
    message = lines[0] if len(lines) == 1 else '%s ... %s' % (lines[0], lines[-1])
    return 'seed %s: %s: %s%s' % (seed, type(error).__name__, message, where)


def failed_row(scenario, error, wall_seconds=math.nan):
    row = {field: scenario.get(field, '') for field in SCENARIO_FIELDS} if isinstance(scenario, dict) else \
        dict.fromkeys(SCENARIO_FIELDS, '')
    row.update({'laps': math.nan, 'return': math.nan, 'crashed': False, 'sim_time': math.nan, 'steps_run': 0,
                'lap_time': math.nan, 'wall_seconds': wall_seconds, 'error': failure(scenario, error)})
    return row


def run_scenario(scenario):
    """Drives one scenario with follow the gap for up to its `steps` env steps (or to a crash) and
    returns its row: the scenario's fields (completed with the defaults) and RESULT_FIELDS. Never
    raises: an exception is the row's `error` ('' when it ran), with the scenario's seed."""
    begun = time.perf_counter()
    try:
        scenario = complete(scenario)
        row = dict(scenario, **drive(scenario))
    except Exception as error:  # noqa: BLE001  one scenario's failure is its row's, not the sweep's
        return failed_row(scenario, error, time.perf_counter() - begun)
    row.update(wall_seconds=time.perf_counter() - begun, error='')
    return row


# Scenario sets.

def grid(**axes):
    """The cartesian product of the values given per field (a list each; a single value is a list of
    one), the first field varying slowest; the other fields at their defaults."""
    lists = {field: list(values) if isinstance(values, (list, tuple)) else [values] for field, values in axes.items()}
    complete(lists)  # the fields are scenario fields
    for field, values in lists.items():
        if not values:
            raise ValueError('grid axis %s has no values' % field)
    return [complete(dict(zip(lists, values))) for values in itertools.product(*lists.values())]


def random_scenarios(count, seed, ranges=None):
    """`count` scenarios, each field of `ranges` ({field: (low, high)}, default RANDOM_RANGES) drawn
    uniformly from its range by a numpy Generator seeded by `seed` (integers, low and high included,
    for seed and steps), scenario by scenario, so the first k of a longer set are the same k; the other
    fields at their defaults. The same arguments give the same scenarios."""
    ranges = dict(RANDOM_RANGES if ranges is None else ranges)
    complete(ranges)
    if count < 0:
        raise ValueError('count is a number of scenarios, 0 or more; got %r' % (count,))
    for field, bounds in ranges.items():
        if FIELD_TYPES[field] is str:
            raise ValueError('%s is not drawn from a range: give it as a fixed value or grid axis' % field)
        low, high = bounds
        if not low <= high:
            raise ValueError('the range of %s is (low, high) with low <= high; got %r' % (field, bounds))
    rng = np.random.default_rng(seed)
    scenarios = []
    for _ in range(count):
        drawn = {}
        for field in SCENARIO_FIELDS:  # a fixed order: the draws do not depend on the dict's
            if field in ranges:
                low, high = ranges[field]
                drawn[field] = int(rng.integers(low, high, endpoint=True)) if FIELD_TYPES[field] is int \
                    else float(rng.uniform(low, high))
        scenarios.append(complete(drawn))
    return scenarios
