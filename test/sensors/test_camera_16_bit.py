"""A camera with a 16-bit <image><format> (L16, R16G16B16) renders at 16 bits, as Gazebo renders it
into a 16-bit OGRE target: a smooth shade takes levels between the 8-bit ones (not 257 x a byte),
each within half an 8-bit level of the same view from an 8-bit camera; its noise is drawn at 16
bits (a stddev of 0.001 is 65.5 levels of 1/65535, a quarter of one 8-bit level) and comes after the
lens, as the 8-bit camera's does. Forced onto llvmpipe's 128-bit path too (LP_NATIVE_VECTOR_WIDTH), and
onto a GL without 16-bit colour targets (Mesa's MESA_EXTENSION_OVERRIDE), which gives 257 x the 8-bit
frame."""
import io
import os
import subprocess
import sys

import numpy as np
import pytest

from tianracer_description import bullet_plant

SIZE = 96


def camera(name, image_format, noise='', distortion=''):
    lens = '<distortion>%s<center>0.5 0.5</center></distortion>' % distortion if distortion else ''
    noise = f'<noise><type>gaussian</type><mean>0</mean><stddev>{noise}</stddev></noise>' if noise else ''
    return f"""<sensor name="{name}" type="camera"><update_rate>10</update_rate><camera><horizontal_fov>0.9</horizontal_fov>
<image><width>{SIZE}</width><height>{SIZE}</height><format>{image_format}</format></image>
<clip><near>0.05</near><far>20</far></clip>{noise}{lens}</camera></sensor>"""


def world(cameras):
    # a white sphere lit by a low sun: its shade falls smoothly from the lit side to the terminator
    return f"""<sdf version="1.6"><world name="w"><scene><ambient>0.1 0.1 0.1 1</ambient>
<background>0 0 0 1</background></scene>
<light name="sun" type="directional"><diffuse>1 1 1 1</diffuse><specular>0 0 0 1</specular>
<direction>-0.3 -0.9 -0.3</direction><cast_shadows>false</cast_shadows></light>
<model name="ball"><static>true</static><pose>3 0 1 0 0 0</pose><link name="link"><visual name="v">
<geometry><sphere><radius>1</radius></sphere></geometry>
<material><ambient>1 1 1 1</ambient><diffuse>1 1 1 1</diffuse></material></visual></link></model>
<model name="eye"><static>true</static><pose>0 0 1 0 0 0</pose><link name="link">{''.join(cameras)}</link></model>
</world></sdf>"""


def frames(cameras):
    w = bullet_plant.World.from_sdf(world(cameras))
    w.echo = False
    eye = w.robot('eye')
    names = [c.split('"')[1] for c in cameras]
    for name in names:
        eye.enable_sensor(name)
    w.step(100)
    return {name: eye.image(name) for name in names}


def test_a_16_bit_camera_renders_levels_between_the_8_bit_ones():
    images = frames([camera('deep', 'L16'), camera('colour', 'R16G16B16'), camera('byte', 'R8G8B8')])
    deep, byte = images['deep'], images['byte']
    assert 'rgb16' not in byte and deep['rgb16'].dtype == np.uint16
    red16 = deep['rgb16'][..., 0].astype(int)
    red8 = byte['rgb'][..., 0].astype(int)
    on_ball = red8 > 0
    assert on_ball.mean() > 0.3, 'the ball fills the view'
    # the same view, within half an 8-bit level (8-bit rounding of the same shade)
    assert np.abs(red16 - 257 * red8).max() <= 129
    # and finer than bytes: most values on the ball are not 257 x a byte, and there are several
    # 16-bit levels for each 8-bit one the ball shows
    assert np.mean(red16[on_ball] % 257 != 0) > 0.9
    assert len(np.unique(red16[on_ball])) > 4 * len(np.unique(red8[on_ball]))
    # rgb, for 8-bit readers of a 16-bit camera, is rgb16 rounded to bytes
    assert np.array_equal(deep['rgb'].astype(int), (red16[..., None] * 255 + 32767) // 65535 * np.ones(3, int))
    colour = images['colour']['rgb16'].astype(int)
    assert np.abs(colour - 257 * byte['rgb'].astype(int)).max() <= 129
    assert np.array_equal(colour[..., 0], red16), 'L16 is the red channel of the colour one'


@pytest.mark.parametrize('distortion', ['', '<k1>-0.3</k1>'], ids=['no lens', 'barrel'])
def test_a_16_bit_cameras_noise_is_drawn_at_16_bits(distortion):
    stddev = 0.001  # a quarter of an 8-bit level: at 8 bits it would round away
    images = frames([camera('clean', 'L16', distortion=distortion),
                     camera('noisy', 'L16', noise=stddev, distortion=distortion)])
    clean, noisy = images['clean']['rgb16'].astype(int), images['noisy']['rgb16'].astype(int)
    inner = (slice(SIZE // 4, 3 * SIZE // 4), slice(SIZE // 4, 3 * SIZE // 4), 0)
    difference = (noisy - clean)[inner]
    lit = (clean[inner] > 2000) & (clean[inner] < 63000)  # away from the clamps
    assert lit.mean() > 0.5
    assert np.std(difference[lit]) == pytest.approx(65535 * stddev, rel=0.15)
    assert abs(np.mean(difference[lit])) < 10
    # one sample a pixel after the lens: neighbours independent
    d = np.where(lit, difference, 0).astype(float)
    right = np.corrcoef(d[:, :-1].ravel(), d[:, 1:].ravel())[0, 1]
    assert abs(right) < 0.15, right


def frame_in_a_child(**environment):
    """An L16 camera's rgb16 and an R8G8B8 one's rgb, rendered in a child process with `environment` set."""
    script = ("import numpy as np, sys; sys.path[:0] = %r; import test_camera_16_bit as t; "
              "f = t.frames([t.camera('deep', 'L16'), t.camera('byte', 'R8G8B8')]); "
              "np.save(sys.stdout.buffer, f['deep']['rgb16']); np.save(sys.stdout.buffer, f['byte']['rgb'])") % [
                  os.path.dirname(__file__)]
    out = subprocess.run([sys.executable, '-c', script], env=dict(os.environ, **environment), capture_output=True,
                         check=True).stdout
    stream = io.BytesIO(out)
    return np.load(stream).astype(int), np.load(stream).astype(int)


def test_llvmpipes_128_bit_path_renders_16_bits_alike():
    narrow, _ = frame_in_a_child(LP_NATIVE_VECTOR_WIDTH='128')
    wide = frames([camera('deep', 'L16')])['deep']['rgb16'].astype(int)
    assert (narrow[..., 0] % 257 != 0).mean() > 0.3
    assert np.abs(narrow - wide).max() <= 2


def test_a_gl_without_16_bit_targets_gives_257_times_the_8_bit_frame():
    """Mesa told to hide GL_EXT_texture_norm16 (MESA_EXTENSION_OVERRIDE): the 8-bit render spread."""
    deep, byte = frame_in_a_child(MESA_EXTENSION_OVERRIDE='-GL_EXT_texture_norm16')
    assert (deep[..., 0] > 0).mean() > 0.3
    assert np.array_equal(deep[..., 0], 257 * byte[..., 0])
