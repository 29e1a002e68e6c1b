"""What racing for learning costs (`make bench-racing`): environment steps a second of the Gymnasium
environments, side by side in one run.

The tutorial's car with its IMU and the 1081-ray lidar (40 Hz, ray-cast in 3-D by Embree) on
worlds/race_track.world (boxes) and on the mesh race track of bench/sensor_bench.py (the same walls
as one OBJ, a textured OBJ floor; the same centre line), driven by follow the gap at the default
10 ms control period (ten 1 ms physics steps an env step). Per round, in turn:
- physics: the car on its controllers with no sensor enabled, physics steps per CPU second;
- single: RaceEnv, env steps per CPU second (one core's worth) and per wall second; and per CPU
  second with physics_dt 5 ms (docs/racing.md, "A larger physics step for learning");
- vector: RaceVectorEnv with 4, 8 and 16 cars (VECTOR_ENVS) on one thread and on two, env steps per
  wall second (all cars), and the two threads' gain over one. The two envs are stepped in turn, in
  blocks of VECTOR_BLOCK env steps, so that the machine's moments fall on both alike. What a vector step
  costs besides its worlds (the Python around CarBatch, about 70 us with the caches cold from the
  worlds) is the same for any number of cars, and a world goes to a thread whole (one that scans
  costs twice one that does not): more cars gain more from the second thread (docs/design.md, "What
  an environment step costs", sums it up).
- physics on the race circuit (258 walls) over physics on an empty world, the same car (issue 42's
  target: at most 1.10, a broad phase and step that do not grow with static walls far from the car);
- the machine's own: two processes each running the single env at once, their env steps per wall
  second together over one process's alone (the same code side by side, nothing shared): what the
  two cores give at that moment, the ceiling of the vector env's x2/x1. On this shared VM it moves
  between rounds, and the vector env's gain with it.
Only the environment's own calls are timed (the policy's are not), from the first step on: episodes
that end are reset, and those resets are timed (a vector env's within its step), the first reset is
not (for 16 cars it makes 16 worlds one after another, 40 ms: a seventh of the measurement on two
threads, where a training run pays it once). Medians of ROUNDS rounds, and the real time factor env steps make (x 0.01 s).
Targets (issue 27): 4,000 env steps per second per core for the single env; the vector env on 2 cores
1.8 times one.
f1tenth_gym says "up to 30x realtime" (a kinematic single-track model and a 2-D ray-marched lidar;
no hardware or method given): printed beside ours, for what a comparison without its numbers is worth.
"""
import os
import statistics
import subprocess
import sys
import tempfile
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from sensor_bench import cpu_name, write_mesh_track  # noqa: E402
from tianracer_description.racing.car import CarModel, new_world  # noqa: E402
from tianracer_description.racing.cars import RaceCars, race_parts, steps_per_action  # noqa: E402
from tianracer_description.racing.env import RaceEnv  # noqa: E402
from tianracer_description.racing.follow_the_gap import FollowTheGap  # noqa: E402
from tianracer_description.racing.track import centerline_file  # noqa: E402
from tianracer_description.racing.vector_env import RaceVectorEnv  # noqa: E402
from tianracer_description.tianracer import RACE_CIRCUIT_WORLD, RACE_TRACK_WORLD  # noqa: E402

ROUNDS = 5
ENV_STEPS = 3000  # a measurement: this many env steps (single) or vector steps x cars
COARSE_PHYSICS_DT = 0.005  # the single env again with this physics_dt (s)
VECTOR_ENVS = (4, 8, 16)
VECTOR_BLOCK = 500  # env steps (vector steps x cars) on one env before the other's turn
CONTROL_PERIOD = 0.01  # s
F1TENTH_PUBLISHED = 30.0  # "up to 30x realtime"


def physics(world_file, wheel_speed=15.0, steps=10 * ENV_STEPS):
    """Physics steps per CPU second of the car on its controllers (rear wheels at wheel_speed rad/s),
    no sensor enabled."""
    model = CarModel()
    world = new_world(world_file, model.controllers)
    robot = model.spawn(world, 'car', (0.0, 0.0, 0.0))
    for controller in ('rear_left_velocity_controller', 'rear_right_velocity_controller'):
        robot.controller_manager.command(controller, wheel_speed)
    world.step(100)
    start = time.process_time()
    world.step(steps)
    return steps / (time.process_time() - start)


def walls_over_empty_world():
    """Physics on the race circuit (258 walls) over physics on an empty world: the car rolling slowly
    from the start (2 rad/s, 8 cm in the 5 s measured), so that it meets no wall on the circuit
    and the two worlds differ by the walls alone."""
    return physics(None, 2.0, 5000) / physics(RACE_CIRCUIT_WORLD, 2.0, 5000)


