"""The command line of a sweep, `/usr/bin/python3 -m tianracer_description.sweep` (see the package's
docstring)."""
import argparse
import sys

from tianracer_description import racing
from tianracer_description.sweep.cluster import run_sweep
from tianracer_description.sweep.results import INDEX_FIELD, check_results_path, plot, summary
from tianracer_description.sweep.scenarios import FIELD_TYPES, RANDOM_RANGES, SCENARIO_FIELDS, grid, random_scenarios


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
