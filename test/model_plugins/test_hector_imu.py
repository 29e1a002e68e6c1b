"""hector_gazebo_plugins' libhector_gazebo_ros_imu.so on the plant, through its Python module, on
the skid_bot, as Husky carries it."""
import math

import pytest

from plant_helpers import fixture_urdf, yaw_of
from tianracer_description import bullet_plant


NOISELESS_IMU = dict(accelDrift=None, accelGaussianNoise=None, rateDrift=None, rateGaussianNoise=None, yawDrift=None,
                     yawGaussianNoise=None)


def imu_bot(**params):
    world = bullet_plant.World()
    world.echo = False
    robot = world.spawn(fixture_urdf('skid_bot', 'imu', **params), 'skid_bot', namespace='/')
    world.step(500)
    return world, robot


def test_hector_imu_at_rest_feels_gravitys_reaction_and_turns_with_the_robot():
    world, robot = imu_bot(**NOISELESS_IMU)
    assert robot.plugin_topics('imu') == {'subscribes': [], 'publishes': ['imu/data', 'imu/data/bias'],
                                          'serves': ['imu/data/calibrate', 'imu/data/set_accel_bias', 'imu/data/set_rate_bias']}
    imu = robot.plugin_latest('imu', 'imu/data')
    assert imu['frame_id'] == 'base_link' and world.time - imu['stamp'] <= 0.021, 'updateRate 50'
    assert imu['linear_acceleration'] == pytest.approx([0, 0, 9.8], abs=1e-3)
    assert imu['angular_velocity'] == pytest.approx([0, 0, 0], abs=1e-4)
    assert imu['orientation'] == pytest.approx([0, 0, 0, 1], abs=1e-4)
    robot.plugin_send('skid_steer_drive', 'cmd_vel', (0.0, 1.0))
    world.step(2000)
    imu = robot.plugin_latest('imu', 'imu/data')
    assert imu['angular_velocity'][2] == pytest.approx(robot.base_twist()[1][2], rel=0.03), 'the turn over 20 ms'
    x, y, z, w = imu['orientation']
    assert math.atan2(2 * (w * z + x * y), 1 - 2 * (y * y + z * z)) == pytest.approx(yaw_of(robot.base_pose()), abs=0.02)
    # rpyOffset: the IMU mounted on its side reads gravity along its y axis.
    world, robot = imu_bot(rpyOffset='1.5707963 0 0', **NOISELESS_IMU)
    assert robot.plugin_latest('imu', 'imu/data')['linear_acceleration'] == pytest.approx([0, 9.8, 0], abs=1e-3)


def test_hector_imu_error_models_biases_and_covariances():
    world, robot = imu_bot(accelOffset='0.2 0 0', accelDrift=None, rateDrift=None, yawDrift=None)
    imu, bias = robot.plugin_latest('imu', 'imu/data'), robot.plugin_latest('imu', 'imu/data/bias')
    assert bias['linear_acceleration'] == pytest.approx([0.2, 0, 0]), 'the bias topic: offset plus drift'
    assert imu['linear_acceleration'][0] == pytest.approx(0.2, abs=0.03), 'offset plus white noise of 5 mm/s^2'
    # The accelerometer's bias tilts the pseudo-AHRS orientation: 0.2 / 9.8 / 2 about -y.
    assert bias['orientation'][1] == pytest.approx(-0.5 * 0.2 / 9.8, rel=0.01)
    assert imu['linear_acceleration_covariance'] == pytest.approx([0.005 ** 2] * 3)
    assert imu['angular_velocity_covariance'] == pytest.approx([0.005 ** 2] * 3)
    assert imu['orientation_covariance'] == pytest.approx([(0.005 / 9.8) ** 2, (0.005 / 9.8) ** 2, 0.005 ** 2])
    world, robot = imu_bot()
    first = robot.plugin_latest('imu', 'imu/data')
    assert abs(robot.plugin_latest('imu', 'imu/data/bias')['angular_velocity'][0]) > 0, 'a drift of 5 mrad/s drawn at load'
    assert imu_bot()[1].plugin_latest('imu', 'imu/data') == first, 'the same seed: the same readings'
    world, robot = imu_bot(gaussianNoise=0.1)
    assert robot.plugin_latest('imu', 'imu/data')['angular_velocity_covariance'] == pytest.approx([0.01] * 3), \
        'the legacy <gaussianNoise> sets both noises'


def test_hector_imu_services_set_the_biases_and_calibrate_draws_the_rate_drift_anew():
    world, robot = imu_bot(accelGaussianNoise=None, rateGaussianNoise=None, yawGaussianNoise=None, accelDrift=None)
    assert robot.plugin_call('imu', 'imu/data/set_accel_bias', (0.3, -0.1, 0.0))
    assert robot.plugin_call('imu', 'imu/data/set_rate_bias', (0.0, 0.0, 0.02))
    world.step(40)
    imu, bias = robot.plugin_latest('imu', 'imu/data'), robot.plugin_latest('imu', 'imu/data/bias')
    assert bias['linear_acceleration'] == pytest.approx([0.3, -0.1, 0.0], abs=1e-4) and imu['linear_acceleration'] == \
        pytest.approx([0.3, -0.1, 9.8], abs=1e-3), 'set_accel_bias: the drift now (fading at its drift frequency)'
    assert bias['angular_velocity'][2] == pytest.approx(0.02, abs=1e-3)
    assert robot.plugin_call('imu', 'imu/data/calibrate')
    world.step(40)
    calibrated = robot.plugin_latest('imu', 'imu/data/bias')['angular_velocity'][2]
    assert calibrated != pytest.approx(0.02, abs=1e-3) and abs(calibrated) < 0.03, 'a new drift drawn, N(0, 5 mrad/s)'
    world, robot = imu_bot(serviceName='')
    assert 'imu/data/calibrate' not in robot.plugin_topics('imu')['serves'], 'an empty serviceName: no calibrate'
