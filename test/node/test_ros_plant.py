"""The plant as a ROS node, each test with its own ROS master: the tutorial's spawner line, the
controller manager services through rosservice, controller topics, the simulator services, the lidar,
spawn_model. What a user of Gazebo + gazebo_ros_control would type, against the real tools."""
import math
import time

import pytest

from ros_harness import tianracer_plant
from tianracer_description.tianracer import TUTORIAL_CONTROLLERS

pytestmark = pytest.mark.ros

NS = '/tianracer'
CM = NS + '/controller_manager/'


@pytest.fixture
def plant(ros, urdf_file):
    return tianracer_plant(ros, urdf_file)


def spawner(ros, *names):
    """The tutorial's control.launch spawner line: ns /tianracer, the controllers as arguments."""
    return ros.start(['rosrun', 'controller_manager', 'spawner', '__ns:=' + NS] + list(names), 'spawner')


def controller_states(ros):
    return {c['name']: c for c in ros.service(CM + 'list_controllers')['controller']}


def wait_for_running(ros, names, timeout=20):
    ros.wait_until(lambda: all(controller_states(ros).get(n, {}).get('state') == 'running' for n in names),
                   timeout, 'controllers %s running' % ', '.join(names))


def echo(ros, topic, count=1, timeout=15):
    """`count` messages of a topic as dicts (a rospy probe: no YAML guessing of nan/inf)."""
    return ros.probe('node/probes/echo.py', topic, count, timeout, timeout=timeout + 10)


@pytest.mark.slow
def test_tutorial_spawner_starts_the_five_controllers(ros, plant):
    start = time.monotonic()
    spawn = spawner(ros, *TUTORIAL_CONTROLLERS)
    # Polled every 20 ms in one process: a `rosservice call` per poll would add its own start-up,
    # a second or two each on a loaded 2-core machine, to what is timed.
    ros.wait_for_controllers(len(TUTORIAL_CONTROLLERS), namespace=NS)
    started_in = time.monotonic() - start
    wait_for_running(ros, TUTORIAL_CONTROLLERS)
    states = controller_states(ros)
    assert list(states) == list(TUTORIAL_CONTROLLERS)
    assert states['rear_left_velocity_controller']['claimed_resources'] == [
        {'hardware_interface': 'hardware_interface::VelocityJointInterface', 'resources': ['left_rear_wheel_joint']}]
    assert states['front_left_steering_position_controller']['claimed_resources'][0]['resources'] == [
        'left_steering_hinge_joint']
    for service, srv_type in [('load_controller', 'LoadController'), ('unload_controller', 'UnloadController'),
                              ('switch_controller', 'SwitchController'), ('list_controllers', 'ListControllers'),
                              ('list_controller_types', 'ListControllerTypes'),
                              ('reload_controller_libraries', 'ReloadControllerLibraries')]:
        result = ros.run(['rosservice', 'type', CM + service])
        assert result.stdout.strip() == 'controller_manager_msgs/' + srv_type
    assert started_in < 15
    assert spawn.popen.poll() is None, 'the spawner keeps running until it is stopped'


@pytest.mark.slow
def test_command_topic_turns_the_wheel_and_state_topics_publish(ros, plant):
    spawner(ros, *TUTORIAL_CONTROLLERS)
    wait_for_running(ros, TUTORIAL_CONTROLLERS)
    ros.run(['rostopic', 'pub', '-1', NS + '/rear_left_velocity_controller/command', 'std_msgs/Float64', 'data: 8.0'])

    def left_wheel_velocity():
        state = echo(ros, NS + '/joint_states')[0]
        return dict(zip(state['name'], state['velocity']))['left_rear_wheel_joint']
    ros.wait_until(lambda: abs(left_wheel_velocity() - 8.0) < 0.2, 10, 'the left rear wheel at 8 rad/s')
    state = echo(ros, NS + '/front_left_steering_position_controller/state')[0]
    assert (state['p'], state['i'], state['d']) == (4.0, 2.0, 1.0)
    assert echo(ros, NS + '/front_right_steering_position_controller/state')


@pytest.mark.slow
def test_controller_manager_errors_through_rosservice(ros, plant):
    ros.set_param(NS + '/wrong_joint', {'type': 'velocity_controllers/JointVelocityController', 'joint': 'nope'})
    assert ros.service(CM + 'load_controller', "name: 'not_configured'") == {'ok': False}
    assert ros.service(CM + 'load_controller', "name: 'wrong_joint'") == {'ok': False}
    assert ros.service(CM + 'load_controller', "name: 'joint_state_controller'") == {'ok': True}
    assert ros.service(CM + 'load_controller', "name: 'joint_state_controller'") == {'ok': False}
    strict = "{start_controllers: [ghost], stop_controllers: [], strictness: 2, start_asap: false, timeout: 0.0}"
    assert ros.service(CM + 'switch_controller', strict) == {'ok': False}
    assert ros.service(CM + 'unload_controller', "name: 'ghost'") == {'ok': False}
    ros.wait_until(lambda: "Could not find resource 'nope'" in plant.log(), 5, 'the error in the log')
    log = plant.log()
    for text in ["Could not load controller 'not_configured' because the type was not specified",
                 "Initializing controller 'wrong_joint' failed",
                 "A controller named 'joint_state_controller' was already loaded",
                 "Could not start controller with name 'ghost' because no controller with this name exists",
                 "Could not unload controller with name 'ghost' because no controller with this name exists"]:
        assert text in log
    assert plant.popen.poll() is None
    # A switch while paused returns at once (the real manager would wait for a control loop that is stopped).
    ros.service('/gazebo/pause_physics')
    start = time.monotonic()
    switch = "{start_controllers: [joint_state_controller], stop_controllers: [], strictness: 2, start_asap: false, timeout: 0.0}"
    assert ros.service(CM + 'switch_controller', switch, timeout=10) == {'ok': True}
    assert time.monotonic() - start < 5
    assert controller_states(ros)['joint_state_controller']['state'] == 'running'


