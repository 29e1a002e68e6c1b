"""hector's sonar (libhector_gazebo_ros_sonar.so) and gazebo_ros_block_laser through the node, on a
mast (test/fixtures/urdf/ranger_mast.urdf) before a wall. What their users rely on: the sonar's
Range is the nearest ray's distance through hector's error model, only when something is in range,
at hector's 10 Hz timer, with its defaults (topic `sonar`, frame `/sonar_link`); the block laser's
PointCloud has a point per ray at upstream's angles, holding the ray's range (max where it hits
nothing, as gazebo_ros_pkgs 2.9.2)."""
import math
import os

import pytest

from plant_helpers import FIXTURES, sdf_world
from ros_harness import spawn_urdf, start_plant
from test_velodyne_ros import wall

pytestmark = pytest.mark.ros

WALL_X = 2.95  # the wall's face, in the world (the mast stands at the origin)


def test_hector_sonar_and_block_laser(ros, tmp_path):
    (tmp_path / 'wall.world').write_text(sdf_world(wall()))
    plant = start_plant(ros, str(tmp_path / 'wall.world'))
    ros.set_param('/robot_description', textfile=os.path.join(FIXTURES, 'urdf', 'ranger_mast.urdf'))
    spawn_urdf(ros, plant, '/robot_description', 'ranger_mast')
    seen = ros.probe('sensor_plugins/probes/hector_sonar_and_block_laser.py', timeout=90)
    front, back, cloud = seen['front'], seen['back'], seen['cloud']

    for m in front:
        assert m['frame'] == 'sonar_front_link' and m['radiation'] == 0, 'ULTRASOUND, <frameId> as given'
        assert m['fov'] == pytest.approx(0.1, abs=1e-6), 'the smaller of the 0.4 rad and 0.1 rad spans'
        assert m['limits'] == pytest.approx([0.03, 3.0])
        # the centre ray, from 0.05 m ahead of the mast, plus the error model's <offset>
        assert m['range'] == pytest.approx(WALL_X - 0.05 + 0.04, abs=1e-4)
    stamps = [m['stamp_ns'] for m in front]
    assert all(s % 100_000_000 == 0 for s in stamps), 'hector\'s timer fires on multiples of its 0.1 s period'
    assert all(b - a == 100_000_000 for a, b in zip(stamps, stamps[1:])), '10 Hz, though the sensor runs at 20'
    for m in back:  # every default: nothing within 3 m behind the mast
        assert m['frame'] == '/sonar_link'
        assert m['range'] == pytest.approx(3.0), 'the maximum, no offset added when nothing is in range'

    assert cloud['frame'] == 'ranger'
    assert len(cloud['points']) == 27 and [len(c[1]) for c in cloud['channels']] == [27]
    assert cloud['channels'][0][1] == [0.0] * 27, 'intensity: the rays\' retro, 0'
    yaws = [-1.6 + 0.4 * i for i in range(9)]
    pitches = [-0.05, 0.0, 0.05]
    for k, (x, y, z) in enumerate(cloud['points']):
        row, column = divmod(k, 9)
        yaw, pitch = yaws[column], pitches[row]
        hits = abs(yaw) < math.atan2(4.0, WALL_X)
        r = WALL_X / (math.cos(yaw) * math.cos(pitch)) if hits else 10.0
        # placed at the mean angle of the ray and the next one (upstream's interpolation pair)
        placed_yaw = (yaw + yaws[min(column + 1, 8)]) / 2
        placed_pitch = (pitch + pitches[min(row + 1, 2)]) / 2
        expected = [r * math.cos(placed_pitch) * math.cos(placed_yaw), r * math.cos(placed_pitch) * math.sin(placed_yaw),
                    r * math.sin(placed_pitch)]
        assert [x, y, z] == pytest.approx(expected, abs=2e-3), (k, row, column)
