"""The world for rviz (tianracer_description.scene_markers, scripts/scene_markers): the race track's walls,
cones and floor as markers where the world file puts them, the mesh track's meshes by file, planes of
any normal with their top face on the plane; and the node's latched MarkerArray from the plant's
/gazebo/scene, which rviz.launch starts beside rviz."""
import glob
import json
import math
import os
import struct
import subprocess
import time
import xml.etree.ElementTree as ET

import numpy as np
import pytest

from plant_helpers import TRACK_WORLD, find_fixture_packages
from tianracer_description import bullet_plant
from tianracer_description.scene_markers import PLANE_THICKNESS, rotate, scene_markers, z_to
from tianracer_description.tianracer import PACKAGE, RACE_TRACK_WORLD


def scene_of(world_file):
    world = bullet_plant.World.from_file(world_file)
    world.echo = False
    return json.loads(world.scene_json())


def markers_of(world_file, frame='odom'):
    import rospy
    from visualization_msgs.msg import Marker
    markers = scene_markers(scene_of(world_file), frame, rospy.Time(0)).markers
    assert markers[0].action == Marker.DELETEALL, 'an earlier scene cleared first'
    for m in markers[1:]:  # nothing rviz's marker checks warn of (rviz 1.14's marker_utils)
        q = m.pose.orientation
        assert not m.text and math.isclose(q.x ** 2 + q.y ** 2 + q.z ** 2 + q.w ** 2, 1.0), m
        assert min(m.scale.x, m.scale.y, m.scale.z) > 0, m
    assert len({m.id for m in markers}) == len(markers), 'ids unique'
    assert all(m.header.frame_id == frame for m in markers)
    return markers[1:]


def test_the_race_tracks_walls_cones_and_floor_are_markers_where_the_world_puts_them():
    from visualization_msgs.msg import Marker
    markers = markers_of(RACE_TRACK_WORLD)
    by_model = {m.ns: m for m in markers}
    models = ET.parse(RACE_TRACK_WORLD).getroot().iter('model')
    for model in models:
        box, cylinder = model.find('link/visual/geometry/box'), model.find('link/visual/geometry/cylinder')
        if box is None and cylinder is None:
            continue
        m = by_model[model.get('name')]
        x, y, z, _, _, yaw = map(float, model.findtext('pose').split())
        assert [m.pose.position.x, m.pose.position.y, m.pose.position.z] == pytest.approx([x, y, z], abs=1e-6)
        assert 2 * math.atan2(m.pose.orientation.z, m.pose.orientation.w) == pytest.approx(yaw, abs=1e-6)
        if box is not None:
            assert m.type == Marker.CUBE
            assert [m.scale.x, m.scale.y, m.scale.z] == pytest.approx(list(map(float, box.findtext('size').split())))
            colour = list(map(float, model.findtext('link/visual/material/diffuse').split()))
            assert [m.color.r, m.color.g, m.color.b, m.color.a] == pytest.approx(colour, abs=1e-6)
        else:
            radius, length = float(cylinder.findtext('radius')), float(cylinder.findtext('length'))
            assert m.type == Marker.CYLINDER
            assert [m.scale.x, m.scale.y, m.scale.z] == pytest.approx([2 * radius, 2 * radius, length])
    floor = by_model['ground_plane']
    assert floor.type == Marker.CUBE and floor.scale.z == PLANE_THICKNESS
    assert floor.pose.position.z + floor.scale.z / 2 == pytest.approx(0.0, abs=1e-9), 'its top face on the plane'
    assert floor.scale.x >= 100 and floor.color.a == 1.0


def test_the_mesh_tracks_meshes_are_mesh_resources_by_file(monkeypatch):
    from visualization_msgs.msg import Marker
    find_fixture_packages(monkeypatch)
    meshes = [m for m in markers_of(TRACK_WORLD) if m.type == Marker.MESH_RESOURCE]
    assert meshes
    for m in meshes:
        path = m.mesh_resource[len('file://'):]
        assert m.mesh_resource.startswith('file:///') and os.path.isfile(path)
        if path.endswith('.stl'):  # no materials of its own: the visual's colour
            assert not m.mesh_use_embedded_materials and m.color.a > 0
        else:  # rviz: all-zero colour means the file's materials untinted
            assert m.mesh_use_embedded_materials and (m.color.r, m.color.g, m.color.b, m.color.a) == (0, 0, 0, 0)


@pytest.mark.parametrize('normal', [(0, 0, 1), (1, 0, 0), (0, -1, 0), (0.6, 0, 0.8), (0, 0, -1)])
def test_a_planes_marker_turns_z_to_its_normal(normal):
    q = z_to(normal)
    assert sum(v * v for v in q) == pytest.approx(1.0)
    assert rotate(q, (0, 0, 1)) == pytest.approx(normal, abs=1e-12)


