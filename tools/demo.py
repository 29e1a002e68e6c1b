#!/usr/bin/python3
"""`make demo`: the Tianracer drives a figure-eight in worlds/arena.world, headless, at four times real
time (figure_eight.py paces its commands by simulated time: the same figures as at real time, in half
the wall time), on a ROS master of its own (a free loopback port); prints the figures and writes
figure_eight.png here."""
import os
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), os.pardir, 'test', 'helpers'))
from ros_harness import RosSystem  # noqa: E402  (the test harness: a ROS master of its own)
from tianracer_description.tianracer import PACKAGE, TUTORIAL_CONTROLLERS  # noqa: E402


def main():
    plot = os.path.join(os.getcwd(), 'figure_eight.png')
    with tempfile.TemporaryDirectory() as workdir:
        ros = RosSystem(workdir)
        try:
            ros.start(['roslaunch', 'tianracer_description', 'tianracer_world.launch', 'gui:=false',
                       'real_time_factor:=4',
                       'world_name:=' + os.path.join(PACKAGE, 'worlds', 'arena.world')], 'tianracer_launch')
            ros.wait_for_controllers(len(TUTORIAL_CONTROLLERS))
            demo = ros.run(['rosrun', 'tianracer_description', 'figure_eight.py', '_plot:=' + plot], timeout=180)
            print(demo.stdout.strip())
            if demo.returncode != 0:
                print(demo.stderr, file=sys.stderr)
                return 1
        finally:
            ros.close()
    return 0


if __name__ == '__main__':
    sys.exit(main())
