"""gazebo_ros_openni_kinect and Noetic's gazebo_ros_depth_camera through the node, side by side on a
mast (test/fixtures/urdf/depth_mast.urdf) 2.95 m before a wall, both given pointCloudCutoffMax 2.0:
the Kinect drops the wall (beyond its far cutoff) and keeps an organized cloud; the depth camera,
which reads no far cutoff, sees the wall, in one row of points as Noetic's publishes it. Neither
names its image topics: both publish them where upstream's do, image_raw and camera_info (their
infrared defaults, ir/image_raw and ir/camera_info, are overwritten by GazeboRosCameraUtils::Load).
The depth camera's CameraInfos (its depth's and its image's), which Noetic's never publishes
(gazebo_ros_pkgs #1174), the plant's own does, on purpose (image_pipeline needs them): a test of
its own."""
import math
import os

import pytest

from plant_helpers import FIXTURES, sdf_world
from ros_harness import spawn_urdf, start_plant
from test_velodyne_ros import wall

pytestmark = pytest.mark.ros

WALL_X = 2.95


def test_kinect_and_depth_camera_before_a_wall(ros, tmp_path):
    (tmp_path / 'wall.world').write_text(sdf_world(wall()))
    plant = start_plant(ros, str(tmp_path / 'wall.world'))
    ros.set_param('/robot_description', textfile=os.path.join(FIXTURES, 'urdf', 'depth_mast.urdf'))
    spawn_urdf(ros, plant, '/robot_description', 'depth_mast')
    seen = ros.probe('sensor_plugins/probes/kinect_and_depth_camera_before_a_wall.py', timeout=90)
    kinect, depth_camera = seen['kinect'], seen['depth_camera']
    assert kinect['shape'][:2] == [24, 32], 'openni_kinect: organized, as the image'
    assert depth_camera['shape'][:2] == [1, 32 * 24], 'the depth camera: one row of every pixel'
    assert kinect['frame'] == 'kinect_optical' and depth_camera['frame'] == 'depth_optical'
    assert kinect['info'] == [24, 32]
    for camera in (kinect, depth_camera):
        assert camera['image'] == [24, 32, '32FC1']
        assert camera['ir'][:3] == [24, 32, 'rgb8']
    # dense until a point is NaN, as upstream's fill their clouds: the Kinect's beyond its 2 m are
    assert kinect['shape'][2] is False, 'NaN points beyond the cutoff: not dense'
    assert depth_camera['shape'][2] is True, 'every pixel sees the wall or the ground: dense'
    assert kinect['ir'][3] == 32
    # The middle rows look at the wall, square on: depth (z in the optical frame) 2.95 m.
    centre = 12 * 32 + 16
    assert depth_camera['depths'][centre] == pytest.approx(WALL_X, abs=1e-3)
    assert depth_camera['points'][centre][2] == pytest.approx(WALL_X, abs=1e-3)
    assert kinect['depths'][centre] is None and kinect['points'][centre] is None, 'beyond the Kinect\'s 2 m'
    wall_pixels = [k for k, d in enumerate(depth_camera['depths']) if d is not None and abs(d - WALL_X) < 1e-3]
    assert len(wall_pixels) > 32 * 8
    assert all(kinect['depths'][k] is None for k in wall_pixels)
    # the ground, nearer than 2 m, both see (the lowest rows)
    near = [k for k, d in enumerate(kinect['depths']) if d is not None]
    assert near and all(0.5 < kinect['depths'][k] < 2.0 for k in near)
    assert all(depth_camera['depths'][k] == pytest.approx(kinect['depths'][k], abs=1e-5) for k in near)


def test_the_plants_depth_camera_publishes_its_camera_infos(ros, tmp_path):
    (tmp_path / 'wall.world').write_text(sdf_world(wall()))
    plant = start_plant(ros, str(tmp_path / 'wall.world'))
    ros.set_param('/robot_description', textfile=os.path.join(FIXTURES, 'urdf', 'depth_mast.urdf'))
    spawn_urdf(ros, plant, '/robot_description', 'depth_mast')
    for topic in ('/depth_camera/depth/camera_info', '/depth_camera/camera_info'):
        info = ros.probe('sensor_plugins/probes/first_message.py', topic, timeout=60)
        assert info == {'frame': 'depth_optical', 'type': 'sensor_msgs/CameraInfo'}, topic
