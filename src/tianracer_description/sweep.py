"""Parameter sweeps of the race car: many scenarios (a track, a seed, the car's top speed, its steering
controllers' gains, follow the gap's speeds), each driven by follow the gap in a RaceEnv of its own,
one result row per scenario, run in this process or as Ray tasks on a cluster.

    /usr/bin/python3 -m tianracer_description.sweep --grid max_speed=2,3 --grid seed=0,1,2 --local --out r.csv
    /usr/bin/python3 -m tianracer_description.sweep --random 200 --seed 1 --range max_speed=1.5,4 \\
        --address 127.0.0.1:6379 --out r.csv --plot r.png

A scenario is a plain dict of SCENARIO_FIELDS (missing ones at default_scenario()'s values);
run_scenario(scenario) drives it and returns a flat row: the scenario's fields and RESULT_FIELDS. It
never raises: what goes wrong in a scenario is in the row's `error`, with its seed, and the sweep goes
on. The plant is deterministic, so a scenario's row is the same wherever it runs (apart from
wall_seconds): in-process, on a local Ray or on a cluster's worker.

Rows are written as the scenarios finish (a CSV flushed row by row; .parquet, with pyarrow, at the
end), with a progress bar on stderr and a summary on stdout at the end.

Ray's workers must import this package: the driver hands them its ROS workspace's environment
(worker_environment(): PYTHONPATH, ROS_PACKAGE_PATH, ...) as the job's runtime_env, so a cluster
started by `ray start` in a shell without the workspace sourced runs the sweep too; on several
machines the workspace must be at the same path on each. On one machine a head started with
RAY_ENABLE_WINDOWS_OR_OSX_CLUSTER=0 listens on loopback only, and a driver must have the variable as
well (else it looks for the head at the machine's network address and waits there): connect_ray
sets it for loopback addresses. A head that runs with token authentication (`ray start` turns it on
when it finds ~/.ray/auth_token, which a local ray.init() writes) takes a driver only with
RAY_AUTH_MODE=token and the token in its environment.
"""
import argparse
import copy
import csv
import itertools
import logging
import math
import os
import re
import socket
import sys
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
# Rows of a sweep are numbered by their scenario's place in it: the CSV is in the order they finish.
INDEX_FIELD = 'scenario'
COLUMNS = (INDEX_FIELD,) + SCENARIO_FIELDS + RESULT_FIELDS

# Where random_scenarios draws from unless told otherwise: around the tutorial's car, which follow the
# gap drives round the race track at its defaults.
RANDOM_RANGES = {'seed': (0, 2 ** 31 - 1), 'max_speed': (1.5, 3.5), 'steering_p': (2.0, 8.0),
                 'steering_d': (0.2, 2.0), 'straight_speed': (0.6, 1.0), 'turn_speed': (0.3, 0.7)}

CLUSTER_VARIABLE = 'RAY_ENABLE_WINDOWS_OR_OSX_CLUSTER'  # 0: Ray's node address is loopback
# What Ray's workers need of the driver's environment to import the package and find the ROS packages
# (rospack for xacro and the car's files), besides every ROS_* and TIANRACER_* variable.
WORKER_VARIABLES = ('PYTHONPATH', 'LD_LIBRARY_PATH', 'CMAKE_PREFIX_PATH', 'PKG_CONFIG_PATH')
LOOPBACK_HOSTS = ('localhost', '::1')
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


# Running a sweep.

def local_results(scenarios):
    """(index, row) of each scenario, run one after another in this process."""
    for index, scenario in enumerate(scenarios):
        yield index, run_scenario(scenario)


def worker_environment():
    """The driver's variables Ray's workers need to import the package and find the ROS packages."""
    return {name: value for name, value in os.environ.items()
            if name in WORKER_VARIABLES or name.startswith(('ROS_', 'TIANRACER_'))}


def host_and_port(address):
    """(host, port) of 'host:port' (or 'ray://host:port'); None for another form ('auto')."""
    host, sep, port = address.split('://', 1)[-1].rpartition(':')
    return (host.strip('[]'), int(port)) if sep and host and port.isdigit() else None


def is_loopback(address):
    where = host_and_port(address)
    return where is not None and (where[0] in LOOPBACK_HOSTS or where[0].startswith('127.'))