@pytest.mark.slow
def test_sigint_to_the_spawner_stops_and_unloads_its_controllers(ros, plant):
    # What roslaunch's Ctrl-C needs: the spawner exits (upstream's could hang) and leaves nothing
    # loaded. How quickly is not timed here (a test times nothing): on a slow machine one rosservice
    # poll alone takes a second.
    spawn = spawner(ros, *TUTORIAL_CONTROLLERS)
    wait_for_running(ros, TUTORIAL_CONTROLLERS)
    spawn.interrupt()
    assert spawn.wait(5) is not None, 'the spawner exits'
    ros.wait_until(lambda: controller_states(ros) == {}, 10, 'the controllers unloaded')


@pytest.mark.slow
def test_non_finite_commands_leave_the_state_finite(ros, plant):
    spawner(ros, *TUTORIAL_CONTROLLERS)
    wait_for_running(ros, TUTORIAL_CONTROLLERS)
    # one rospy program for the six messages (`rostopic pub -1` takes seconds a message)
    topics = [NS + '/rear_left_velocity_controller/command', NS + '/front_left_steering_position_controller/command']
    assert ros.python(f'''
import json, time, rospy
from std_msgs.msg import Float64
rospy.init_node('non_finite_commands', anonymous=True)
publishers = [rospy.Publisher(topic, Float64, queue_size=10) for topic in {topics!r}]
deadline = time.time() + 20
while any(p.get_num_connections() == 0 for p in publishers) and time.time() < deadline:
    time.sleep(0.05)
for value in (float('nan'), float('inf'), float('-inf')):
    for p in publishers:
        p.publish(Float64(value))
        time.sleep(0.05)
time.sleep(0.5)
print(json.dumps(all(p.get_num_connections() > 0 for p in publishers)))
''', timeout=60)
    state = echo(ros, NS + '/joint_states')[0]
    odom = echo(ros, NS + '/odom')[0]
    numbers = state['position'] + state['velocity'] + state['effort'] + list(odom['pose']['pose']['position'].values())
    assert all(isinstance(v, float) and math.isfinite(v) for v in numbers)
    assert 'Rejected a non-finite command' in plant.log()


def test_pause_unpause_and_reset_like_gazebo(ros, plant):
    assert ros.get_param('/use_sim_time') is True
    clock = ros.probe('node/probes/pause_unpause_and_reset_like_gazebo.py')
    assert clock['during_pause'] == 0, 'no /clock while paused'
    assert clock['paused_at'] < clock['resumed'] < clock['paused_at'] + 0.05, 'time goes on from where it stopped'
    assert clock['after_reset'] < 0.5, 'reset_simulation restarts time from 0'


def test_scan_publishes_at_40_hz_of_simulated_time_in_the_lasers_frame(ros, plant):
    scans = echo(ros, '/scan', count=20, timeout=20)
    assert len(scans) == 20
    stamps = [s['header']['stamp'] for s in scans]
    periods = [b - a for a, b in zip(stamps, stamps[1:])]
    assert all(p == pytest.approx(0.025, abs=1e-6) for p in periods)
    assert {s['header']['frame_id'] for s in scans} == {'laser_link'}
    assert len(scans[0]['ranges']) == 1081


def test_spawn_model_with_a_malformed_urdf_exits_1_with_the_parsers_message(ros, plant, tmp_path):
    broken = tmp_path / 'broken.urdf'
    broken.write_text('<robot name="broken"><link name="a"><joint></robot>')
    result = ros.run(['rosrun', 'gazebo_ros', 'spawn_model', '-urdf', '-file', str(broken), '-model', 'broken'])
    assert result.returncode == 1
    assert 'not well-formed' in result.stdout + result.stderr
    assert plant.popen.poll() is None
    assert ros.service(CM + 'load_controller', "name: 'joint_state_controller'") == {'ok': True}


@pytest.mark.slow
def test_cameras_publish_at_their_rates_only_while_subscribed(ros, plant):
    rates = ros.probe('node/probes/cameras_publish_at_their_rates_only_while_subscribed.py', timeout=60)
    camera, info = rates['/camera/image_raw'], rates['/camera/camera_info']
    assert camera['rate'] == pytest.approx(30, rel=0.05) and camera['encoding'] == 'rgb8'
    assert info['size'] == camera['size'] == [160, 120]
    assert camera['frame'] == 'camera_optical_frame'
    depth = rates['/depth_camera/depth/image_raw']
    assert depth['rate'] == pytest.approx(15, rel=0.05) and depth['encoding'] == '32FC1'
    assert rates['/depth_camera/depth/camera_info']['size'] == depth['size'] == [128, 96]
    assert rates['/depth_camera/depth/points']['size'] == [128, 96]
    log = plant.log()
    for sensor in ('camera', 'depth_camera'):
        assert "tianracer sensor '%s': subscribed, computing" % sensor in log
    ros.wait_until(lambda: "tianracer sensor 'camera': no subscribers, idle" in plant.log(), 5, 'the camera idle')