@pytest.mark.ros
def test_the_node_publishes_the_plants_world_latched_in_its_frame(ros):
    from ros_harness import start_plant
    start_plant(ros, RACE_TRACK_WORLD)
    ros.start(['rosrun', 'tianracer_description', 'scene_markers', '_frame_id:=world'], 'scene_markers')
    out = ros.probe('viewer/probes/the_node_publishes_the_plants_world_latched_in_its_frame.py', timeout=60)
    assert out[0][1] == 3  # DELETEALL
    world_visuals = [v for v in scene_of(RACE_TRACK_WORLD)['visuals'] if not v['model']]
    assert sorted(m[3] for m in out[1:]) == sorted(v['link'].split('::')[0] for v in world_visuals)
    assert {m[0] for m in out} == {'world'}


def xwd_rgb(data):
    """An X window dump (xwd -root, a TrueColor screen at 24 or 32 bits a pixel) as rows of r g b."""
    header = struct.unpack('>25I', data[:100])
    header_size, width, height, byte_order = header[0], header[4], header[5], header[7]
    bits_per_pixel, bytes_per_line, colours = header[11], header[12], header[19]
    start = header_size + 12 * colours
    n = bits_per_pixel // 8
    pixels = np.frombuffer(data[start:start + bytes_per_line * height], np.uint8).reshape(height, bytes_per_line)
    pixels = pixels[:, :width * n].reshape(height, width, n)
    return pixels[:, :, [2, 1, 0]] if byte_order == 0 else pixels[:, :, [n - 3, n - 2, n - 1]]


@pytest.mark.ros
def test_rviz_started_with_rviz_true_draws_the_race_tracks_walls(ros, tmp_path):
    """tianracer_world.launch rviz:=true on a virtual screen (Xvfb): rviz with the car's config draws the
    track's red walls (the World display, from scene_markers); the red is the walls' alone (the car is
    blue, the cones orange, the floor grey). The screenshot is kept in the test's folder."""
    xvfb = ros.start(['Xvfb', '-displayfd', '1', '-screen', '0', '1200x800x24', '-nolisten', 'tcp'], 'xvfb')
    ros.wait_until(lambda: xvfb.log().strip().isdigit(), 15, 'Xvfb to choose a display')
    ros.env['DISPLAY'] = ':' + xvfb.log().strip()
    ros.start(['roslaunch', 'tianracer_description', 'tianracer_world.launch', 'gui:=false', 'rviz:=true',
               'world_name:=' + RACE_TRACK_WORLD], 'launch')
    ros.probe('viewer/probes/rviz_started_with_rviz_true_draws_the_race_tracks_walls.py', timeout=90)

    def red_share():
        dump = subprocess.run(['xwd', '-root', '-silent'], env=ros.env, capture_output=True, timeout=30)
        assert dump.returncode == 0, dump.stderr
        rgb = xwd_rgb(dump.stdout)
        r, g, b = (rgb[:, :, k].astype(int) for k in range(3))
        red_share.rgb = rgb
        return np.mean((r > 60) & (r > 3 * g) & (r > 3 * b))
    deadline = time.monotonic() + 60
    while red_share() < 0.02 and time.monotonic() < deadline:
        time.sleep(1.0)
    from PIL import Image
    Image.fromarray(np.ascontiguousarray(red_share.rgb)).save(str(tmp_path / 'rviz.png'))
    assert red_share() >= 0.02, 'no red walls in rviz (screenshot: %s)\n%s' % (tmp_path / 'rviz.png', rviz_state(ros))


def rviz_state(ros):
    """What a failure needs said (its screenshot is gone with CI's machine): whether rviz subscribes to
    the markers, its own log, and the end of the launch's."""
    topic = ros.run(['rostopic', 'info', '/gazebo/scene_markers'], timeout=15)
    rviz_logs = glob.glob(os.path.join(ros.env['ROS_HOME'], 'log', '*', 'rviz-*-stdout.log'))
    rviz_log = ''.join(open(path, errors='replace').read()[-3000:] for path in rviz_logs)
    launch_log = ''.join(p.log() for p in ros.processes if p.log_path.endswith('launch.log'))[-3000:]
    return '--- rostopic info /gazebo/scene_markers:\n%s%s\n--- rviz\'s log:\n%s\n--- the launch\'s log, its end:\n%s' % (
        topic.stdout, topic.stderr, rviz_log or '(none)', launch_log)


def test_rviz_launch_starts_scene_markers_beside_rviz_with_a_display_for_them():
    root = ET.parse(os.path.join(PACKAGE, 'launch', 'rviz.launch')).getroot()
    assert {n.get('type') for n in root.iter('node')} == {'scene_markers', 'rviz'}
    with open(os.path.join(PACKAGE, 'config', 'tianracer.rviz')) as f:
        assert 'Marker Topic: /gazebo/scene_markers' in f.read()
