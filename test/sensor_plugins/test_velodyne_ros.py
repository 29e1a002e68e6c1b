"""velodyne_simulator's plugins through the node: a VLP-16 (gazebo_ros_velodyne_laser) and an
HDL-32E (the gpu variant, organize_cloud) on a mast (test/fixtures/urdf/velodyne_mast.urdf), in a
world of a ground plane and one wall. What point cloud users rely on: Velodyne's field layout (x y z
intensity ring time, 22 bytes), every ring at its elevation, every point on the wall or the ground
where the geometry puts it, nothing inside min_range, the organized cloud's shape and NaNs."""
import math
import os

import pytest

from plant_helpers import FIXTURES, sdf_world
from ros_harness import spawn_urdf, start_plant

pytestmark = pytest.mark.ros

WALL_X = 2.95  # the wall's face, in the world (the mast stands at the origin)
VLP16_Z, HDL32_Z = 0.6, 1.2


def wall(name='wall', size=(0.1, 8.0, 3.0), xyz=(3.0, 0.0, 1.5)):
    """A static box seen by both ray lidars (its collision) and gpu lidars (its visual)."""
    geometry = '<geometry><box><size>%g %g %g</size></box></geometry>' % size
    return f"""<model name="{name}"><static>true</static><pose>{xyz[0]} {xyz[1]} {xyz[2]} 0 0 0</pose>
  <link name="link"><collision name="collision">{geometry}</collision><visual name="visual">{geometry}</visual></link>
</model>"""


def test_vlp16_and_hdl32_point_clouds(ros, tmp_path):
    (tmp_path / 'wall.world').write_text(sdf_world(wall()))
    plant = start_plant(ros, str(tmp_path / 'wall.world'))
    ros.set_param('/robot_description', textfile=os.path.join(FIXTURES, 'urdf', 'velodyne_mast.urdf'))
    spawn_urdf(ros, plant, '/robot_description', 'velodyne_mast')
    seen = ros.probe('sensor_plugins/probes/vlp16_and_hdl32_point_clouds.py', timeout=90)
    vlp, hdl = seen['/velodyne_points'], seen['/hdl32/points']
    layout = [['x', 0, 7], ['y', 4, 7], ['z', 8, 7], ['intensity', 12, 7], ['ring', 16, 4], ['time', 18, 7]]
    assert vlp['fields'] == layout and hdl['fields'] == layout, 'x y z intensity float32, ring uint16, time float32'
    assert vlp['frame'] == 'velodyne' and hdl['frame'] == 'velodyne2'

    height, width, step, row_step, dense = vlp['shape']
    assert (height, step, dense) == (1, 22, True) and row_step == width * 22 == vlp['count'] * 22
    # azimuth by azimuth, every ring at each, as the driver orders them; behind the mast (the first
    # azimuths) only the 8 downward rings hit anything (the ground), the upward ones are dropped
    assert vlp['rings_in_order'][:24] == list(range(8)) * 3
    ring_pitch = [math.radians(-15 + 2 * k) for k in range(16)]
    on_wall = on_ground = 0
    for x, y, z, intensity, ring, time in vlp['points']:
        r = math.sqrt(x * x + y * y + z * z)
        assert r > 0.9, 'nothing inside min_range'
        assert math.atan2(z, math.hypot(x, y)) == pytest.approx(ring_pitch[ring], abs=1e-4), 'the ring is its elevation'
        assert intensity == 0.0 and time == 0.0
        if abs(z + VLP16_Z) < 0.03:
            on_ground += 1  # gaussianNoise 0.008 along the ray
        else:
            assert x == pytest.approx(WALL_X, abs=0.04) and abs(y) < 4.05, (x, y, z)
            on_wall += 1
    assert on_wall > 300 and on_ground > 300
    # The wall spans 2 atan(4 / 2.95) of the 1875 azimuths; the rings that miss it hit the ground or nothing.
    assert vlp['count'] < 16 * 1875

    height, width, step, row_step, dense = hdl['shape']
    assert (width, height, step, row_step, dense) == (32, 2187, 22, 32 * 22, False), 'organize_cloud: a ring per column'
    hdl_pitch = [-0.5353010844 + k * (0.1862291875 + 0.5353010844) / 31 for k in range(32)]
    nans = 0
    for x, y, z, intensity, ring, time in hdl['points']:
        if x is None:
            nans += 1
            continue
        assert math.atan2(z, math.hypot(x, y)) == pytest.approx(hdl_pitch[ring], abs=1e-4)
        assert abs(z + HDL32_Z) < 1e-3 or x == pytest.approx(WALL_X, abs=1e-3), 'no noise: exactly on the surfaces'
    assert nans > 0, 'rays that hit nothing are NaN in an organized cloud'