def single(world_file, centerline, physics_dt=None):
    """RaceEnv's env steps per CPU second and per wall second (its calls only)."""
    env = RaceEnv(world_file, centerline=centerline, physics_dt=physics_dt)
    policy = FollowTheGap.for_env(env)
    cpu = wall = 0.0
    observation, _ = env.reset(seed=0)
    for _ in range(ENV_STEPS):
        action = policy(observation)
        c0, w0 = time.process_time(), time.perf_counter()
        observation, _, terminated, truncated, _ = env.step(action)
        if terminated or truncated:
            observation, _ = env.reset()
        cpu += time.process_time() - c0
        wall += time.perf_counter() - w0
    return ENV_STEPS / cpu, ENV_STEPS / wall


def two_processes(world_file, centerline):
    """Env steps per wall second of two processes each running single() at once (their sum)."""
    children = [subprocess.Popen([sys.executable, os.path.abspath(__file__), '--single', world_file, centerline],
                                 stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True) for _ in range(2)]
    for child in children:  # each has built its env: start both timed loops together
        if child.stdout.readline().strip() != 'ready':
            raise RuntimeError('a --single child of %s did not start' % __file__)
    for child in children:
        child.stdin.write('go\n')
        child.stdin.flush()
    rates = [float(child.communicate()[0].split()[-1]) for child in children]
    if any(child.returncode for child in children):
        raise RuntimeError('a --single child of %s failed' % __file__)
    return sum(rates)


def single_child(world_file, centerline):
    """two_processes' side: single() once the parent says go (its env's calls timed, as single() times
    them); prints their env steps per wall second."""
    RaceEnv(world_file, centerline=centerline)  # the files read and the xacro run: the first env's cost
    print('ready', flush=True)
    sys.stdin.readline()
    print(single(world_file, centerline)[1], flush=True)


def vector(world_file, centerline, cars):
    """RaceVectorEnv's env steps (all cars) per wall second on one thread and on two ({threads: rate};
    their calls only): two envs side by side, stepped in turn in blocks of VECTOR_BLOCK env steps, so
    that the machine's good and bad moments fall on both alike and their ratio holds still."""
    envs = {threads: RaceVectorEnv(cars, world_file, centerline=centerline, threads=threads, max_episode_steps=2000)
            for threads in (1, 2)}
    policy = FollowTheGap.for_env(envs[1])
    observations = {threads: env.reset(seed=0)[0] for threads, env in envs.items()}
    wall = {1: 0.0, 2: 0.0}
    steps, block_steps = ENV_STEPS // cars, max(1, VECTOR_BLOCK // cars)
    for block, first in enumerate(range(0, steps, block_steps)):
        for threads in ((1, 2) if block % 2 == 0 else (2, 1)):
            for _ in range(min(block_steps, steps - first)):
                actions = np.array([policy({'scan': observations[threads]['scan'][i]}) for i in range(cars)])
                w0 = time.perf_counter()
                observations[threads], *_ = envs[threads].step(actions)
                wall[threads] += time.perf_counter() - w0
    return {threads: steps * cars / wall[threads] for threads in (1, 2)}


