"""What reading SDF costs the plant, now that sdformat reads every document (docs/sdf.md, "One
parser: sdformat"): wall-clock medians of ROUNDS reads each, in one process.

- the first document of a process (sdformat's spec read once, then an empty world);
- an empty world, its text new each round (nothing kept);
- worlds/race_track.world (70 static models), new each round, and read again (kept);
- the car's URDF spawned (its <gazebo> sensors and plugins read by sdformat), new and again.

Instructions are what the plant's hot path is measured in; this is start-up and spawn time, which the
user waits for once per world or spawn, so wall-clock medians on a quiet machine say enough.

    python3 bench/sdf_read_cost.py
"""
import os
import statistics
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), os.pardir, 'test', 'helpers'))
from suite_paths import REPOSITORY  # noqa: E402

ROUNDS = int(os.environ.get('ROUNDS', '7'))


def median_seconds(read):
    times = []
    for round_ in range(ROUNDS):
        start = time.perf_counter()
        read(round_)
        times.append(time.perf_counter() - start)
    return statistics.median(times)


def main():
    start = time.perf_counter()
    from tianracer_description import bullet_plant
    from tianracer_description.tianracer import tianracer_urdf
    imported = time.perf_counter() - start
    start = time.perf_counter()
    bullet_plant.World()  # the empty world: model://sun and model://ground_plane, read by sdformat
    first = time.perf_counter() - start
    print('first world of a process: %.3f s (the module imported in %.3f s)' % (first, imported))

    empty = '<sdf version="1.6"><world name="w%d"/></sdf>'
    print('an empty world, new text: %.1f ms' % (1e3 * median_seconds(
        lambda n: bullet_plant.WorldDescription.from_sdf(empty % n))))

    with open(os.path.join(REPOSITORY, 'worlds', 'race_track.world')) as f:
        track = f.read()
    print('the race track (70 models), new text: %.1f ms' % (1e3 * median_seconds(
        lambda n: bullet_plant.WorldDescription.from_sdf(track.replace('race_track', 'race_track_%d' % n, 1)))))
    print('the race track, read again: %.1f ms' % (1e3 * median_seconds(
        lambda n: bullet_plant.WorldDescription.from_sdf(track))))

    urdf = tianracer_urdf()
    world = bullet_plant.World()
    world.echo = False
    print('the car spawned, its URDF new: %.1f ms' % (1e3 * median_seconds(
        lambda n: world.spawn(urdf.replace('name="tianracer"', 'name="car_%d"' % n, 1), 'new_%d' % n))))
    print('the car spawned again: %.1f ms' % (1e3 * median_seconds(lambda n: world.spawn(urdf, 'again_%d' % n))))


if __name__ == '__main__':
    main()
