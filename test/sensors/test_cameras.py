"""The colour and depth cameras of the URDF through the Python module: a box of known size and
colour at a known pose appears where the pinhole model puts it, in its colour; the depth camera
measures its face; the point cloud lies on it. Each test runs once per instruction set of Embree's
kernels this CPU runs (the embree_isa fixture, test/conftest.py: lidars cast rays). Cameras render
with OpenGL (llvmpipe here); where there is none they are off, say why, and the rest runs."""
import json
import math
import os
import subprocess
import sys

import numpy as np
import pytest

from plant_helpers import box_model, make_world, sdf_world
from suite_paths import HELPERS
from tianracer_description.urdf_geometry import _rpy_matrix

BOX_CENTRE = (2.0, 0.1, 0.15)
BOX_SIZE = (0.2, 0.4, 0.3)
FACE_X = BOX_CENTRE[0] - BOX_SIZE[0] / 2    # the face towards the car
RED = (1.0, 0.0, 0.0)
LIGHT = (0.5, 0.1, -0.9)                     # the sun shines along +x, onto the face


@pytest.fixture
def scene(embree_isa, urdf_xml, control_config):
    box = f"""<model name="box"><static>true</static><pose>{' '.join(map(str, BOX_CENTRE))} 0 0 0</pose>
      <link name="link">
        <collision name="collision"><geometry><box><size>{' '.join(map(str, BOX_SIZE))}</size></box></geometry></collision>
        <visual name="visual"><geometry><box><size>{' '.join(map(str, BOX_SIZE))}</size></box></geometry>
          <material><ambient>{' '.join(map(str, RED))} 1</ambient><diffuse>{' '.join(map(str, RED))} 1</diffuse></material></visual>
      </link></model>
      <light name="sun" type="directional"><direction>{' '.join(map(str, LIGHT))}</direction></light>"""
    world = make_world(control_config, sdf_world(box))
    robot = world.spawn(urdf_xml, 'tianracer')
    world.step(300)  # settle
    return world, robot


def optical_pose(robot, camera):
    """Rotation and position of a camera's optical frame in the world."""
    pose = robot.link_pose(camera + '_optical_frame')
    x, y, z, w = pose[3:]
    roll = math.atan2(2 * (w * x + y * z), 1 - 2 * (x * x + y * y))
    pitch = math.asin(max(-1.0, min(1.0, 2 * (w * y - z * x))))
    yaw = math.atan2(2 * (w * z + x * y), 1 - 2 * (y * y + z * z))
    return _rpy_matrix(roll, pitch, yaw), np.array(pose[:3])


def expected_face_mask(frame, rotation, origin):
    """Pixels whose centre ray meets the box's front face, by the pinhole model."""
    fx, cx, fy, cy = frame['K'][0], frame['K'][2], frame['K'][4], frame['K'][5]
    u, v = np.meshgrid(np.arange(frame['width']), np.arange(frame['height']))
    rays = np.stack([(u - cx) / fx, (v - cy) / fy, np.ones_like(u, dtype=float)], axis=-1) @ rotation.T
    t = (FACE_X - origin[0]) / rays[..., 0]
    hit_y, hit_z = origin[1] + t * rays[..., 1], origin[2] + t * rays[..., 2]
    return ((np.abs(hit_y - BOX_CENTRE[1]) <= BOX_SIZE[1] / 2) & (hit_z >= 0) & (hit_z <= BOX_SIZE[2])), t


