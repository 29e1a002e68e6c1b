"""hector_gazebo_plugins' libhector_gazebo_ros_gps.so on the plant, through its Python module, on
the skid_bot, as Husky carries it."""
import math

import pytest

from plant_helpers import fixture_urdf, logged
from tianracer_description import bullet_plant


WGS84_A, WGS84_F = 6378137.0, 1 / 298.257223563


def radii_of_curvature(latitude_deg):
    """The meridian and the prime-vertical-times-cos radii at a latitude (textbook WGS84 geodesy)."""
    e2 = WGS84_F * (2 - WGS84_F)
    s = math.sin(math.radians(latitude_deg))
    meridian = WGS84_A * (1 - e2) / (1 - e2 * s * s) ** 1.5
    prime_vertical = WGS84_A / math.sqrt(1 - e2 * s * s)
    return meridian, prime_vertical * math.cos(math.radians(latitude_deg))


def gps_bot(pose=(0, 0, 0, 0, 0, 0), **params):
    world = bullet_plant.World()
    world.echo = False
    robot = world.spawn(fixture_urdf('skid_bot', 'gps', **params), 'skid_bot', namespace='/', pose=pose)
    world.step(200)
    return world, robot


def test_gps_fix_is_the_position_on_the_tangent_plane_of_the_reference():
    world, robot = gps_bot(pose=(10, 5, 0, 0, 0, 0), drift=None)
    assert robot.plugin_topics('gps') == {'subscribes': [], 'publishes': ['navsat/fix', 'navsat/vel']}
    fix = robot.plugin_latest('gps', 'navsat/fix')
    north, east = radii_of_curvature(49.9)
    x, y, z = robot.link_pose('base_link')[:3]
    assert fix['latitude'] == pytest.approx(49.9 + math.degrees(x / north), abs=1e-10), 'x is north'
    assert fix['longitude'] == pytest.approx(8.9 - math.degrees(y / east), abs=1e-10), 'y is west (hector: y left of north)'
    assert fix['altitude'] == pytest.approx(z, abs=1e-6)
    assert (fix['frame_id'], fix['status'], fix['service']) == ('base_link', 0, 0), 'STATUS_FIX, service 0'
    assert fix['position_covariance'] == [0.0, 0.0, 0.0], 'no drift, no noise'
    # referenceHeading 90: the world's x axis points east.
    world, robot = gps_bot(pose=(10, 0, 0, 0, 0, 0), drift=None, referenceHeading=90, referenceLatitude=-33.9,
                           referenceLongitude=151.2, referenceAltitude=50)
    fix = robot.plugin_latest('gps', 'navsat/fix')
    north, east = radii_of_curvature(-33.9)
    assert fix['latitude'] == pytest.approx(-33.9, abs=1e-9)
    assert fix['longitude'] == pytest.approx(151.2 + math.degrees(10 / east), abs=1e-9)
    assert fix['altitude'] == pytest.approx(50.04, abs=1e-3)


def test_gps_velocity_north_west_up_at_the_update_rate():
    world, robot = gps_bot(drift=None)
    robot.plugin_send('skid_steer_drive', 'cmd_vel', (0.3, 0.0))
    world.step(1000)
    velocity = robot.plugin_latest('gps', 'navsat/vel')
    assert velocity['vector'] == pytest.approx([0.3, 0.0, 0.0], abs=0.005)
    stamps = []
    for _ in range(100):
        world.step(1)
        stamps.append(robot.plugin_latest('gps', 'navsat/fix')['stamp'])
    assert sorted(set(round(s, 6) for s in stamps)) == pytest.approx([1.2, 1.225, 1.25, 1.275]), \
        'updateRate 40, phase-locked to multiples of 25 ms'


def test_gps_error_model_drift_and_noise_deterministic():
    world, robot = gps_bot(drift='0.5 0.5 1.0', gaussianNoise=0.2)
    fix = robot.plugin_latest('gps', 'navsat/fix')
    assert fix['position_covariance'] == pytest.approx([0.25 + 0.04, 0.25 + 0.04, 1.0 + 0.04]), 'drift^2 + noise^2'
    north, _ = radii_of_curvature(49.9)
    latitudes = []
    for _ in range(40):
        world.step(25)
        latitudes.append(math.radians(robot.plugin_latest('gps', 'navsat/fix')['latitude'] - 49.9) * north)
    spread = max(latitudes) - min(latitudes)
    assert 0.2 < spread < 2.0, 'white noise of 0.2 m over a drift that moves by at most millimetres in a second'
    again = gps_bot(drift='0.5 0.5 1.0', gaussianNoise=0.2)
    assert again[1].plugin_latest('gps', 'navsat/fix') == fix, 'the same seed: the same fix'
    world, robot = gps_bot(bodyName='antenna')
    assert 'gps' not in robot.model_plugins
    assert any("plugin 'gps' (libhector_gazebo_ros_gps.so) <bodyName> names 'antenna', which is no link" in m
               for m in logged(world, 'ERROR'))
    world, robot = gps_bot(drift='1 2')
    assert any('<drift> of plugin' in m and 'expected 3 numbers' in m for m in logged(world, 'ERROR'))