def check_listening(address, timeout=5.0):
    """ConnectionError unless something accepts a connection at the address: ray.init retries a
    dead address for a quarter of an hour before it gives up."""
    where = host_and_port(address)
    if where is None:
        return
    try:
        socket.create_connection(where, timeout).close()
    except OSError as error:
        raise ConnectionError('nothing answers at %s (%s): start the cluster\'s head there (ray start --head '
                              '--port=%d) or give --address of one that runs' % (address, error, where[1])) from None


def connect_ray(address=None):
    """ray, initialised: connected to the cluster at `address`, or (None) a local Ray of its own, the
    job's workers given worker_environment(). Sets RAY_ENABLE_WINDOWS_OR_OSX_CLUSTER=0 (unless it is
    set) for a loopback address before ray is imported: a head on loopback is found only so."""
    if address is not None:
        check_listening(address)
        if is_loopback(address):
            os.environ.setdefault(CLUSTER_VARIABLE, '0')
    import ray
    settings = dict(log_to_driver=False, logging_level=logging.WARNING,
                    runtime_env={'env_vars': worker_environment()})
    if address is None:
        ray.init(include_dashboard=False, **settings)
        return ray
    try:
        ray.init(address=address, **settings)
    except ConnectionError as error:
        # What is listening did not take us: most often token authentication, which `ray start` turns
        # on when it finds ~/.ray/auth_token, and which a driver given an address never assumes.
        raise ConnectionError(
            'cannot join the Ray cluster at %s (%s). A head with token authentication takes drivers with '
            'RAY_AUTH_MODE=token and its token (~/.ray/auth_token or RAY_AUTH_TOKEN) in their environment.'
            % (address, error)) from None
    return ray


def ray_results(ray, scenarios, workers=None):
    """(index, row) of each scenario as it finishes, run as Ray tasks (one CPU each) through `ray`
    (connect_ray's), at most `workers` at a time (default: the cluster's CPUs). A task that fails in
    Ray (a worker that dies, cannot import the package) is its scenario's error row; the others go on."""
    remote_scenario = ray.remote(num_cpus=1)(run_scenario)
    limit = workers or max(1, int(ray.cluster_resources().get('CPU', 1)))
    waiting = iter(enumerate(scenarios))
    running = {}

    def submit():
        for index, scenario in itertools.islice(waiting, 1):
            running[remote_scenario.remote(scenario)] = (index, scenario)

    for _ in range(limit):
        submit()
    while running:
        done, _ = ray.wait(list(running), num_returns=1)
        for ref in done:
            index, scenario = running.pop(ref)
            try:
                row = ray.get(ref)
            except Exception as error:  # noqa: BLE001  Ray's failure of one task: its row's
                row = failed_row(scenario, error)
                row['error'] = 'on Ray: ' + row['error']
            submit()
            yield index, row


class ResultsFile:
    """Where a sweep's rows go: a CSV, each row written and flushed as it comes (floats as repr: they
    read back exactly), or a .parquet file (pyarrow) written whole at the end."""

    def __init__(self, path):
        check_results_path(path)
        self.path = path
        self.rows = []
        self._file = self._writer = None
        if path.endswith('.csv'):
            self._file = open(path, 'w', newline='')
            self._writer = csv.DictWriter(self._file, COLUMNS)
            self._writer.writeheader()
            self._file.flush()

    def write(self, row):
        self.rows.append(row)
        if self._writer:
            self._writer.writerow(row)
            self._file.flush()

    def close(self):
        if self._file:
            self._file.close()
        else:
            import pandas
            pandas.DataFrame(self.rows, columns=list(COLUMNS)).to_parquet(self.path)


def check_results_path(path):
    if path.endswith('.parquet'):
        try:
            import pyarrow  # noqa: F401
        except ImportError:
            raise ValueError('%s: writing .parquet needs pyarrow, which is not installed: install it '
                             '(/usr/bin/python3 -m pip install pyarrow) or write a .csv' % path) from None
    elif not path.endswith('.csv'):
        raise ValueError('%s: results are written as .csv (or .parquet with pyarrow)' % path)


def read_results(path):
    """A sweep's CSV as rows of typed values (the types it was written with)."""
    types = dict(FIELD_TYPES, **RESULT_TYPES, **{INDEX_FIELD: int})
    with open(path, newline='') as f:
        return [{name: parse(types[name], text) for name, text in row.items()} for row in csv.DictReader(f)]


def parse(kind, text):
    if kind is bool:
        return text == 'True'
    if kind is str or text == '':
        return text
    return kind(text)


def scenario_of(row):
    """The scenario a row is the result of."""
    return {field: row[field] for field in SCENARIO_FIELDS}


