"""gazebo_ros_camera's options as gazebo_ros_camera_utils (noetic-devel) and Gazebo 11 honour them,
through the node. Cameras side by side on one static model look at a red post left of a grey wall:
- the <image><format>: L8 (mono8) is the red channel of the R8G8B8 camera's pixels (OGRE's PF_L8
  keeps red), L16 (mono16) that red rendered at 16 bits, little-endian, step width x bytes a pixel;
  BAYER_RGGB8 its blocks; a format upstream does not know is bgr8 (with upstream's error);
- the <distortion>: a barrel lens (k1 < 0) shows the post nearer the image's centre, a pincushion
  one (k1 > 0) farther from it, where Brown's model puts it (u_d = c + f x (1 + k1 x^2));
- CameraInfo: K and P from Cx, Cy, focalLength and hackBaseline, D from distortionK1..T2, or from
  the sensor's <distortion> with autoDistortion; the defaults' centre (width + 1) / 2;
- set_hfov and set_update_rate: nobody subscribes, as upstream (its subscriptions are commented out)."""
import pytest

from plant_helpers import sdf_world
from ros_harness import start_plant

pytestmark = pytest.mark.ros

WIDTH, HFOV = 128, 1.0
POST_Y = -0.8  # m, right of the axis, 2 m ahead


def camera(name, image_format='R8G8B8', distortion='', plugin=''):
    lens = '<distortion>%s<center>0.5 0.5</center></distortion>' % distortion if distortion else ''
    return f"""<sensor name="{name}" type="camera"><update_rate>10</update_rate>
    <camera><horizontal_fov>{HFOV}</horizontal_fov>
      <image><width>{WIDTH}</width><height>{WIDTH}</height><format>{image_format}</format></image>
      <clip><near>0.05</near><far>20</far></clip>{lens}</camera>
    <plugin name="{name}_plugin" filename="libgazebo_ros_camera.so"><cameraName>{name}</cameraName>
      <frameName>eye</frameName>{plugin}</plugin>
  </sensor>"""


CAMERAS = [
    camera('rgb'),
    camera('mono', 'L8'),
    camera('mono16', 'L16'),
    camera('bayer', 'BAYER_RGGB8'),
    camera('odd', 'FLOAT32'),
    camera('barrel', distortion='<k1>-0.5</k1>', plugin='<borderCrop>false</borderCrop><autoDistortion>true</autoDistortion>'),
    camera('pincushion', distortion='<k1>0.5</k1>'),
    camera('tuned', plugin='<Cx>30</Cx><Cy>20</Cy><focalLength>50</focalLength><hackBaseline>0.1</hackBaseline>'
                           '<distortionK1>0.1</distortionK1><distortionK2>0.2</distortionK2>'
                           '<distortionT1>0.3</distortionT1><distortionT2>0.4</distortionT2>'
                           '<distortionK3>0.5</distortionK3>'),
]


def scene():
    post = '<geometry><box><size>0.05 0.05 2.0</size></box></geometry>'
    wall = '<geometry><box><size>0.1 8 3</size></box></geometry>'
    red = '<material><ambient>1 0 0 1</ambient><diffuse>1 0 0 1</diffuse></material>'
    grey = '<material><ambient>0.5 0.5 0.5 1</ambient><diffuse>0.5 0.5 0.5 1</diffuse></material>'
    return f"""<model name="post"><static>true</static><pose>2 {POST_Y} 1 0 0 0</pose><link name="link">
  <visual name="visual">{post}{red}</visual></link></model>
<model name="wall"><static>true</static><pose>4 0 1.5 0 0 0</pose><link name="link">
  <visual name="visual">{wall}{grey}</visual></link></model>
<model name="eye"><static>true</static><pose>0 0 1 0 0 0</pose><link name="link">
  {''.join(CAMERAS)}
</link></model>"""


def post_column(k1, undistorted):
    """Brown's model: where a lens of k1 shows the post the undistorted camera sees at `undistorted`
    (pixel centres at integers, the centre between the middle two pixels)."""
    import math
    f, c = WIDTH / (2 * math.tan(HFOV / 2)), WIDTH / 2.0
    x = (undistorted + 0.5 - c) / f
    return c + f * x * (1 + k1 * x * x) - 0.5


