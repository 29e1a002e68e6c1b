"""Soak: the car on the race track at full speed for SOAK_MINUTES (default 10) of wall time, with the
tutorial's five controllers, every sensor on and read, random commands every simulated half second,
the car put back on the track (reset_world) every 20 simulated seconds and removed and spawned again
every 200. Prints, every 30 s: simulated seconds, real time factor, resident memory (RSS) and its
growth since the end of the first minute (a fifth of shorter runs: allocators settle first), and any non-finite state read
back. Ends with a verdict: no non-finite state and RSS growth under 5 MB. `make soak`.
"""
import math
import os
import random
import sys
import time

import yaml

from tianracer_description import bullet_plant
from tianracer_description.tianracer import (CONFIG_YAML, RACE_TRACK_WORLD, REAR_WHEEL_CONTROLLERS,
                                            STEERING_CONTROLLERS, TUTORIAL_CONTROLLERS, tianracer_urdf)
from tianracer_description.urdf_geometry import ackermann_geometry

MINUTES = float(os.environ.get('SOAK_MINUTES', '10'))
SEED = int(os.environ.get('SOAK_SEED', '1'))
COMMAND_STEPS = 500        # a new random command every 0.5 s simulated
RESET_EVERY = 20000        # steps: back to the start line
RESPAWN_EVERY = 200000     # steps: remove and spawn again
SETTLE_S = min(60.0, MINUTES * 60 / 5)  # wall seconds before the RSS baseline
REPORT_S = 30.0
MAX_RSS_GROWTH_MB = 5.0


def rss_mb():
    with open('/proc/self/status') as f:
        for line in f:
            if line.startswith('VmRSS:'):
                return int(line.split()[1]) / 1024.0
    raise RuntimeError('no VmRSS in /proc/self/status')


def spawn_car(world, urdf):
    car = world.spawn(urdf, 'tianracer')
    manager = car.controller_manager
    loaded, started = manager.spawn(list(TUTORIAL_CONTROLLERS))
    assert started, world.messages()
    for sensor in car.sensors:
        car.enable_sensor(sensor)
    world.step(2)  # the switch happens in the control loop
    return car


def state_finite(world, car):
    values = list(car.base_pose()) + [v for part in car.base_twist() for v in part]
    for joint in car.joint_names:
        values += list(car.joint_state(joint))
    return all(math.isfinite(v) for v in values) and math.isfinite(world.time)


def main():
    rng = random.Random(SEED)
    urdf = tianracer_urdf()
    wheel_radius = ackermann_geometry(urdf).wheel_radius
    with open(RACE_TRACK_WORLD) as f:
        world = bullet_plant.World.from_sdf(f.read())
    world.echo = False
    with open(CONFIG_YAML) as f:
        world.load_params(yaml.safe_load(f))
    car = spawn_car(world, urdf)
    print('soak: %g min at full speed, seed %d; the car on the race track with %s on' % (
        MINUTES, SEED, ', '.join(car.sensors)), flush=True)

    start = time.monotonic()
    end = start + MINUTES * 60
    baseline = None
    next_report = start + REPORT_S
    non_finite = 0
    messages = 0
    while time.monotonic() < end:
        manager = car.controller_manager
        speed = rng.uniform(-3, 3)
        for name in REAR_WHEEL_CONTROLLERS:
            manager.command(name, speed / wheel_radius)
        for name in STEERING_CONTROLLERS:
            manager.command(name, rng.uniform(-0.6, 0.6))
        world.step(COMMAND_STEPS)
        car.scan('lidar')
        car.image('camera')
        car.image('depth_camera')
        manager.joint_states()
        if not state_finite(world, car):
            non_finite += 1
            print('NON-FINITE state at %.1f s simulated' % world.time, flush=True)
        messages += len(world.messages(clear=True))
        if world.steps % RESPAWN_EVERY < COMMAND_STEPS:
            world.remove('tianracer')
            car = spawn_car(world, urdf)
        elif world.steps % RESET_EVERY < COMMAND_STEPS:
            world.reset_world()
        now = time.monotonic()
        if baseline is None and now - start >= SETTLE_S:
            baseline = rss_mb()
        if now >= next_report:
            next_report += REPORT_S
            print('%6.0f s wall  %9.1f s simulated  %5.1fx real time  RSS %.1f MB  growth %s  non-finite %d' % (
                now - start, world.time, world.time / (now - start), rss_mb(),
                '%+.2f MB' % (rss_mb() - baseline) if baseline is not None else '(settling)', non_finite),
                flush=True)
    elapsed = time.monotonic() - start
    growth = rss_mb() - baseline if baseline is not None else float('nan')
    print('soak: %.0f s wall, %.1f s simulated (%.1fx real time), %d plant messages, RSS %.1f MB, growth %+.2f MB '
          'since settling, %d non-finite states' % (elapsed, world.time, world.time / elapsed, messages, rss_mb(),
                                                   growth, non_finite))
    ok = non_finite == 0 and growth < MAX_RSS_GROWTH_MB
    print('soak: %s (no non-finite state, RSS growth under %g MB)' % ('PASS' if ok else 'FAIL', MAX_RSS_GROWTH_MB))
    return 0 if ok else 1


if __name__ == '__main__':
    sys.exit(main())
