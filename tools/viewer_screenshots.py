"""The README's and docs/viewer.md's screenshots of the browser viewer (docs/images/viewer_*.png), made the way
test/viewer/test_viewer.py opens the page (Debian's chromium, headless): the race track with the car, its
camera's overlay and its lidar's hits, and the mesh track of test/fixtures/gazebo_pkg.

    source .ws/devel/setup.bash; export ROS_IP=127.0.0.1; /usr/bin/python3 tools/viewer_screenshots.py
"""
import os
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path[:0] = [os.path.join(HERE, os.pardir, 'test', 'helpers'), os.path.join(HERE, os.pardir, 'test', 'viewer')]
from plant_helpers import FIXTURES, TRACK_WORLD  # noqa: E402
from test_viewer import opened, tick_overlay  # noqa: E402
from ros_harness import RosSystem  # noqa: E402
from tianracer_description.tianracer import RACE_TRACK_WORLD, tianracer_urdf  # noqa: E402

OUT = os.path.join(HERE, os.pardir, 'docs', 'images')


def shoot(world, name, urdf_file=None, eye=None, target=None, overlays=()):
    with tempfile.TemporaryDirectory() as workdir:
        ros = RosSystem(workdir)
        try:
            with opened(ros, world, urdf_file) as (_, _, driver, _):
                if eye:
                    driver.execute_script('viewer.lookAt(arguments[0], arguments[1])', eye, target)
                for topic in overlays:
                    tick_overlay(driver, topic, topic)
                time.sleep(0.5)
                driver.save_screenshot(os.path.join(OUT, name))
        finally:
            ros.close()
    print('wrote', os.path.join(OUT, name))


def main():
    os.makedirs(OUT, exist_ok=True)
    with tempfile.NamedTemporaryFile('w', suffix='.urdf') as urdf:
        urdf.write(tianracer_urdf())
        urdf.flush()
        shoot(RACE_TRACK_WORLD, 'viewer_race_track.png', urdf.name, eye=[-1.6, -1.9, 1.2], target=[0.6, 0.4, 0],
              overlays=('/camera/image_raw', '/scan'))
    os.environ['ROS_PACKAGE_PATH'] = FIXTURES + os.pathsep + os.environ['ROS_PACKAGE_PATH']
    shoot(TRACK_WORLD, 'viewer_mesh_track.png', eye=[-2.0, -4.0, 4.0], target=[5.0, 0, 0.5])


if __name__ == '__main__':
    main()
