#!/usr/bin/env python3
"""Records the reference frames test/test_camera_references.py compares the OpenGL cameras with:
the car's colour and depth cameras as the ray caster renders them (TIANRACER_GL_DEVICE=gpu on a
machine without a GPU makes the cameras cast rays; the script checks that they did), on the worlds
this package ships, from the poses SCENES names. Writes test/data/camera_references/<world>_<pose>_
{camera.png, depth_camera_depth.npy}. Run once, with /usr/bin/python3 and the workspace sourced:

    TIANRACER_GL_DEVICE=gpu tools/make_camera_references.py
"""
import os
import sys
import tempfile

import matplotlib
matplotlib.use('Agg')
import matplotlib.image  # noqa: E402
import numpy as np  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, os.pardir, 'test', 'data', 'camera_references')
BENCH = os.path.join(HERE, os.pardir, 'bench')
MESH_RACE_TRACK = 'mesh_race_track.world'  # written by bench/sensor_bench.py, not shipped

# world file (in worlds/), the car's pose (x y z roll pitch yaw), a name for both
SCENES = [('race_track.world', (0.0, 0.0, 0.05, 0, 0, 0.0), 'start'),
          ('race_track.world', (1.5, -0.4, 0.05, 0, 0, 0.8), 'turned'),
          ('arena.world', (0.0, 0.0, 0.05, 0, 0, 0.4), 'centre'),
          (MESH_RACE_TRACK, (0.0, 0.0, 0.05, 0, 0, 0.0), 'start'),
          (MESH_RACE_TRACK, (-4.4, 2.2, 0.05, 0, 0, -1.9), 'bend')]


def world_file(world, directory):
    """The path of `world`: one of worlds/, or the mesh race track written into `directory`."""
    if world != MESH_RACE_TRACK:
        return os.path.join(HERE, os.pardir, 'worlds', world)
    sys.path.insert(0, BENCH)
    from sensor_bench import write_mesh_track
    return write_mesh_track(directory)[0]


def frames(world_file, pose):
    """The car's camera (rgb) and depth camera (depth) frames after 0.3 s at `pose`, and what the
    plant said about how cameras render."""
    from tianracer_description import bullet_plant
    from tianracer_description.tianracer import CONFIG_YAML, tianracer_urdf
    world = bullet_plant.World.from_file(world_file)
    world.echo = False
    world.load_params(CONFIG_YAML)
    car = world.spawn(tianracer_urdf(), 'tianracer', pose=pose)
    car.enable_sensor('camera')
    car.enable_sensor('depth_camera')
    world.step(300)
    said = [text for _, text in world.messages() if text.startswith('cameras:')]
    return car.image('camera')['rgb'], car.image('depth_camera')['depth'], said


def main():
    os.makedirs(OUT, exist_ok=True)
    only = sys.argv[1:]  # scene stems (race_track_start ...) to record again; all when none
    directory = tempfile.mkdtemp()
    for world, pose, name in SCENES:
        stem = os.path.join(OUT, '%s_%s' % (os.path.splitext(world)[0], name))
        if only and os.path.basename(stem) not in only:
            continue
        rgb, depth, said = frames(world_file(world, directory), pose)
        if not said or 'they cast rays instead' not in said[0]:
            sys.exit('make_camera_references: the cameras did not cast rays (%s): run it with '
                     'TIANRACER_GL_DEVICE=gpu on a machine without a GPU' % said)
        matplotlib.image.imsave(stem + '_camera.png', rgb)
        np.save(stem + '_depth_camera_depth.npy', depth.astype(np.float32))
        print('wrote', stem + '_*')


if __name__ == '__main__':
    main()
