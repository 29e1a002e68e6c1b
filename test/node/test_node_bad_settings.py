"""The simulator node against bad settings: --help, a real_time_factor too small or not a number, robots
with bad ROS names, mistakes through spawn_model and the controller manager (the slow pace:
test_node_slow_pace.py)."""
import os
import subprocess
import time

import pytest
import yaml

from ros_harness import free_port


def test_help_prints_usage_without_a_master():
    env = dict(os.environ, ROS_MASTER_URI='http://127.0.0.1:%d' % free_port(), ROS_IP='127.0.0.1')
    result = subprocess.run(['rosrun', 'tianracer_description', 'bullet_plant', '--help'], env=env,
                            capture_output=True, text=True, timeout=10)
    assert result.returncode == 0, result.stderr
    assert 'usage: bullet_plant' in result.stdout
    assert 'real_time_factor' in result.stdout


@pytest.mark.ros
@pytest.mark.parametrize('value', ['1e-6', "'1e-6'", 'fast'])
def test_a_real_time_factor_too_small_or_not_a_number_is_refused(ros, value):
    # `_real_time_factor:=1e-6` arrives as a string (YAML 1.1 reads no float without a dot), as from roslaunch.
    plant = ros.start(['rosrun', 'tianracer_description', 'bullet_plant', '_real_time_factor:=' + value], 'plant')
    assert plant.wait(15) == 1, plant.log()
    assert '/gazebo/real_time_factor' in plant.log()


@pytest.mark.ros
@pytest.mark.parametrize('bad, what', [
    ('<topicName>my scan</topicName>', "sensor 'lidar' topic: 'my scan'"),
    ('<topicName>1scan</topicName>', "sensor 'lidar' topic: '1scan'"),
    ('<robotNamespace>/tian racer</robotNamespace>', "robotNamespace: '/tian racer'"),
    ('<robotNamespace>/tianracer</robotNamespace><eStopTopic>e stop</eStopTopic>', "eStopTopic: 'e stop'"),
])
def test_a_robot_with_a_bad_ros_name_is_refused_and_the_node_keeps_running(ros, urdf_xml, bad, what):
    import re
    tag = re.match(r'<(\w+)>', bad).group(1)
    original = '<topicName>scan</topicName>' if tag == 'topicName' else \
        re.search(r'<robotNamespace>[^<]*</robotNamespace>', urdf_xml).group(0)
    assert original in urdf_xml
    bad_urdf = urdf_xml.replace(original, bad, 1)
    plant = ros.start(['rosrun', 'tianracer_description', 'bullet_plant', '_real_time_factor:=0'], 'plant')
    ros.service('/gazebo/pause_physics', wait=True, timeout=30)

    def spawn(name, urdf):
        return ros.service('/gazebo/spawn_urdf_model', yaml.safe_dump(
            {'model_name': name, 'model_xml': urdf, 'robot_namespace': ''}), timeout=60)
    bad = spawn('bad', bad_urdf)
    assert bad['success'] is False and what in bad['status_message'], bad
    assert spawn('good', urdf_xml)['success'] is True, plant.log()
    ros.service('/gazebo/unpause_physics')
    time.sleep(1.0)
    assert plant.popen.poll() is None, plant.log()
    assert ros.run(['rostopic', 'echo', '-n', '1', '/tianracer/odom'], timeout=20).returncode == 0, plant.log()


@pytest.mark.ros
@pytest.mark.slow
def test_mistakes_through_spawn_model_and_the_controller_manager_get_answers_not_exceptions(ros, urdf_file):
    from ros_harness import tianracer_plant
    plant = tianracer_plant(ros, urdf_file, paused=True)

    def spawn_model(*args):
        return ros.run(['rosrun', 'gazebo_ros', 'spawn_model', '-urdf', '-param', 'robot_description']
                       + list(args), timeout=60)
    yaw = spawn_model('-model', 'spun', '-Y', 'inf')
    assert yaw.returncode == 1 and 'Traceback' not in yaw.stderr, yaw.stderr
    assert "option '-Y' needs a finite number, not inf" in yaw.stdout + yaw.stderr
    # The URDF's robotNamespace is /tianracer, where the first car's controller manager already is.
    twin = spawn_model('-model', 'twin', '-y', '2')
    assert twin.returncode == 1
    assert ("robot 'twin': robotNamespace '/tianracer' already holds the controller manager of robot 'tianracer'"
            in twin.stdout + twin.stderr), twin.stdout + twin.stderr
    for name in ('a b', '../../etc', '~x'):
        answer = ros.service('/tianracer/controller_manager/load_controller', "{name: '%s'}" % name)
        assert answer == {'ok': False}, answer
        ros.wait_until(lambda: "Exception thrown while constructing nodehandle for controller with name '%s'" % name
                       in plant.log(), 10, 'the load error in the log')
    assert ros.service('/tianracer/controller_manager/load_controller', '{name: joint_state_controller}') == {'ok': True}
    assert plant.popen.poll() is None, plant.log()