def run_sweep(scenarios, out=None, address=None, local=False, workers=None, progress=True):
    """Runs the scenarios (in this process with local, else on Ray: the cluster at `address`, or a local
    Ray of its own) and returns their rows in the scenarios' order, each with its INDEX_FIELD; with
    `out`, writes them there as they finish. A progress bar on stderr unless progress is False."""
    from tqdm import tqdm
    ray = None if local else connect_ray(address)  # before the results file: no empty file when it fails
    results = None
    try:
        results = ResultsFile(out) if out else None
        rows = [None] * len(scenarios)
        finished = local_results(scenarios) if local else ray_results(ray, scenarios, workers)
        with tqdm(total=len(scenarios), file=sys.stderr, unit='scenario', disable=not progress) as bar:
            for index, row in finished:
                row = dict({INDEX_FIELD: index}, **row)
                rows[index] = row
                if results:
                    results.write(row)
                bar.update(1)
    finally:
        if ray:
            ray.shutdown()
        if results:
            results.close()
    return rows


def summary(rows):
    """The sweep in one table: scenarios, failed (an error), crashes and mean laps of those that ran."""
    ran = [row for row in rows if not row['error']]
    laps = [row['laps'] for row in ran]
    lap_times = [row['lap_time'] for row in ran if not math.isnan(row['lap_time'])]
    columns = [('scenarios', len(rows)), ('failed', len(rows) - len(ran)),
               ('crashes', sum(row['crashed'] for row in ran)),
               ('mean laps', '%.3f' % np.mean(laps) if laps else '-'),
               ('mean lap time (s)', '%.2f' % np.mean(lap_times) if lap_times else '-'),
               ('summed wall (s)', '%.1f' % sum(row['wall_seconds'] for row in ran))]
    widths = [max(len(name), len(str(value))) for name, value in columns]
    return '\n'.join('  '.join(str(cell).rjust(width) for cell, width in zip(line, widths))
                     for line in ([name for name, _ in columns], [value for _, value in columns]))


def varied_fields(rows):
    """The scenario fields that take more than one value in the rows."""
    return [field for field in SCENARIO_FIELDS if len({row[field] for row in rows}) > 1]


def plot(rows, path):
    """Laps against each varied field (one panel each; the scenario's index when none varies), crashes
    as red crosses; failed scenarios left out. Matplotlib's Figure draws on its Agg canvas: no display,
    and pyplot's global backend is left alone."""
    from matplotlib.figure import Figure
    ran = [row for row in rows if not row['error']]
    varied = varied_fields(ran)
    # A random sweep's env seeds are names, not a scale: their panel only when nothing else varies.
    fields = [field for field in varied if field != 'seed'] or varied or [INDEX_FIELD]
    columns = min(3, len(fields))
    line_count = math.ceil(len(fields) / columns)
    figure = Figure(figsize=(4.2 * columns, 3.4 * line_count), layout='constrained')
    axes = figure.subplots(line_count, columns, squeeze=False).ravel()
    for ax, field in zip(axes, fields):
        values = [row[field] for row in ran]
        if values and isinstance(values[0], str):  # a track: categories along x
            names = sorted(set(values))
            ax.set_xticks(range(len(names)), [os.path.basename(n) for n in names], rotation=20)
            values = [names.index(v) for v in values]
        for crashed, style in ((False, dict(marker='o', color='tab:blue', label='no crash')),
                               (True, dict(marker='x', color='tab:red', label='crashed'))):
            points = [(x, row['laps']) for x, row in zip(values, ran) if row['crashed'] == crashed]
            if points:
                ax.scatter(*zip(*points), s=22, **style)
        ax.set_xlabel(field)
        ax.set_ylabel('laps')
        ax.grid(alpha=0.3)
    if ran:
        axes[0].legend(loc='best', fontsize='small')
    for ax in axes[len(fields):]:
        ax.set_visible(False)
    failed = len(rows) - len(ran)
    figure.suptitle('%d scenario%s%s' % (len(rows), '' if len(rows) == 1 else 's',
                                         ', %d failed (not shown)' % failed if failed else ''))
    figure.savefig(path, dpi=100)


# The command line.

