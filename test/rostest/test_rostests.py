"""The rostest files (test/*.test) run the ROS way, `rostest tianracer_description FILE`, each with its
own ROS master: every <test> in them passes, or this fails with rostest's summary. Debian's python3 is
put first on PATH, since rostest's own nodes (hztest, a user's) start with `/usr/bin/env python3`."""
import glob
import os
import subprocess

import pytest

from suite_paths import TEST_DIR

pytestmark = pytest.mark.ros

ROSTESTS = sorted(os.path.basename(path) for path in glob.glob(os.path.join(TEST_DIR, '*.test')))


def test_there_are_rostests():
    assert {'tutorial.test', 'controller_manager.test', 'simulator.test', 'two_robots.test'} <= set(ROSTESTS)


@pytest.mark.parametrize('launch_file', ROSTESTS)
@pytest.mark.slow
def test_rostest(launch_file, tmp_path):
    env = dict(os.environ, PATH='/usr/bin:' + os.environ['PATH'], ROS_IP='127.0.0.1',
               ROS_HOME=str(tmp_path / 'ros_home'), PYTHONUNBUFFERED='1')
    env.pop('ROS_HOSTNAME', None)
    result = subprocess.run(['rostest', '--results-base-dir', str(tmp_path / 'results'), 'tianracer_description',
                             launch_file], env=env, capture_output=True, text=True, timeout=600)
    summary = result.stdout[result.stdout.rfind('[ROSTEST]'):] if '[ROSTEST]' in result.stdout else result.stdout[-4000:]
    assert result.returncode == 0 and 'RESULT: SUCCESS' in result.stdout, summary + result.stderr[-2000:]
