"""What a world's static models cost a step: instructions per physics step under callgrind (as
bench/step_cost.py counts them: (Ir(long) - Ir(short)) / (long - short) steps) of the Tianracer driving
at 1 m/s with its lidar on, through a world of N static box models (posts 2 m apart on a square grid,
the car on a lane between two rows), and of the same car on the ground alone.

    source .ws/devel/setup.bash; /usr/bin/python3 bench/static_models_cost.py [--models 1000]
    ... bench/static_models_cost.py --world FILE [--pose X Y YAW]   # that world's instead (the house, a circuit)

Static models are models (listed, moved, removed) and their shapes stay in the world's static scene:
the figure must not grow with what they became.
"""
import argparse
import math
import os
import subprocess
import sys
import tempfile

from step_cost import callgrind_total  # beside this file

STEPS_SHORT, STEPS_LONG = 500, 1500

RUN = """
import sys
from tianracer_description import bullet_plant
from tianracer_description.tianracer import CONFIG_YAML, TUTORIAL_CONTROLLERS, tianracer_urdf
world = bullet_plant.World.from_file(sys.argv[1])
world.echo = False
world.load_params(CONFIG_YAML)
x, y, yaw = (float(v) for v in sys.argv[3:6])
car = world.spawn(tianracer_urdf(), 'tianracer', pose=(x, y, 0.0, 0.0, 0.0, yaw))
manager = car.controller_manager
manager.spawn(list(TUTORIAL_CONTROLLERS))
world.step(2)
for name in ('rear_left_velocity_controller', 'rear_right_velocity_controller'):
    manager.command(name, 31.25)
car.enable_sensor('lidar')
world.step(int(sys.argv[2]))
"""


def posts_world(count):
    """A world of `count` static 0.1 x 0.1 x 0.5 m posts, 2 m apart on a square grid around the origin."""
    side = math.ceil(math.sqrt(count))
    posts = []
    for k in range(count):
        x, y = 2.0 * (k % side - side // 2), 2.0 * (k // side - side // 2)
        posts.append(f"""<model name="post_{k}"><static>true</static><pose>{x} {y} 0.25 0 0 0</pose>
  <link name="link"><collision name="c"><geometry><box><size>0.1 0.1 0.5</size></box></geometry></collision>
    <visual name="v"><geometry><box><size>0.1 0.1 0.5</size></box></geometry></visual></link></model>""")
    return f"""<?xml version="1.0"?><sdf version="1.6"><world name="posts">
  <include><uri>model://ground_plane</uri></include>{''.join(posts)}</world></sdf>"""


def per_step(world_file, workdir, tag, pose=(0.0, 1.0, 0.0)):
    def total(steps):
        return callgrind_total([sys.executable, '-c', RUN, world_file, str(steps), *map(str, pose)],
                               os.path.join(workdir, 'callgrind.%s.%d' % (tag, steps)))
    return (total(STEPS_LONG) - total(STEPS_SHORT)) / (STEPS_LONG - STEPS_SHORT)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument('--models', type=int, default=1000, help='static models in the world (default 1000)')
    parser.add_argument('--world', help='a world file to measure instead of the posts')
    parser.add_argument('--pose', nargs=3, type=float, default=(0.0, 1.0, 0.0), metavar=('X', 'Y', 'YAW'),
                        help="where the car starts in --world's (default 0 1 0)")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as workdir:
        if args.world:
            cost = per_step(os.path.abspath(args.world), workdir, 'world', tuple(args.pose))
            print('instructions per step, the car driving with its lidar on in %s: %.1fk' % (args.world, cost / 1000))
            return
        files = {}
        for tag, count in (('ground', 0), ('posts', args.models)):
            files[tag] = os.path.join(workdir, tag + '.world')
            with open(files[tag], 'w') as f:
                f.write(posts_world(count))
        ground = per_step(files['ground'], workdir, 'ground')
        posts = per_step(files['posts'], workdir, 'posts')
        print('instructions per step, the car driving with its lidar on: the ground alone %.1fk, among %d static '
              'models %.1fk: %.3fx' % (ground / 1000, args.models, posts / 1000, posts / ground))


if __name__ == '__main__':
    main()
