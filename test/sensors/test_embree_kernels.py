"""The sensors on every instruction set of Embree's kernels this CPU runs (TIANRACER_EMBREE_ISA):
the car's camera, depth camera and lidar on a race track of meshes (test/fixtures/gazebo_pkg: a
Collada floor, STL walls) see the same thing on each. Embree runs 4-wide SSE, 8-wide AVX and
16-wide AVX-512 kernels whose float arithmetic differs in order: measured on an AMD EPYC (Zen 4),
the colour images are bit-identical and distances differ by at most 1.9e-6 m (two float steps at
8 m); the test allows 1e-5 m."""

import numpy as np

from plant_helpers import ISA_VARIABLE, ISAS_RUN, TRACK_WORLD, embree_isas, find_fixture_packages
from tianracer_description import bullet_plant
from tianracer_description.tianracer import CONFIG_YAML

DISTANCE_TOLERANCE = 1e-5  # m


def sensor_readings(urdf_xml):
    """What the car's sensors see, 0.3 s after it is set down on the track, turned towards a wall."""
    world = bullet_plant.World.from_file(TRACK_WORLD)
    world.echo = False
    world.load_params(CONFIG_YAML)
    car = world.spawn(urdf_xml, 'tianracer', pose=(1.0, 0.1, 0.55, 0, 0, 0.2))
    for sensor in car.sensors:
        car.enable_sensor(sensor, True)
    world.step(300)
    depth = car.image('depth_camera')
    return {'camera': car.image('camera')['rgb'].copy(), 'depth_rgb': depth['rgb'].copy(),
            'depth': np.asarray(depth['depth']).copy(), 'lidar': np.asarray(car.scan('lidar')['ranges']).copy(),
            'log': [text for _, text in world.messages()]}


def test_every_kernel_sees_the_same_frames_and_scans(urdf_xml, monkeypatch):
    find_fixture_packages(monkeypatch)
    isas = embree_isas()
    readings = {}
    for isa in isas:
        monkeypatch.setenv(ISA_VARIABLE, isa)
        readings[isa] = sensor_readings(urdf_xml)
        ISAS_RUN.add(isa)
        assert "sensors: rays cast with Embree's %s kernels (TIANRACER_EMBREE_ISA)" % isa in readings[isa]['log']
    widest = readings[isas[-1]]
    assert np.isfinite(widest['lidar']).sum() > 500, 'the lidar sees the walls'
    assert np.isfinite(widest['depth']).mean() > 0.5, 'the depth camera sees the floor and a wall'
    for isa in isas[:-1]:
        got = readings[isa]
        for image in ('camera', 'depth_rgb'):
            differ = np.any(got[image] != widest[image], axis=2)
            assert not differ.any(), '%s: %d pixels of the %s differ from %s' % (isa, differ.sum(), image, isas[-1])
        for distances in ('lidar', 'depth'):
            a, b = got[distances], widest[distances]
            np.testing.assert_array_equal(np.isfinite(a), np.isfinite(b),
                                          err_msg='%s: %s sees something where %s does not' % (isa, distances, isas[-1]))
            seen = np.isfinite(a)
            assert np.abs(a[seen] - b[seen]).max() <= DISTANCE_TOLERANCE, (isa, distances)


def test_a_variable_the_plant_cannot_follow_is_named_and_the_widest_kernels_cast(urdf_xml, monkeypatch):
    find_fixture_packages(monkeypatch)
    monkeypatch.setenv(ISA_VARIABLE, 'avx1024')
    assert bullet_plant.embree_isa() == {
        'name': embree_isas()[-1], 'forced': False,
        'problem': "TIANRACER_EMBREE_ISA='avx1024' is not one of sse2, sse4.2, avx, avx2, avx512: ray casting uses "
                   "%s, the widest this CPU runs" % embree_isas()[-1]}
    readings = sensor_readings(urdf_xml)
    assert [line for line in readings['log'] if 'avx1024' in line] == [
        "sensors: TIANRACER_EMBREE_ISA='avx1024' is not one of sse2, sse4.2, avx, avx2, avx512: ray casting uses "
        "%s, the widest this CPU runs" % embree_isas()[-1]]
    assert np.isfinite(readings['lidar']).sum() > 500
