"""Shared fixtures. The suite runs through `make test`, which builds the catkin workspace and
sources it; run by hand, `source .ws/devel/setup.bash` first."""
import os
import shutil
import subprocess

import pytest
import yaml

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CONFIG_YAML = os.path.join(REPO, 'config', 'smart_control_config.yaml')
MODEL_XACRO = 'urdf/tianracer_description.xacro'


def rospack_find(package):
    result = subprocess.run(['rospack', 'find', package], capture_output=True, text=True)
    if result.returncode != 0:
        pytest.fail("rospack cannot find '%s': %s Build and source the workspace "
                    "(make build; source .ws/devel/setup.bash)." % (package, result.stderr.strip()))
    return result.stdout.strip()


def pytest_sessionstart(session):
    if shutil.which('rospack') is None or 'ROS_PACKAGE_PATH' not in os.environ:
        pytest.exit('The ROS workspace is not sourced: run the suite with `make test`, or '
                    '`source .ws/devel/setup.bash` first.', returncode=2)


def run_xacro(xacro_file, *args):
    """Run xacro the way a launch file does: $(find xacro)/xacro --inorder FILE."""
    return subprocess.run([os.path.join(rospack_find('xacro'), 'xacro'), '--inorder', xacro_file, *args],
                          capture_output=True, text=True)


@pytest.fixture(scope='session')
def urdf_xml():
    result = run_xacro(os.path.join(rospack_find('tianracer_description'), MODEL_XACRO))
    assert result.returncode == 0, result.stderr
    return result.stdout


@pytest.fixture(scope='session')
def control_config():
    with open(CONFIG_YAML) as f:
        return yaml.safe_load(f)