def test_colour_camera_sees_the_box_where_the_pinhole_model_puts_it(scene):
    world, robot = scene
    robot.enable_sensor('camera')
    world.step(34)
    frame = robot.image('camera')
    assert (frame['width'], frame['height'], frame['frame_id']) == (160, 120, 'camera_optical_frame')
    rotation, origin = optical_pose(robot, 'camera')
    expected, _ = expected_face_mask(frame, rotation, origin)
    rgb = frame['rgb'].astype(int)
    seen = (rgb[..., 0] > 100) & (rgb[..., 1] < 40) & (rgb[..., 2] < 40)
    assert expected.sum() > 200
    rows, cols = np.nonzero(expected)
    seen_rows, seen_cols = np.nonzero(seen)
    for a, b in ((rows.min(), seen_rows.min()), (rows.max(), seen_rows.max()),
                 (cols.min(), seen_cols.min()), (cols.max(), seen_cols.max())):
        assert abs(int(a) - int(b)) <= 1, 'box bounds within 1 px of the pinhole model'
    # its colour: red, in SDF's default ambient light (0.4) and lit on the face by the sun of SDF's
    # default diffuse colour (1): 0.4 + cos (pinhole.h), noise stddev 0.007
    light = -np.array(LIGHT) / np.linalg.norm(LIGHT)
    shade = 0.4 + 1.0 * max(0.0, np.dot([-1, 0, 0], light))
    inside = expected & seen
    assert np.mean(rgb[inside][:, 0]) == pytest.approx(255 * shade, abs=2)
    assert np.mean(rgb[inside][:, 1]) < 3 and np.mean(rgb[inside][:, 2]) < 3


def test_depth_camera_measures_the_face_and_its_points_lie_on_it(scene):
    world, robot = scene
    robot.enable_sensor('depth_camera')
    world.step(67)
    frame = robot.image('depth_camera')
    assert (frame['width'], frame['height']) == (128, 96)
    rotation, origin = optical_pose(robot, 'depth_camera')
    expected, t = expected_face_mask(frame, rotation, origin)
    core = expected.copy()  # leave out the face's edge pixels, where a ray may meet the box's side
    core[1:-1, 1:-1] = expected[1:-1, 1:-1] & expected[:-2, 1:-1] & expected[2:, 1:-1] & expected[1:-1, :-2] & expected[1:-1, 2:]
    assert core.sum() > 100
    depth = frame['depth']
    assert np.abs(depth[core] - t[core]).max() < 1e-3, 'depth of the face within 1 mm (no noise)'
    points = frame['points'][core] @ rotation.T + origin   # optical frame -> world
    assert np.abs(points[:, 0] - FACE_X).max() < 1e-3, 'points on the face within 1 mm'
    assert np.isnan(depth[0, 0]) or depth[0, 0] > 0.3, 'NaN where nothing is hit within the clip range'
    assert np.isnan(depth).any()


def test_cameras_work_only_while_enabled_at_their_rates(scene):
    world, robot = scene
    world.step(1000)
    assert robot.image('camera') is None and robot.sensor_updates('camera') == 0
    robot.enable_sensor('camera')
    robot.enable_sensor('depth_camera')
    world.step(1000)
    assert robot.sensor_updates('camera') == 30
    assert robot.sensor_updates('depth_camera') == 15


POST_X = 1.5
POST_URDF = """<robot name="post"><link name="post_link">
  <visual><geometry><box size="0.5 0.5 1"/></geometry><material name="blue"><color rgba="0 0 1 1"/></material></visual>
  <collision><geometry><box size="0.1 0.1 1"/></geometry></collision>
  <inertial><mass value="1"/><inertia ixx="0.1" iyy="0.1" izz="0.1" ixy="0" ixz="0" iyz="0"/></inertial>
</link><gazebo><static>true</static></gazebo></robot>"""


POST_SDF = f"""<model name="post"><static>true</static><pose>{POST_X} 0 0.5 0 0 0</pose><link name="link">
  <collision name="collision"><geometry><box><size>0.1 0.1 1</size></box></geometry></collision>
  <visual name="visual"><geometry><box><size>0.5 0.5 1</size></box></geometry>
    <material><ambient>0 0 1 1</ambient><diffuse>0 0 1 1</diffuse></material></visual></link></model>"""


