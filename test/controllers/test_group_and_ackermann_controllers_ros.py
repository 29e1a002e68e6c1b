"""The controller types beyond the tutorial's through ROS (docs/interfaces.md section 12):
launch/ackermann_steering.launch driven by a Twist on /tianracer/cmd_vel with no converter script
(odometry on the controller's odom topic and /tf), and a JointGroup controller commanded by a
std_msgs/Float64MultiArray."""
import math

import pytest

from ros_harness import tianracer_plant

pytestmark = pytest.mark.ros

NS = '/tianracer'


def collect(ros, topics, seconds):
    """The messages of several topics over `seconds` of simulated time from when every one of them is
    connected, as dicts per topic."""
    return ros.probe('controllers/probes/collect_messages.py', seconds, *topics, timeout=120)


def wait_for_message_where(ros, topic, condition, timeout=60):
    """Waits (wall clock) for a message of `topic` for which `condition`, a Python expression of the
    message as a dict `m`, holds: a command from `rostopic pub` has reached the plant once it shows."""
    ros.probe('controllers/probes/wait_for_message_where.py', topic, condition, timeout, timeout=timeout + 30)


@pytest.mark.slow
def test_ackermann_launch_drives_the_car_from_a_twist(ros):
    ros.start(['roslaunch', 'tianracer_description', 'ackermann_steering.launch', 'gui:=false'], 'ackermann')
    ros.wait_for_controllers(3, NS, timeout=90)
    speed, steering = 1.0, 0.3
    ros.start(['rostopic', 'pub', '-r', '10', NS + '/cmd_vel', 'geometry_msgs/Twist',
               '{linear: {x: %g}, angular: {z: %g}}' % (speed, steering)], 'twist')
    wait_for_message_where(ros, NS + '/odom', "m['twist']['twist']['angular']['z'] > 0.5")
    collect(ros, [NS + '/odom'], 3.0)   # let it reach its circle
    got = collect(ros, [NS + '/odom', NS + '/ackermann_right_controller/odom', '/tf'], 1.0)

    truth = got[NS + '/odom'][-1]['twist']['twist']
    bicycle_yaw_rate = speed * math.tan(steering) / 0.261
    assert math.hypot(truth['linear']['x'], truth['linear']['y']) == pytest.approx(speed, rel=0.05)
    assert 0.80 <= truth['angular']['z'] / bicycle_yaw_rate <= 1.02   # test_group_and_ackermann_controllers.py says why

    odometry = got[NS + '/ackermann_right_controller/odom']
    assert 40 <= len(odometry) <= 60, 'publish_rate 50 in simulated time'
    last = odometry[-1]
    assert (last['header']['frame_id'], last['child_frame_id']) == ('odom', 'base_footprint')
    assert last['pose']['covariance'][0] == 0.001 and last['pose']['covariance'][35] == 1000.0
    assert last['twist']['twist']['angular']['z'] > 0.5

    # odom -> base_footprint on /tf is the controller's odometry only (the ground truth steps aside).
    poses = {round(o['header']['stamp'], 6): o['pose']['pose']['position'] for o in odometry}
    transforms = [t for m in got['/tf'] for t in m['transforms'] if t['child_frame_id'] == 'base_footprint']
    assert transforms, 'no odom -> base_footprint on /tf'
    for t in transforms:
        assert t['header']['frame_id'] == 'odom'
        pose = poses.get(round(t['header']['stamp'], 6))
        if pose is not None:
            assert (t['transform']['translation']['x'], t['transform']['translation']['y']) == (pose['x'], pose['y'])
    assert sum(round(t['header']['stamp'], 6) in poses for t in transforms) >= 0.8 * len(transforms)


@pytest.mark.slow
def test_joint_group_velocity_controller_takes_a_float64_multi_array(ros, urdf_file):
    tianracer_plant(ros, urdf_file)
    ros.set_param(NS + '/rear_wheels', {'type': 'velocity_controllers/JointGroupVelocityController',
                                        'joints': ['left_rear_wheel_joint', 'right_rear_wheel_joint']})
    ros.start(['rosrun', 'controller_manager', 'spawner', '__ns:=' + NS, 'joint_state_controller', 'rear_wheels'],
              'spawner')
    ros.wait_for_controllers(2, NS)
    ros.start(['rostopic', 'pub', '-r', '10', NS + '/rear_wheels/command', 'std_msgs/Float64MultiArray',
               '{data: [10.0, 20.0]}'], 'command')
    wait_for_message_where(ros, NS + '/joint_states', "m['velocity'][m['name'].index('right_rear_wheel_joint')] > 10.0")
    collect(ros, [NS + '/joint_states'], 1.0)
    state = collect(ros, [NS + '/joint_states'], 0.2)[NS + '/joint_states'][-1]
    velocity = dict(zip(state['name'], state['velocity']))
    assert velocity['left_rear_wheel_joint'] == pytest.approx(10.0, abs=0.5)
    assert velocity['right_rear_wheel_joint'] == pytest.approx(20.0, abs=0.5)