def test_formats_lens_and_camera_info_as_upstream(ros, tmp_path):
    (tmp_path / 'cameras.world').write_text(sdf_world(scene()))
    plant = start_plant(ros, str(tmp_path / 'cameras.world'))
    seen = ros.probe('sensor_plugins/probes/camera_options.py', timeout=120)
    images, infos = seen['images'], seen['infos']
    size = WIDTH * WIDTH

    rgb = images['rgb']
    assert (rgb['encoding'], rgb['step']) == ('rgb8', 3 * WIDTH)
    red = bytes.fromhex(rgb['data'])[0::3]
    assert len(set(red)) > 2, 'the scene has more than one shade of red'
    mono = images['mono']
    assert (mono['encoding'], mono['step'], len(mono['data']) // 2) == ('mono8', WIDTH, size)
    assert bytes.fromhex(mono['data']) == red, 'L8 is the red channel of the colour camera'
    mono16 = images['mono16']
    assert (mono16['encoding'], mono16['step'], mono16['is_bigendian']) == ('mono16', 2 * WIDTH, 0)
    data16 = bytes.fromhex(mono16['data'])
    values16 = [data16[2 * k] | data16[2 * k + 1] << 8 for k in range(size)]
    # rendered at 16 bits: the red channel to within half a level of the 8-bit camera's
    assert max(abs(v16 - 257 * v) for v16, v in zip(values16, red)) <= 129
    bayer = images['bayer']
    assert (bayer['encoding'], bayer['step']) == ('bayer_rggb8', WIDTH)
    rgb_bytes, bayer_bytes = bytes.fromhex(rgb['data']), bytes.fromhex(bayer['data'])
    channel = lambda v, u: (0, 1, 1, 2)[(v % 2) * 2 + u % 2]
    assert all(bayer_bytes[v * WIDTH + u] == rgb_bytes[3 * (v * WIDTH + u) + channel(v, u)]
               for v in range(WIDTH) for u in range(WIDTH))
    odd = images['odd']
    assert (odd['encoding'], odd['step']) == ('bgr8', 3 * WIDTH)
    assert bytes.fromhex(odd['data'])[2::3] == red, 'an unknown format: B G R bytes, labelled bgr8'
    assert 'Unsupported Gazebo ImageFormat' in plant.log(), "upstream's error (the plant's own names the format)"

    # The post, right of the centre: the barrel lens pulls it in, the pincushion pushes it out.
    straight = seen['post']['rgb']
    assert straight > WIDTH / 2 + 20, seen['post']
    for name, k1 in (('barrel', -0.5), ('pincushion', 0.5)):
        expected = post_column(k1, straight)
        assert seen['post'][name] == pytest.approx(expected, abs=1.0), (name, seen['post'], expected)
    assert seen['post']['barrel'] < straight - 2 and seen['post']['pincushion'] > straight + 2

    import math
    f = WIDTH / (2 * math.tan(HFOV / 2))
    c = (WIDTH + 1) / 2.0  # upstream's default centre
    assert infos['rgb']['K'] == pytest.approx([f, 0, c, 0, f, c, 0, 0, 1])
    assert infos['rgb']['P'] == pytest.approx([f, 0, c, 0, 0, f, c, 0, 0, 0, 1, 0])
    assert infos['rgb']['D'] == [0, 0, 0, 0, 0] and infos['rgb']['model'] == 'plumb_bob'
    assert infos['tuned']['K'] == pytest.approx([50, 0, 30, 0, 50, 20, 0, 0, 1])
    assert infos['tuned']['P'] == pytest.approx([50, 0, 30, -5, 0, 50, 20, 0, 0, 0, 1, 0])
    assert infos['tuned']['D'] == pytest.approx([0.1, 0.2, 0.3, 0.4, 0.5]), 'k1 k2 t1 t2 k3'
    assert infos['barrel']['D'] == pytest.approx([-0.5, 0, 0, 0, 0]), 'autoDistortion: the sensor lens'
    assert infos['pincushion']['D'] == [0, 0, 0, 0, 0], 'without autoDistortion: the plugin zeros'
    assert 'inconsistent with specified image_width' in plant.log(), 'upstream warns about focalLength'
    assert seen['control_subscribers'] == [], 'set_hfov / set_update_rate: commented out upstream'
