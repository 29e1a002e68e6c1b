"""The gazebo_ros sensor plugins by their own parameters (docs/interfaces.md section 11), through the
plant's Python API: namespaces, topics and frame ids as each plugin makes them, the IMU at rest and
on a circle, gazebo_ros_p3d, and unknown plugins."""
import math

import numpy as np
import pytest

from plant_helpers import PLUGIN_URDF, logged, make_world
from tianracer_description.tianracer import MODEL_XACRO, TUTORIAL_CONTROLLERS, run_xacro

IMU_RATE = 100.0  # Hz, urdf/sensors.xacro


def car_urdf(*args):
    result = run_xacro(MODEL_XACRO, *args)
    assert result.returncode == 0, result.stderr
    return result.stdout


def test_the_cars_sensors_publish_in_the_spawn_namespace_with_their_frames_as_given(control_config):
    world = make_world(control_config)
    car = world.spawn(car_urdf('prefix:=tianracer_01/', 'robot_namespace:=/tianracer_01/tianracer', 'imu:=true'),
                      'tianracer_01', namespace='/tianracer_01')
    assert car.sensor_namespace('lidar') == '/tianracer_01'
    # no tf_prefix parameter (none in Python): frameName as given, as gazebo_ros_pkgs 2.9.2's laser and
    # camera resolve it (before 2.9.2 they fell back to the namespace)
    assert car.sensor_frame('lidar') == 'laser_link'
    assert car.sensor_frame('camera') == 'camera_optical_frame'
    assert car.sensor_topic('camera') == 'camera/image_raw'                # under cameraName
    assert car.sensor_frame('imu') == 'tianracer_01/imu_link'              # frameName as given
    assert car.sensor_topic('imu') == 'imu'
    tutorial = make_world(control_config).spawn(car_urdf(), 'tianracer', namespace='/')
    assert tutorial.sensor_frame('lidar') == 'laser_link', "namespace '/': no prefix"


def test_plugin_parameters_are_honoured(control_config):
    world = make_world(control_config)
    robot = world.spawn(PLUGIN_URDF, 'probe', namespace='/robot_a')
    assert robot.sensor_topic('front_laser') == '/shared/laser'
    assert robot.sensor_frame('front_laser') == 'scanner', "an absolute frameName loses its '/' only"
    assert robot.sensor_namespace('eye') == '/other', "the plugin's robotNamespace wins over the spawn's"
    assert robot.sensor_topic('eye') == 'front/rgb'
    assert robot.sensor_frame('eye') == 'eye_frame'  # no tf_prefix parameter in Python: as given
    assert robot.sensor_namespace('truth') == '/robot_a' and robot.sensor_topic('truth') == 'ground_truth'
    assert robot.sensor_frame('truth') == 'world'
    assert robot.sensor_topic('body_imu') == 'imu_raw' and robot.sensor_frame('body_imu') == 'scanner'
    # rates: the camera plugin's updateRate throttles the 30 Hz sensor to 5 Hz; p3d at 50 Hz
    for name in ('eye', 'truth', 'body_imu'):
        robot.enable_sensor(name)
    world.step(1000)
    assert robot.sensor_updates('eye') == pytest.approx(5, abs=1)
    assert robot.sensor_updates('truth') == pytest.approx(50, abs=1)
    assert robot.sensor_updates('body_imu') == pytest.approx(200, abs=1)
    truth = robot.ground_truth('truth')
    assert truth['child_frame_id'] == 'base_footprint' and truth['frame_id'] == 'world'


def test_an_unknown_plugin_is_warned_about_once_naming_it(control_config):
    world = make_world(control_config)
    world.spawn(PLUGIN_URDF, 'probe')
    world.step(2000)
    warnings = [text for level, text in world.messages() if 'libacme_sonar_plugin.so' in text]
    assert len(warnings) == 1 and "'sonar_plugin'" in warnings[0] and "'sonar'" in warnings[0]


def test_robot_sim_type_other_than_the_default_is_an_error_and_no_controller_manager(control_config, urdf_xml):
    world = make_world(control_config)
    urdf = urdf_xml.replace('gazebo_ros_control/DefaultRobotHWSim', 'my_robot_hw/MyRobotHWSim')
    robot = world.spawn(urdf, 'tianracer')
    errors = logged(world, 'ERROR')
    assert any("robotSimType 'my_robot_hw/MyRobotHWSim'" in e for e in errors), errors
    with pytest.raises(ValueError):
        robot.controller_manager


@pytest.fixture
def car_with_imu(control_config):
    world = make_world(control_config)
    car = world.spawn(car_urdf('imu:=true'), 'tianracer', pose=(0, 0, 0, 0, 0, 0.4))
    car.enable_sensor('imu')
    return world, car


def test_imu_at_rest_reads_gravity_up_and_zero_rates(car_with_imu):
    world, car = car_with_imu
    world.step(1000)
    imu = car.imu('imu')
    assert imu['linear_acceleration'][2] == pytest.approx(9.8, abs=0.01)
    assert np.abs(imu['linear_acceleration'][:2]).max() < 0.01
    assert np.abs(imu['angular_velocity']).max() < 1e-3
    qx, qy, qz, qw = imu['orientation']
    assert 2 * math.atan2(qz, qw) == pytest.approx(0.4, abs=1e-3), 'in the world frame (REP 145), as gazebo_ros_pkgs 2.9'


def test_imu_yaw_rate_on_a_circle_equals_odometrys(car_with_imu):
    world, car = car_with_imu
    manager = car.controller_manager
    manager.spawn(list(TUTORIAL_CONTROLLERS))
    world.step(2)
    for c in ('rear_left_velocity_controller', 'rear_right_velocity_controller'):
        manager.command(c, 25.0)
    for c in ('front_left_steering_position_controller', 'front_right_steering_position_controller'):
        manager.command(c, 0.35)
    world.step(3000)  # onto the circle
    imu_rates, odom_rates = [], []
    for _ in range(200):  # 2 s, one IMU sample each 10 ms
        world.step(10)
        imu_rates.append(car.imu('imu')['angular_velocity'][2])
        odom_rates.append(car.base_twist()[1][2])  # the ground truth odom publishes
    assert np.mean(odom_rates) > 0.5
    assert np.mean(imu_rates) == pytest.approx(np.mean(odom_rates), rel=0.02)