def field_values(text, option):
    """'field=v1,v2,...' as (field, [typed values]); ValueError naming the option otherwise."""
    field, sep, values = text.partition('=')
    if not sep or field not in FIELD_TYPES or not values:
        raise ValueError('%s %r: give field=v1,v2,... with a field of %s' % (option, text, ', '.join(SCENARIO_FIELDS)))
    try:
        return field, [FIELD_TYPES[field](v) for v in values.split(',')]
    except ValueError:
        raise ValueError('%s %r: %s takes %s values' % (option, text, field, FIELD_TYPES[field].__name__)) from None


def scenarios_from(args):
    fixed = {name: value for name, value in (('track', args.track), ('steps', args.steps)) if value is not None}
    if args.grid:
        axes = dict(field_values(text, '--grid') for text in args.grid)
        for name in fixed:
            if name in axes:
                raise ValueError('--%s and --grid %s=... both set %s: give one' % (name, name, name))
        return grid(**axes, **fixed)
    ranges = dict(RANDOM_RANGES)
    for text in args.range or []:
        field, values = field_values(text, '--range')
        if len(values) != 2 or field in fixed:
            raise ValueError('--range %r: give field=low,high (a field --track or --steps does not set)' % text)
        ranges[field] = tuple(values)
    return [dict(scenario, **fixed) for scenario in random_scenarios(args.random, args.seed or 0, ranges)]


def argument_parser():
    parser = argparse.ArgumentParser(
        prog='python3 -m tianracer_description.sweep',
        description='Drive many scenarios of the race car with follow the gap, on Ray or in this process; '
                    'one result row per scenario. Fields: ' + ', '.join(SCENARIO_FIELDS) + '.')
    which = parser.add_mutually_exclusive_group(required=True)
    which.add_argument('--grid', action='append', metavar='FIELD=V1,V2,...',
                       help='a grid axis (repeat for more): every combination of the axes runs')
    which.add_argument('--random', type=int, metavar='N', help='N scenarios drawn from the --range ranges')
    parser.add_argument('--seed', type=int, help='the seed the random scenarios are drawn with (default 0)')
    parser.add_argument('--range', action='append', metavar='FIELD=LOW,HIGH',
                        help='a field drawn uniformly from [LOW, HIGH] (LOW=HIGH pins it); the defaults: '
                             + ', '.join('%s=%s,%s' % ((f,) + r) for f, r in RANDOM_RANGES.items()))
    parser.add_argument('--track', help='every scenario\'s track: %s or a world file (default RaceTrack)'
                        % ', '.join(racing.TRACKS))
    parser.add_argument('--steps', type=int, help='every scenario\'s env steps (default %d)' % racing.MAX_EPISODE_STEPS)
    parser.add_argument('--out', help='results file: .csv, written as scenarios finish (.parquet needs pyarrow)')
    parser.add_argument('--plot', metavar='PNG', help='a summary plot: laps against each varied field')
    where = parser.add_mutually_exclusive_group()
    where.add_argument('--address', help='the Ray cluster to run on (ray.init(address=...)); default: a local Ray')
    where.add_argument('--local', action='store_true', help='no Ray: run in this process, one after another')
    parser.add_argument('--workers', type=int,
                        help='at most this many Ray tasks at once (default: the cluster\'s CPUs)')
    return parser


def main(argv=None):
    parser = argument_parser()
    args = parser.parse_args(argv)
    if args.random is not None and args.random < 1:
        parser.error('--random N: N is 1 or more')
    if args.seed is not None and args.grid:
        parser.error('--seed is what --random draws with; a grid\'s env seeds are an axis: --grid seed=0,1,...')
    if args.range and args.grid:
        parser.error('--range is for --random; a --grid axis lists its values')
    if args.local and args.workers:
        parser.error('--workers limits Ray tasks; --local runs one scenario at a time')
    try:
        scenarios = scenarios_from(args)
        if args.out:
            check_results_path(args.out)  # before anything runs
    except ValueError as error:
        parser.error(str(error))
    try:
        rows = run_sweep(scenarios, out=args.out, address=args.address, local=args.local, workers=args.workers)
    except ConnectionError as error:
        print('%s: %s' % (parser.prog, error), file=sys.stderr)
        return 1
    if args.plot:
        plot(rows, args.plot)
    print(summary(rows))
    for row in rows:
        if row['error']:
            print('scenario %d failed: %s' % (row[INDEX_FIELD], row['error']), file=sys.stderr)
    if args.out:
        print('results: %s' % args.out)
    return 0


if __name__ == '__main__':
    # Through the package's module, not __main__: Ray's workers import run_scenario by its name.
    from tianracer_description.sweep import main as sweep_main
    sys.exit(sweep_main())
