"""What one physics step costs, counted rather than timed, and a fingerprint of what it computes
(`make step-cost`).

Instructions per step: the Tianracer from the xacro output with config/smart_control_config.yaml,
the tutorial's five controllers spawned and the rear wheels commanded 31.25 rad/s (1 m/s), in an
empty world with 1 ms steps, run under `valgrind --tool=callgrind` for STEPS_SHORT and STEPS_LONG
steps; (Ir(long) - Ir(short)) / (long - short) is the cost of one step with Python's start-up and
the spawn subtracted. Instruction counts do not depend on the load of the machine, so they judge a
change to the hot path where times cannot.

Trajectory digest: the same car on worlds/race_track.world driving and steering through a command
sequence for DIGEST_STEPS steps with its lidar and cameras on (it drives into the track's first cone
and pushes against it: wheel, body and cone contacts); the SHA-256 of every reported number
(poses, twists, joint states, scans, images) after every 100 steps. A change that only moves code
(a refactoring) keeps the digest bit for bit; one that changes the arithmetic changes it. The
physics digest hashes the poses, twists and joint states alone: a change to how sensors render
changes the first digest and keeps this one.
"""
import argparse
import hashlib
import os
import re
import subprocess
import sys
import tempfile

import numpy as np

from tianracer_description import bullet_plant
from tianracer_description.tianracer import (CONFIG_YAML, RACE_TRACK_WORLD, REAR_WHEEL_CONTROLLERS, TUTORIAL_CONTROLLERS,
                                            tianracer_urdf)

STEPS_SHORT, STEPS_LONG = 500, 1500
DIGEST_STEPS = 6000
WHEEL_RATE = 31.25  # rad/s: 1 m/s on the 0.032 m wheels


def driving_car(urdf, world_sdf=None):
    world = bullet_plant.World.from_sdf(world_sdf) if world_sdf else bullet_plant.World()
    world.echo = False
    world.load_params(CONFIG_YAML)
    car = world.spawn(urdf, 'tianracer', pose=(0, 0, 0, 0, 0, 0))
    manager = car.controller_manager
    manager.spawn(list(TUTORIAL_CONTROLLERS))
    # The switch happens in the control loop, which resets the controllers' commands: a command given
    # before it is lost (until stop 45 this car stood still through every figure and digest).
    world.step(2)
    for name in REAR_WHEEL_CONTROLLERS:
        manager.command(name, WHEEL_RATE)
    return world, car, manager


def run_steps(steps, urdf_path):
    with open(urdf_path) as f:
        world, _, _ = driving_car(f.read())
    world.step(steps)


def callgrind_instructions(steps, urdf_path, workdir):
    return callgrind_total([sys.executable, __file__, '--run', str(steps), '--urdf', urdf_path],
                           os.path.join(workdir, 'callgrind.%d' % steps))


def callgrind_total(command, out):
    """The instructions `command` executes, counted by callgrind (its output file: `out`)."""
    # One hash seed for every run: with Python's random one, its start-up differs between the two
    # processes by enough to move the per-step figure by about 1 % between runs of the same build.
    subprocess.run(['valgrind', '--tool=callgrind', '--callgrind-out-file=' + out] + command,
                   check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                   env=dict(os.environ, PYTHONHASHSEED='0'))
    with open(out) as f:
        for line in f:
            match = re.match(r'(?:summary|totals):\s+(\d+)', line)
            if match:
                return int(match.group(1))
    raise RuntimeError('no instruction total in ' + out)


def digest(urdf):
    with open(RACE_TRACK_WORLD) as f:
        world, car, manager = driving_car(urdf, f.read())
    for sensor in ('lidar', 'camera', 'depth_camera'):
        car.enable_sensor(sensor)
    sha, physics = hashlib.sha256(), hashlib.sha256()
    steering = ('front_left_steering_position_controller', 'front_right_steering_position_controller')
    travelled, last = 0.0, np.array(car.base_pose()[:2])
    for chunk in range(DIGEST_STEPS // 100):
        angle = 0.3 * np.sin(chunk / 7.0)
        for name in steering:
            manager.command(name, angle)
        world.step(100)
        here = np.array(car.base_pose()[:2])
        travelled, last = travelled + float(np.hypot(*(here - last))), here
        values = list(car.base_pose())
        linear, angular = car.base_twist()
        values += list(linear) + list(angular)
        for joint in car.joint_names:
            values += list(car.joint_state(joint))
        sha.update(np.array(values, dtype=np.float64).tobytes())
        physics.update(np.array(values, dtype=np.float64).tobytes())
        sha.update(np.asarray(car.scan('lidar')['ranges'], dtype=np.float32).tobytes())
        sha.update(np.asarray(car.image('camera')['rgb']).tobytes())
        sha.update(np.asarray(car.image('depth_camera')['depth'], dtype=np.float32).tobytes())
    # At 1 m/s it meets the track's first cone, 1.5 m ahead, after 1.3 m, and pushes against it.
    if travelled < 1.0:
        raise RuntimeError('the car went %.2f m in %g s: it should drive 1.3 m, into the first cone' %
                           (travelled, DIGEST_STEPS * 1e-3))
    return sha.hexdigest(), physics.hexdigest()


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument('--run', type=int, help=argparse.SUPPRESS)   # the process callgrind counts
    parser.add_argument('--urdf', help=argparse.SUPPRESS)
    parser.add_argument('--digest-only', action='store_true', help='print the trajectory digest only')
    args = parser.parse_args()
    if args.run is not None:
        run_steps(args.run, args.urdf)
        return
    urdf = tianracer_urdf()
    everything, physics = digest(urdf)
    print('trajectory digest (%d steps on the race track, sensors on): %s' % (DIGEST_STEPS, everything))
    print('physics digest (the same run\'s poses, twists and joint states only): %s' % physics)
    if args.digest_only:
        return
    with tempfile.TemporaryDirectory() as workdir:
        urdf_path = os.path.join(workdir, 'tianracer.urdf')
        with open(urdf_path, 'w') as f:
            f.write(urdf)
        short = callgrind_instructions(STEPS_SHORT, urdf_path, workdir)
        long = callgrind_instructions(STEPS_LONG, urdf_path, workdir)
    print('instructions per step (callgrind, the car driving with the five controllers): %.1fk'
          % ((long - short) / (STEPS_LONG - STEPS_SHORT) / 1000.0))


if __name__ == '__main__':
    main()
