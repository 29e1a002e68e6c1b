"""The compat message packages generate the real packages' md5 sums (docs/interfaces.md section 1):
a real rospy/roscpp client refuses a service whose md5 differs."""
import os
import subprocess

import pytest

from suite_paths import REPOSITORY

# From the real controller_manager_msgs 0.20, control_msgs 1.5, gazebo_msgs 2.9 (gazebo_ros_pkgs, ROS 1
# Noetic) and ackermann_msgs 1.0 (docs/interfaces.md sections 1 and 10).
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
    ('gazebo_msgs', 'msg', 'ContactState'): '48c0ffb054b8c444f870cecea1ee50d9',
    ('gazebo_msgs', 'msg', 'ContactsState'): 'acbcb1601a8e525bf72509f18e6f668d',
    ('gazebo_msgs', 'msg', 'LinkState'): '0818ebbf28ce3a08d48ab1eaa7309ebe',
    ('gazebo_msgs', 'msg', 'LinkStates'): '48c080191eb15c41858319b4d8a609c2',
    ('gazebo_msgs', 'msg', 'ModelState'): '9330fd35f2fcd82d457e54bd54e10593',
    ('gazebo_msgs', 'msg', 'ModelStates'): '48c080191eb15c41858319b4d8a609c2',
    ('gazebo_msgs', 'msg', 'ODEJointProperties'): '1b744c32a920af979f53afe2f9c3511f',
    ('gazebo_msgs', 'msg', 'ODEPhysics'): '667d56ddbd547918c32d1934503dc335',
    ('gazebo_msgs', 'msg', 'PerformanceMetrics'): '884f71fd5037b886ec5e126b83c4425a',
    ('gazebo_msgs', 'msg', 'SensorPerformanceMetric'): '01762ded18cfe9ebc7c8222667c99547',
    ('gazebo_msgs', 'msg', 'WorldState'): 'de1a9de3ab7ba97ac0e9ec01a4eb481e',
    ('gazebo_msgs', 'srv', 'ApplyBodyWrench'): '585b9f9618aa0581b207e2f2d90866bc',
    ('gazebo_msgs', 'srv', 'ApplyJointEffort'): 'c0039811b8cc919490b3cff748cdf46b',
    ('gazebo_msgs', 'srv', 'BodyRequest'): '5eade9afe7f232d78005bd0cafeab755',
    ('gazebo_msgs', 'srv', 'DeleteLight'): 'ae11ea8100d536d5b92c2b5917abf912',
    ('gazebo_msgs', 'srv', 'DeleteModel'): '9ce56b4e9e54616de25d796dc972a262',
    ('gazebo_msgs', 'srv', 'GetJointProperties'): '7b30be900f50aa21efec4a0ec92d91c9',
    ('gazebo_msgs', 'srv', 'GetLightProperties'): 'df2cef87e13e2e6990e81e8aaa454c19',
    ('gazebo_msgs', 'srv', 'GetLinkProperties'): '0e06a70386d0ee3fb880c02f23fcd821',
    ('gazebo_msgs', 'srv', 'GetLinkState'): '09d6c98cce97b35f7ab9bd70300657ab',
    ('gazebo_msgs', 'srv', 'GetModelProperties'): '5717f7bd34ed990fa80e28b3015027a3',
    ('gazebo_msgs', 'srv', 'GetModelState'): '4c515e936d3319c9610c559c60bfc3d4',
    ('gazebo_msgs', 'srv', 'GetPhysicsProperties'): '575a5e74786981b7df2e3afc567693a6',
    ('gazebo_msgs', 'srv', 'GetWorldProperties'): '36bb0f2eccf4d8be971410c22818ba3f',
    ('gazebo_msgs', 'srv', 'JointRequest'): '0be1351618e1dc030eb7959d9a4902de',
    ('gazebo_msgs', 'srv', 'SetJointProperties'): '15a76e921b1410c698d82782ea5fa370',
    ('gazebo_msgs', 'srv', 'SetJointTrajectory'): '88f5c10979e3f9649d5ae87a3b12aa65',
    ('gazebo_msgs', 'srv', 'SetLightProperties'): 'e6f13430c57278bb364aca53a1bf5ebf',
    ('gazebo_msgs', 'srv', 'SetLinkProperties'): 'd534ce1b36ee99de0ffa806c3a6348f0',
    ('gazebo_msgs', 'srv', 'SetLinkState'): '8a5146eb66ae4d26b0860b08f3f271be',
    ('gazebo_msgs', 'srv', 'SetModelConfiguration'): '10e3139d3b669c40afc057d38956fff7',
    ('gazebo_msgs', 'srv', 'SetModelState'): '5b3ab0281d4f5445def017e3a2e4a07b',
    ('gazebo_msgs', 'srv', 'SetPhysicsProperties'): '97e2057080558ce4730434b5fae75c91',
    ('gazebo_msgs', 'srv', 'SpawnModel'): '9ed9c82c96abe1a00c3e8cdaeee24413',
    ('ackermann_msgs', 'msg', 'AckermannDrive'): '3512e91b48d69674a0e86fadf1ea8231',
    ('ackermann_msgs', 'msg', 'AckermannDriveStamped'): '1fd5d7f58889cefd44d29f6653240d0c',
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
    compat = os.path.join(REPOSITORY, 'compat')
    for package in sorted(os.listdir(compat)) + ['tianracer_description']:
        path = rospack_find(package)
        assert os.path.isfile(os.path.join(path, 'package.xml'))