@pytest.mark.parametrize('post_of', ['robot', 'world'])
@pytest.mark.parametrize('lidar_type', ['ray', 'gpu_ray'])
def test_cameras_and_gpu_ray_see_visuals_ray_lidars_collisions(embree_isa, urdf_xml, control_config, lidar_type,
                                                                post_of):
    """A post (a static robot, or a model of the world) whose visual (0.5 m square, blue) is wider
    than its collision (0.1 m): Gazebo's cameras and gpu_ray lidars render visuals, its ray lidars
    hit collisions."""
    world = make_world(control_config, sdf_world(POST_SDF) if post_of == 'world' else None)
    robot = world.spawn(urdf_xml.replace('type="ray"', 'type="%s"' % lidar_type), 'tianracer')
    if post_of == 'robot':
        world.spawn(POST_URDF, 'post', pose=(POST_X, 0, 0.5, 0, 0, 0))
    world.step(300)
    for sensor in ('lidar', 'camera', 'depth_camera'):
        robot.enable_sensor(sensor)
    world.step(67)
    scan = robot.scan('lidar')
    ahead = scan['ranges'][np.argmin(np.abs(scan['angle_min'] + scan['angle_increment'] * np.arange(len(scan['ranges']))))]
    face = 0.25 if lidar_type == 'gpu_ray' else 0.05
    assert ahead == pytest.approx(POST_X - face - robot.link_pose('laser_link')[0], abs=0.05)  # noise 0.01 m
    colour = robot.image('camera')
    centre = colour['rgb'][colour['height'] // 2, colour['width'] // 2].astype(int)
    assert centre[2] > 80 and centre[0] < 10 and centre[1] < 10, 'the blue visual'
    depth = robot.image('depth_camera')
    rotation, origin = optical_pose(robot, 'depth_camera')
    along_x = (POST_X - 0.25 - origin[0]) / rotation[0, 2]  # the optical axis meets the visual's face
    assert depth['depth'][depth['height'] // 2, depth['width'] // 2] == pytest.approx(along_x, abs=0.02)


RENDER_SCRIPT = """
import json, sys, yaml
sys.path.insert(0, %r)
from plant_helpers import make_world, sdf_world
from tianracer_description.tianracer import tianracer_urdf, CONFIG_YAML
box = %r
world = make_world(yaml.safe_load(open(CONFIG_YAML)), sdf_world(box))
robot = world.spawn(tianracer_urdf(), 'tianracer')
world.step(300)
robot.enable_sensor('camera')
robot.enable_sensor('lidar')
world.step(34)
frame = robot.image('camera')  # None: no frame yet
print(json.dumps({'rgb': None if frame is None else frame['rgb'].flatten().tolist(),
                  'frames': robot.sensor_updates('camera'), 'scans': robot.sensor_updates('lidar'),
                  'log': [text for level, text in world.messages() if 'cameras:' in text]}))
"""


def camera_frame_with(**environment):
    """What the car's camera and lidar give before the red box in a fresh process with `environment`
    added: the frame (flat), the frames and scans made in 34 ms, and what the plant said about the
    cameras."""
    box = (f"<model name='box'><static>true</static><pose>{' '.join(map(str, BOX_CENTRE))} 0 0 0</pose><link name='link'>"
           f"<visual name='visual'><geometry><box><size>{' '.join(map(str, BOX_SIZE))}</size></box></geometry>"
           "<material><ambient>1 0 0 1</ambient><diffuse>1 0 0 1</diffuse></material></visual></link></model>")
    env = dict(os.environ, **environment)
    run = subprocess.run([sys.executable, '-c', RENDER_SCRIPT % (HELPERS, box)], capture_output=True, text=True, env=env,
                         timeout=120)
    assert run.returncode == 0, run.stderr
    return json.loads(run.stdout.strip().splitlines()[-1])


def test_cameras_render_with_opengl_on_the_cpu_when_asked():
    out = camera_frame_with(TIANRACER_GL_DEVICE='cpu')
    assert out['log'] == [out['log'][0]] and out['log'][0].startswith('cameras: OpenGL ES on llvmpipe'), out['log']
    assert out['frames'] >= 1 and out['scans'] > 0
    rgb = np.array(out['rgb']).reshape(-1, 3)
    assert np.any((rgb[:, 0] > 60) & (rgb[:, 1] < 15)), 'the red box, its face towards the car in the ambient light'


# glvnd's libEGL reads its vendors (Mesa's libEGL_mesa, a GPU's) from the files this names: none here
NO_EGL_DRIVER = {'__EGL_VENDOR_LIBRARY_FILENAMES': '/nonexistent/egl_vendor.json'}


@pytest.mark.parametrize('environment,why', [
    (NO_EGL_DRIVER, 'EGL has no device enumeration'),
    ({'TIANRACER_GL_DEVICE': 'gpu'}, 'no GPU EGL device (TIANRACER_GL_DEVICE asked for one)')],
    ids=['no EGL driver', 'no GPU where one is asked for'])
def test_without_opengl_cameras_are_off_and_say_why_and_the_lidar_still_scans(environment, why):
    out = camera_frame_with(**environment)
    if environment.get('TIANRACER_GL_DEVICE') == 'gpu' and out['log'][0].startswith('cameras: OpenGL ES on'):
        pytest.skip('this machine has a GPU: ' + out['log'][0])
    assert len(out['log']) == 1, out['log']
    assert out['log'][0].startswith('cameras: off, no OpenGL (') and why in out['log'][0], out['log']
    assert out['log'][0].endswith('): camera sensors give no frames; every other sensor runs'), out['log']
    assert out['frames'] == 0 and out['rgb'] is None
    assert out['scans'] > 0


def shadow_scene_frame(control_config, urdf_xml, shadows):
    """The car's camera frame before a 1 m post 1 m ahead in Gazebo's sun (model://sun, shining
    towards -x, so the post's shadow falls on the floor before it, 0.6 m long), with <scene><shadows>
    as given."""
    box = ("<include><uri>model://sun</uri></include>"
           "<model name='post'><static>true</static><pose>1.0 0.1 0.5 0 0 0</pose>"
           "<link name='link'><visual name='visual'><geometry><box><size>0.2 0.4 1.0</size>"
           "</box></geometry></visual></link></model>"
           f"<scene><shadows>{str(shadows).lower()}</shadows></scene>")
    world = make_world(control_config, sdf_world(box))
    robot = world.spawn(urdf_xml, 'tianracer')
    robot.enable_sensor('camera')
    world.step(334)
    return robot.image('camera')['rgb'].astype(float)


def test_the_sun_casts_shadows_unless_the_scene_turns_them_off(control_config, urdf_xml):
    lit = shadow_scene_frame(control_config, urdf_xml, False)
    shaded = shadow_scene_frame(control_config, urdf_xml, True)
    darker = (lit - shaded).mean(axis=2) > 20  # the camera's noise is about 2 levels
    rows = np.nonzero(darker.any(axis=1))[0]
    assert darker.mean() > 0.01, 'the box\'s shadow on the floor'
    assert rows.min() > lit.shape[0] // 2, 'below the horizon: on the floor before the box'
    assert ((shaded - lit).mean(axis=2) < 8).all(), 'a shadow only takes light away'
    # in the shadow the floor (the ground plane's Gazebo/Grey: ambient 0.3, diffuse 0.7) keeps its
    # ambient share: 0.4 x 0.3 / (0.4 x 0.3 + 0.8 x 0.7 cos) under the sun's diffuse 0.8
    towards = -np.array([-0.5, 0.1, -0.9]) / np.linalg.norm([-0.5, 0.1, -0.9])
    share = 0.4 * 0.3 / (0.4 * 0.3 + 0.8 * 0.7 * towards[2])
    assert shaded[darker].mean() / lit[darker].mean() == pytest.approx(share, rel=0.03)


def stepped_frames(control_config, urdf_xml, ahead):
    """The car's camera and depth camera frames, and the frames counted, after each of 120 single
    steps and at the end, with frames ahead (rendering while the following steps run) or not."""
    world = make_world(control_config, sdf_world(box_model('box', BOX_SIZE, BOX_CENTRE)))
    robot = world.spawn(urdf_xml, 'tianracer')
    world.frames_ahead = ahead
    robot.enable_sensor('camera')
    robot.enable_sensor('depth_camera')
    robot.controller_manager.spawn(['joint_state_controller', 'rear_left_velocity_controller',
                                    'rear_right_velocity_controller'])
    robot.controller_manager.command('rear_left_velocity_controller', 10.0)
    robot.controller_manager.command('rear_right_velocity_controller', 10.0)
    counts, frames = [], []
    for _ in range(120):
        world.step(1)
        counts.append(robot.sensor_updates('camera'))
        image = robot.image('camera')
        frames.append(None if image is None else (image['stamp'], image['rgb'].tobytes()))
    world.frames_ahead = False  # waits for the frames still rendering
    last = robot.image('camera'), robot.image('depth_camera')
    return counts + [robot.sensor_updates('camera')], frames, last


def test_frames_rendered_while_the_simulation_goes_on_are_those_of_their_own_time(control_config, urdf_xml):
    waited_counts, waited, (waited_rgb, waited_depth) = stepped_frames(control_config, urdf_xml, False)
    ahead_counts, ahead, (ahead_rgb, ahead_depth) = stepped_frames(control_config, urdf_xml, True)
    # the car drives on while the frames render: every frame, whenever it was collected, is the
    # frame of its own time, byte for byte the one made waiting
    assert waited_counts[-1] == ahead_counts[-1] == 4, 'frames at 30 Hz in 120 ms, all made in the end'
    waited_by_stamp = {frame[0]: frame[1] for frame in waited if frame}
    assert len(waited_by_stamp) == 4
    for frame in ahead:
        if frame:
            assert waited_by_stamp[frame[0]] == frame[1]
    assert all(a <= w for a, w in zip(ahead_counts, waited_counts)), 'a frame ahead is counted when it is done'
    assert ahead_rgb['stamp'] == waited_rgb['stamp'] and np.array_equal(ahead_rgb['rgb'], waited_rgb['rgb'])
    assert np.array_equal(ahead_depth['depth'], waited_depth['depth'], equal_nan=True)


def test_out_of_lockstep_a_late_frame_is_skipped_and_the_simulation_goes_on(control_config, urdf_xml):
    # The car's camera asked for a frame every step (1 kHz): rendering one takes a
    # millisecond, a step microseconds. In lockstep (the Python module's default) every frame due is
    # made and the steps wait for them; out of it (the node, as Gazebo runs) a frame due while the
    # previous one still renders is skipped, counted, and the steps go on.
    made = {}
    for lockstep in (True, False):
        world = make_world(control_config, sdf_world(box_model('box', BOX_SIZE, BOX_CENTRE)))
        robot = world.spawn(urdf_xml.replace('<update_rate>30.0', '<update_rate>1000'), 'tianracer')
        world.frames_ahead = True
        world.lockstep = lockstep
        assert world.lockstep == lockstep
        robot.enable_sensor('camera')
        world.step(200)
        world.frames_ahead = False  # collects the frame still rendering
        made[lockstep] = robot.sensor_updates('camera'), robot.sensor_skipped('camera')
    assert made[True] == (200, 0)
    rendered, skipped = made[False]
    assert rendered + skipped == 200 and rendered >= 1 and skipped > 100, made


def resident_kb():
    with open('/proc/self/status') as status:
        return next(int(line.split()[1]) for line in status if line.startswith('VmRSS'))


def test_a_deleted_robot_leaves_the_frames_and_frees_what_cameras_drew_of_it(control_config, urdf_xml):
    """A second car spawned in front of a car's camera and deleted, 150 times, with frames rendered
    while the steps go on (a frame in flight meets the deletion): once deleted it is in no frame, and
    the process's memory stays flat, its bodies' meshes freed from the GL with it (each cycle kept
    about 350 KB of vertex buffers before)."""
    world = make_world(control_config, sdf_world('<include><uri>model://sun</uri></include>'))
    watcher = world.spawn(urdf_xml, 'watcher')
    watcher.enable_sensor('camera')
    world.frames_ahead = True
    world.step(300)
    before = watcher.image('camera')['rgb'].astype(float)
    for cycle in range(150):
        world.spawn(urdf_xml, 'other', pose=(0.6, 0, 0, 0, 0, 0))
        world.step(67)
        if cycle == 0:
            seen = watcher.image('camera')['rgb'].astype(float)
        assert world.remove('other')
        if cycle == 49:
            start_kb = resident_kb()
    grown_kb = resident_kb() - start_kb
    world.step(67)
    after = watcher.image('camera')['rgb'].astype(float)
    # the camera's noise alone: about 2 levels of 255; the car 0.6 m ahead: about 18
    assert np.abs(seen - before).mean() > 3 * np.abs(after - before).mean(), 'seen while there, gone after'
    assert grown_kb < 10_000, '%d KB more after 100 spawn-delete cycles' % grown_kb
