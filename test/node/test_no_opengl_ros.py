"""The node on a machine with no EGL driver at all (glvnd's libEGL given no vendor file: what a
machine without Mesa's libegl-mesa0 or a GPU's driver has): it starts, says once on /rosout that
the cameras are off and why, publishes no camera image, and everything else runs: the car spawns,
the tutorial's controllers start and turn a wheel, the lidar scans, /clock advances."""
import pytest

from ros_harness import tianracer_plant
from tianracer_description.tianracer import TUTORIAL_CONTROLLERS

pytestmark = pytest.mark.ros

NS = '/tianracer'


@pytest.mark.slow
def test_without_egl_the_node_runs_with_its_cameras_off(ros, urdf_file):
    ros.env['__EGL_VENDOR_LIBRARY_FILENAMES'] = '/nonexistent/egl_vendor.json'
    plant = tianracer_plant(ros, urdf_file)
    ros.start(['rosrun', 'controller_manager', 'spawner', '__ns:=' + NS, *TUTORIAL_CONTROLLERS], 'spawner')
    ros.wait_for_controllers(len(TUTORIAL_CONTROLLERS), namespace=NS)
    seen = ros.probe('node/probes/without_egl_the_node_runs_with_its_cameras_off.py', NS, timeout=90)
    log = plant.log()
    assert 'cameras: off, no OpenGL (' in log and 'every other sensor runs' in log, log[-3000:]
    assert log.count('cameras: off') == 1, 'said once'
    assert seen['images'] == [], 'no camera image'
    assert seen['ranges'] == 1081
    assert seen['wheel'] == pytest.approx(8.0, abs=0.2)
    assert seen['clock'] > 2.0
