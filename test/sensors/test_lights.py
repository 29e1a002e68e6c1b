"""Point and spot <light>s of a world light what cameras see as Gazebo's renderer (OGRE) lights it:
the light's diffuse colour times n . l, over constant + linear d + quadratic d^2, within its range,
and a spot's cone. A camera in a static SDF model of the world looks straight down at the ground
plane (grey 0.7) from 3 m; the sun shines straight down too, so every floor pixel has the same
light but for the lamp's share, which is what each test reads. The lights are drawn by a shader
that llvmpipe compiles for the CPU's vector width: the point light is checked at the width this CPU
picks and at 128 bits (SSE, what a CPU without AVX gets), in a process of its own (llvmpipe reads
LP_NATIVE_VECTOR_WIDTH once)."""
import json
import os
import subprocess
import sys

import numpy as np
import pytest

from tianracer_description import bullet_plant

FLOOR = 0.7 * 255  # the ground plane's grey, in levels
WIDTH, HEIGHT, FOV = 81, 61, 1.2


def looking_down(lights='', vector_width=None):
    """The grey levels the camera sees; with vector_width, from llvmpipe at that width in a process of
    its own."""
    if vector_width:
        env = dict(os.environ, LP_NATIVE_VECTOR_WIDTH=vector_width)
        env.pop('TIANRACER_GL_DEVICE', None)
        code = ('import json, sys; sys.path.insert(0, %r); import test_lights; '
                'print(json.dumps(test_lights.looking_down(%r).tolist()))' % (os.path.dirname(__file__), lights))
        run = subprocess.run([sys.executable, '-c', code], capture_output=True, text=True, env=env, timeout=120)
        assert run.returncode == 0, run.stderr
        return np.array(json.loads(run.stdout.strip().splitlines()[-1]))
    world = bullet_plant.World.from_sdf(f"""<sdf version="1.6"><world name="lit">
<scene><ambient>0.2 0.2 0.2 1</ambient><shadows>false</shadows></scene>
<include><uri>model://ground_plane</uri></include>
<light name="sun" type="directional"><direction>0 0 -1</direction></light>
{lights}
<model name="eye"><static>true</static><pose>0 0 3 0 1.5707963267948966 0</pose><link name="link">
  <sensor name="camera" type="camera"><update_rate>10</update_rate><camera><horizontal_fov>{FOV}</horizontal_fov>
    <image><width>{WIDTH}</width><height>{HEIGHT}</height></image><clip><near>0.1</near><far>10</far></clip></camera>
  </sensor></link></model>
</world></sdf>""")
    world.echo = False
    eye = world.robot('eye')
    eye.enable_sensor('camera')
    world.step(120)
    return eye.image('camera')['rgb'].astype(float).mean(axis=2)


def floor_point(u, v):
    """Where pixel (u right, v down) of the camera 3 m up looking down (image top towards +x) meets the floor."""
    f = (WIDTH / 2) / np.tan(FOV / 2)
    return np.array([-(v - (HEIGHT - 1) / 2) / f * 3.0, -(u - (WIDTH - 1) / 2) / f * 3.0, 0.0])


def lamp_share(light_at, u, v, colour=0.5, constant=1.0, linear=0.5, quadratic=0.0):
    to_light = np.asarray(light_at) - floor_point(u, v)
    d = np.linalg.norm(to_light)
    return FLOOR * colour * (to_light[2] / d) / (constant + linear * d + quadratic * d * d)


def point_light(pose='0 0 1 0 0 0', range_m=5.0):
    return f"""<light name="lamp" type="point"><pose>{pose}</pose><diffuse>0.5 0.5 0.5 1</diffuse>
<attenuation><range>{range_m}</range><constant>1</constant><linear>0.5</linear><quadratic>0</quadratic></attenuation></light>"""


@pytest.mark.parametrize('vector_width', [None, '128'], ids=['native', 'llvmpipe128'])
def test_a_point_light_adds_its_attenuated_share_to_every_pixel_it_reaches(vector_width):
    dark, lit = looking_down(vector_width=vector_width), looking_down(point_light(), vector_width)
    assert lit.max() < 250, 'no pixel saturated: the shares are all seen'
    for u, v in ((40, 30), (10, 10), (70, 50), (40, 5)):
        assert lit[v, u] - dark[v, u] == pytest.approx(lamp_share([0, 0, 1], u, v), abs=2.5), (u, v)


def test_beyond_its_range_a_light_adds_nothing():
    dark, lit = looking_down(), looking_down(point_light(range_m=1.2))
    assert lit[30, 40] - dark[30, 40] == pytest.approx(lamp_share([0, 0, 1], 40, 30), abs=2.5)
    far = floor_point(5, 5)
    assert np.linalg.norm(far - [0, 0, 1]) > 1.2
    assert lit[5, 5] == pytest.approx(dark[5, 5], abs=1.0)


def test_a_spot_lights_inside_its_cone_only():
    spot = """<light name="spot" type="spot"><pose>0 0 2 0 0 0</pose><diffuse>0.2 0.2 0.2 1</diffuse>
<direction>0 0 -1</direction><attenuation><range>10</range><constant>1</constant><linear>0</linear><quadratic>0</quadratic></attenuation>
<spot><inner_angle>0.6</inner_angle><outer_angle>0.8</outer_angle><falloff>1</falloff></spot></light>"""
    dark, lit = looking_down(), looking_down(spot)
    # straight below: inside the inner cone, the full share (n . l = 1, no distance falloff)
    assert lit[30, 40] - dark[30, 40] == pytest.approx(FLOOR * 0.2, abs=2.5)
    # a floor point 30 degrees off the axis (beyond the outer half angle, 0.4 rad): dark
    u = 40 + int(round(np.tan(np.radians(30)) * 2.0 / 3.0 * (WIDTH / 2) / np.tan(FOV / 2)))
    assert lit[30, u] == pytest.approx(dark[30, u], abs=1.0)


def test_a_light_that_lights_nothing_is_named_and_left_out():
    world = bullet_plant.World.from_sdf("""<sdf version="1.6"><world name="w">
<light name="dud" type="point"><attenuation><range>5</range><constant>0</constant><linear>0</linear><quadratic>0</quadratic></attenuation></light>
</world></sdf>""")
    world.echo = False
    assert [m for level, m in world.messages() if level == 'WARN' and "light 'dud'" in m and 'left dark' in m]
