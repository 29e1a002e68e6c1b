"""The compat message packages generate the real packages' md5 sums (docs/interfaces.md section 1):
a real rospy/roscpp client refuses a service whose md5 differs."""
import os
import subprocess

import pytest

# From the real controller_manager_msgs 0.20 and control_msgs 1.5.
REAL_MD5 = {
    ('controller_manager_msgs', 'srv', 'LoadController'): '647e5c54b8d6468952d8d31f1efe96c0',
    ('controller_manager_msgs', 'srv', 'UnloadController'): '647e5c54b8d6468952d8d31f1efe96c0',
    ('controller_manager_msgs', 'srv', 'SwitchController'): 'b29a7abc673b2c54c14b54e50f8d06a5',
    ('controller_manager_msgs', 'srv', 'ListControllers'): '1341feb2e63fa791f855565d0da950d8',
    ('controller_manager_msgs', 'srv', 'ListControllerTypes'): 'c1d4cd11aefa9f97ba4aeb5b33987f4e',
    ('controller_manager_msgs', 'srv', 'ReloadControllerLibraries'): '40e8c411fd1797d2e2c486018f846040',
    ('controller_manager_msgs', 'msg', 'ControllerState'): 'aeb6b261d97793ab74099a3740245272',
    ('controller_manager_msgs', 'msg', 'HardwareInterfaceResources'): 'f25b55cbf1d1f76e82e5ec9e83f76258',
    ('control_msgs', 'msg', 'JointControllerState'): '987ad85e4756f3aef7f1e5e7fe0595d1',
}


@pytest.mark.parametrize('package,kind,name', sorted(REAL_MD5))
def test_python_md5_matches_real_package(package, kind, name):
    module = __import__('%s.%s' % (package, kind), fromlist=[name])
    assert getattr(module, name)._md5sum == REAL_MD5[(package, kind, name)]


@pytest.mark.parametrize('package,kind,name', sorted(REAL_MD5))
def test_cpp_header_md5_matches_real_package(package, kind, name):
    # catkin generates C++ headers into <devel space>/include/<package>/.
    headers = [os.path.join(prefix, 'include', package, name + '.h')
               for prefix in os.environ['CMAKE_PREFIX_PATH'].split(':')]
    header = next((h for h in headers if os.path.isfile(h)), None)
    assert header, 'no generated header among %s' % headers
    with open(header) as f:
        assert '"%s"' % REAL_MD5[(package, kind, name)] in f.read()


def test_switch_controller_constants():
    from controller_manager_msgs.srv import SwitchControllerRequest
    assert (SwitchControllerRequest.BEST_EFFORT, SwitchControllerRequest.STRICT) == (1, 2)


def rospack_find(package):
    """`rospack find PACKAGE`, the command roslaunch's $(find) and rosrun rely on."""
    result = subprocess.run(['rospack', 'find', package], capture_output=True, text=True)
    if result.returncode != 0:
        pytest.fail("rospack cannot find '%s': %s Build and source the workspace "
                    "(make build; source .ws/devel/setup.bash)." % (package, result.stderr.strip()))
    return result.stdout.strip()


def test_every_compat_package_is_found_by_rospack():
    compat = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), 'compat')
    for package in sorted(os.listdir(compat)) + ['tianracer_description']:
        path = rospack_find(package)
        assert os.path.isfile(os.path.join(path, 'package.xml'))