def schedule_ceiling(world_file, centerline, cars, phases_apart):
    """What a second thread could gain on the worlds alone, a world going to a thread whole: at every
    vector step of follow the gap each car's world is stepped and timed alone on one thread, then the
    step's worlds are handed to two threads as CarBatch hands them (those that scanned first, each to
    the thread that comes free first). Returns the sum of the worlds' times over the sum of the two
    threads' longest. With phases_apart each car first steps 0-24 ms alone, as resets leave the cars
    of a training run; without, they scan in the same steps."""
    track, model, lidar = race_parts(world_file, centerline, None, None, 2.0)
    race = RaceCars(track, model, lidar, ['car'] * cars)
    rng = np.random.default_rng(0)
    for i in range(cars):
        race.place(i, track.start_pose(rng))
    scans, state = race.settle()
    if phases_apart:
        for i in range(cars):
            ahead = int(rng.integers(0, 25))
            if ahead:
                race.batch.drive(np.zeros((1, 2)), ahead, [i])
    policy = FollowTheGap(lidar.angle_min, lidar.angle_increment, model.max_steering)
    steps = steps_per_action(CONTROL_PERIOD, race.worlds[0].time_step)
    total = makespan = 0.0
    for k in range(ENV_STEPS // cars):
        actions = np.array([policy({'scan': scans[i]}) for i in range(cars)], np.float64)
        costs, scanned = np.empty(cars), np.empty(cars, bool)
        for i in range(cars):
            w0 = time.perf_counter()
            scan, _ = race.batch.drive(actions[i:i + 1], steps, [i])
            costs[i] = time.perf_counter() - w0
            scanned[i] = not np.array_equal(scan[0], scans[i])  # (the noise makes every new scan differ)
            scans[i] = scan[0]
        threads = [0.0, 0.0]
        for i in sorted(range(cars), key=lambda i: not scanned[i]):
            threads[threads.index(min(threads))] += costs[i]
        total, makespan = total + costs.sum(), makespan + max(threads)
    return total / makespan


def main():
    workdir = tempfile.mkdtemp(prefix='racing_bench_')
    mesh_world, _ = write_mesh_track(workdir)
    centerline = centerline_file(RACE_TRACK_WORLD)
    tracks = {'race track (boxes)': RACE_TRACK_WORLD, 'mesh race track': mesh_world}
    print('CPU: %s, %d cores; %d rounds, medians; the 1081-ray lidar at 40 Hz, 10 ms control'
          % (cpu_name(), os.cpu_count(), ROUNDS), flush=True)
    results = {name: {'physics': [], 'single_cpu': [], 'single_wall': [], 'single_5ms': [], 'two_processes': [],
                      **{(cars, threads): [] for cars in VECTOR_ENVS for threads in (1, 2)}}
               for name in tracks}
    walls_over_empty = []
    for round_ in range(ROUNDS):
        walls_over_empty.append(walls_over_empty_world())
        for name, world_file in tracks.items():
            r = results[name]
            r['physics'].append(physics(world_file))
            cpu, wall = single(world_file, centerline)
            r['single_cpu'].append(cpu)
            r['single_wall'].append(wall)
            r['single_5ms'].append(single(world_file, centerline, COARSE_PHYSICS_DT)[0])
            r['two_processes'].append(two_processes(world_file, centerline))
            for cars in VECTOR_ENVS:
                for threads, rate in vector(world_file, centerline, cars).items():
                    r[(cars, threads)].append(rate)
        print('round %d of %d done' % (round_ + 1, ROUNDS), flush=True)
    print()
    vector_titles = ['%d cars x%d' % (cars, threads) for cars in VECTOR_ENVS for threads in (1, 2)]
    print('%-20s %14s %13s %14s %13s' % ('', 'physics/CPU-s', 'single/CPU-s', 'single/wall-s', '5 ms/CPU-s')
          + ''.join(' %12s' % t for t in vector_titles) + ''.join(' %9s' % ('%d: x2/x1' % c) for c in VECTOR_ENVS)
          + ' %9s' % 'machine')
    for name, r in results.items():
        m = {k: statistics.median(v) for k, v in r.items()}
        gains = [statistics.median(b / a for a, b in zip(r[(cars, 1)], r[(cars, 2)])) for cars in VECTOR_ENVS]
        machine = statistics.median(two / one for one, two in zip(r['single_wall'], r['two_processes']))
        print('%-20s %14.0f %13.0f %14.0f %13.0f' % (name, m['physics'], m['single_cpu'], m['single_wall'], m['single_5ms'])
              + ''.join(' %12.0f' % m[(cars, threads)] for cars in VECTOR_ENVS for threads in (1, 2))
              + ''.join(' %9.2f' % g for g in gains) + ' %9.2f' % machine)
    print()
    for name, r in results.items():
        single_rtf = statistics.median(r['single_cpu']) * CONTROL_PERIOD
        vector_rtf = max(statistics.median(r[(cars, 2)]) for cars in VECTOR_ENVS) * CONTROL_PERIOD
        print('%s: one core %.0fx real time (single env), two cores %.0fx (vector env); f1tenth_gym '
              'publishes "up to %.0fx" (2-D, no hardware given)' % (name, single_rtf, vector_rtf, F1TENTH_PUBLISHED))
    print('machine: two processes of the single env at once over one (the two cores\' own gain, this run)')
    for name, world_file in tracks.items():
        print('%s, the worlds alone handed whole to two threads (no Python, no join), the ceiling of x2/x1: %s' % (
            name, ', '.join('%d cars %.2f in phase, %.2f apart' % (cars, schedule_ceiling(world_file, centerline, cars, False),
                                                                  schedule_ceiling(world_file, centerline, cars, True))
                            for cars in VECTOR_ENVS)), flush=True)
    print('physics on the race circuit (258 walls) over an empty world: %.3f (median; rounds %s)'
          % (statistics.median(walls_over_empty), ', '.join('%.3f' % r for r in walls_over_empty)))
    print('targets: single env >= 4000 env steps per CPU second; vector env on 2 threads >= 1.8x one; '
          'the race circuit\'s physics at most 1.10 x the empty world\'s; issue 42: 2x f1tenth_gym\'s single env on '
          'the same map (bench/f1tenth_side_by_side.py runs both, by hand)')


if __name__ == '__main__':
    if sys.argv[1:2] == ['--single']:
        single_child(*sys.argv[2:4])
    else:
        main()
