"""Shared fixtures. The suite runs through `make test`, which builds the catkin workspace and
sources it; run by hand, `source .ws/devel/setup.bash` first. The car's files, controller names
and URDF come from tianracer_description.tianracer, the ROS processes from
tianracer_description.ros_harness (imported inside the fixtures: without a sourced workspace
pytest_sessionstart says so instead of an import error)."""
import os
import shutil

import pytest
import yaml


def pytest_sessionstart(session):
    if shutil.which('rospack') is None or 'ROS_PACKAGE_PATH' not in os.environ:
        pytest.exit('The ROS workspace is not sourced: run the suite with `make test`, or '
                    '`source .ws/devel/setup.bash` first.', returncode=2)


@pytest.fixture(scope='session')
def urdf_xml():
    from tianracer_description.tianracer import tianracer_urdf
    return tianracer_urdf()


@pytest.fixture(scope='session')
def urdf_file(urdf_xml, tmp_path_factory):
    """The car's URDF in a file, for `rosparam set --textfile` and spawn_model."""
    path = tmp_path_factory.mktemp('model') / 'tianracer.urdf'
    path.write_text(urdf_xml)
    return str(path)


@pytest.fixture(scope='session')
def control_config():
    from tianracer_description.tianracer import CONFIG_YAML
    with open(CONFIG_YAML) as f:
        return yaml.safe_load(f)


@pytest.fixture
def ros(request, tmp_path):
    """A ROS master of the test's own on a free loopback port; its processes stop after the test."""
    if request.node.get_closest_marker('ros') is None:
        pytest.fail("%s starts a ROS master: mark it ros (pytestmark = pytest.mark.ros) so that "
                    "-m 'not ros' leaves it out" % request.node.nodeid, pytrace=False)
    from tianracer_description.ros_harness import RosSystem
    system = RosSystem(str(tmp_path))
    yield system
    system.close()
