"""launch/two_cars.launch as a user runs it: two prefixed cars, each with its own controllers,
sensors and TF tree, whose scans, images and IMU readings tf2 places in the odom frame."""
import math

import pytest

from ros_harness import frames_in
from tianracer_description.tianracer import TUTORIAL_CONTROLLERS

pytestmark = pytest.mark.ros

CARS = {'car1': 0.5, 'car2': -0.5}  # spawn y of each car in two_cars.launch
LASER_X = 0.20  # laser_link ahead of base_link (urdf/tianracer_description.xacro)


@pytest.fixture
def two_cars(ros):
    launch = ros.start(['roslaunch', 'tianracer_description', 'two_cars.launch', 'gui:=false'], 'two_cars')
    for car in CARS:
        ros.wait_for_controllers(len(TUTORIAL_CONTROLLERS), namespace='/%s/tianracer' % car, timeout=120)
    return launch


def test_scans_images_and_imu_of_both_cars_transform_into_odom(ros, two_cars):
    topics = []
    for car in CARS:
        topics += ['/%s/scan' % car, '/%s/camera/image_raw' % car, '/%s/depth_camera/depth/points' % car,
                   '/%s/imu' % car]
    frames = frames_in(ros, 'odom', topics)
    for car, y in CARS.items():
        assert frames['/%s/scan' % car]['frame'] == car + '/laser_link'
        assert frames['/%s/camera/image_raw' % car]['frame'] == car + '/camera_optical_frame'
        assert frames['/%s/depth_camera/depth/points' % car]['frame'] == car + '/depth_camera_optical_frame'
        assert frames['/%s/imu' % car]['frame'] == car + '/imu_link'
        x, ly, _ = frames['/%s/scan' % car]['xyz']
        assert x == pytest.approx(LASER_X, abs=0.01) and ly == pytest.approx(y, abs=0.01), car


@pytest.mark.slow
def test_each_car_has_its_own_controllers(ros, two_cars):
    """cmd_vel of car1 moves car1 only, then AckermannDriveStamped of car2 moves car2 only (each through
    its own converter and controllers)."""
    moved = ros.probe('tutorial/probes/each_car_has_its_own_controllers.py', timeout=120)
    twist_phase, ackermann_phase = moved
    assert twist_phase['car1'] > 0.5
    assert abs(twist_phase['car2']) < 0.01
    assert ackermann_phase['car2'] > 0.5
    assert abs(ackermann_phase['car1']) < 0.05, 'car1 only coasts to a stop'


def test_imu_at_rest_reads_gravity_up_and_no_rotation(ros, two_cars):
    reading = ros.probe('tutorial/probes/imu_at_rest_reads_gravity_up_and_no_rotation.py', timeout=60)
    assert reading['frame'] == 'car2/imu_link'
    assert reading['a'][2] == pytest.approx(9.8, abs=0.05)
    assert math.hypot(reading['a'][0], reading['a'][1]) < 0.05
    assert max(abs(v) for v in reading['w']) < 0.01
