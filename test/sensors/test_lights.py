"""A world's <light>s and its visuals' materials light what cameras see as Gazebo 11 (OGRE's per-pixel
lighting) lights it (pinhole.h's Lighting): each pixel is
  emissive + ambient x material ambient
  + sum over lights of attenuation x spot x (diffuse x material diffuse x n . l)
  + sum over lights of attenuation x spot x specular x material specular x (n . h)^shininess,
clamped, with attenuation 1 / (constant + linear d + quadratic d^2) within the light's range and a
spot's ((rho - cos(outer / 2)) / (cos(inner / 2) - cos(outer / 2)))^falloff inside its cone.

The fixture: a camera in a static SDF model looks straight down at a floor (a box whose top is at
z = 0) from 3 m; a world without a directional light unless a test gives one, so the floor shows its
ambient and emissive light and the lamps' shares, which each test works out for every pixel here
(floor_point: where a pixel's ray meets the floor). The lights are drawn by shaders llvmpipe compiles
for the CPU's vector width: the lamps are checked at the width this CPU picks and at 128 bits (SSE,
what a CPU without AVX gets), in a process of its own (llvmpipe reads LP_NATIVE_VECTOR_WIDTH once)."""
import json
import os
import subprocess
import sys

import numpy as np
import pytest

from tianracer_description import bullet_plant

WIDTH, HEIGHT, FOV, EYE = 81, 61, 1.2, 3.0
AMBIENT = np.array([0.10, 0.12, 0.15])   # the fixture's <scene><ambient>
# the floor's <material>: ambient, diffuse, specular, emissive, shininess
FLOOR = dict(ambient=np.array([0.5, 0.5, 0.45]), diffuse=np.array([0.6, 0.55, 0.5]),
             specular=np.array([0.4, 0.4, 0.4]), emissive=np.array([0.02, 0.0, 0.0]), shininess=12.0)


def rgba(c, a=1.0):
    return '%g %g %g %g' % (c[0], c[1], c[2], a)


def floor_model(material=None):
    m = material or FLOOR
    return f"""<model name="floor"><static>true</static><pose>0 0 -0.05 0 0 0</pose><link name="link">
  <visual name="visual"><geometry><box><size>20 20 0.1</size></box></geometry><material>
    <ambient>{rgba(m['ambient'])}</ambient><diffuse>{rgba(m['diffuse'])}</diffuse>
    <specular>{rgba(m['specular'])}</specular><emissive>{rgba(m['emissive'])}</emissive>
    <shininess>{m['shininess']}</shininess></material></visual></link></model>"""


def camera_model():
    return f"""<model name="eye"><static>true</static><pose>0 0 {EYE} 0 1.5707963267948966 0</pose><link name="link">
  <sensor name="camera" type="depth"><update_rate>10</update_rate><camera><horizontal_fov>{FOV}</horizontal_fov>
    <image><width>{WIDTH}</width><height>{HEIGHT}</height></image><clip><near>0.1</near><far>10</far></clip></camera>
  </sensor></link></model>"""


def world_sdf(body, ambient=AMBIENT, floor=True):
    return f"""<sdf version="1.6"><world name="lit">
<scene><ambient>{rgba(ambient)}</ambient><shadows>false</shadows></scene>
{floor_model() if floor else ''}{body}{camera_model()}
</world></sdf>"""


def render(body, vector_width=None, **kw):
    """(rgb in levels as floats, depth, the world's messages) the camera sees; with vector_width, from
    llvmpipe at that width in a process of its own."""
    if vector_width:
        env = dict(os.environ, LP_NATIVE_VECTOR_WIDTH=vector_width)
        env.pop('TIANRACER_GL_DEVICE', None)
        code = ('import json, sys; sys.path.insert(0, %r); import test_lights; rgb, depth, said = test_lights.render(%r); '
                'print(json.dumps([rgb.tolist(), said]))' % (os.path.dirname(__file__), body))
        run = subprocess.run([sys.executable, '-c', code], capture_output=True, text=True, env=env, timeout=120)
        assert run.returncode == 0, run.stderr
        rgb, said = json.loads(run.stdout.strip().splitlines()[-1])
        assert any(('%s bits' % vector_width) in m for m in said), said
        return np.array(rgb), None, said
    world = bullet_plant.World.from_sdf(world_sdf(body, **kw))
    world.echo = False
    eye = world.robot('eye')
    eye.enable_sensor('camera')
    world.step(120)
    frame = eye.image('camera')
    return frame['rgb'].astype(float), frame['depth'], [m for _, m in world.messages()]


def floor_point(u, v):
    """Where pixel (u right, v down) of the camera 3 m up looking down (image top towards +x) meets the floor."""
    f = (WIDTH / 2) / np.tan(FOV / 2)
    return np.array([-(v - (HEIGHT - 1) / 2) / f * EYE, -(u - (WIDTH - 1) / 2) / f * EYE, 0.0])


def unit(v):
    return np.asarray(v, float) / np.linalg.norm(v)


def lamp_shares(p, lamp):
    """(diffuse, specular) light of `lamp` at floor point p (normal +z) seen from the camera, before
    the material: OGRE's per-pixel point, spot or directional light."""
    n = np.array([0.0, 0.0, 1.0])
    to_eye = unit(np.array([0.0, 0.0, EYE]) - p)
    if lamp['type'] == 'directional':
        l, share = -unit(lamp['direction']), 1.0
    else:
        to_light = np.asarray(lamp['position'], float) - p
        d = np.linalg.norm(to_light)
        l = to_light / d
        rng, c, lin, q = lamp['attenuation']
        share = 1.0 / (c + lin * d + q * d * d) if d <= rng else 0.0
        if lamp['type'] == 'spot':
            rho = np.dot(-l, unit(lamp['direction']))
            inner, outer, falloff = np.cos(lamp['inner'] / 2), np.cos(lamp['outer'] / 2), lamp['falloff']
            spot = 0.0 if rho < outer else np.clip((rho - outer) / (inner - outer), 0, 1)
            share *= spot ** falloff
    n_l = np.dot(n, l)
    if n_l <= 0:
        return np.zeros(3), np.zeros(3)
    n_h = max(0.0, np.dot(n, unit(l + to_eye)))
    return np.asarray(lamp['diffuse']) * n_l * share, np.asarray(lamp['specular']) * n_h ** FLOOR['shininess'] * share


def expected_floor(lamps, material=FLOOR, ambient=AMBIENT):
    """The floor's colour in levels at every pixel, as pinhole.h's Lighting has it."""
    out = np.zeros((HEIGHT, WIDTH, 3))
    for v in range(HEIGHT):
        for u in range(WIDTH):
            p = floor_point(u, v)
            diffuse, specular = np.zeros(3), np.zeros(3)
            for lamp in lamps:
                d, s = lamp_shares(p, lamp)
                diffuse += d
                specular += s
            colour = (material['emissive'] + ambient * material['ambient'] + material['diffuse'] * diffuse +
                      material['specular'] * specular)
            out[v, u] = np.clip(colour, 0, 1) * 255
    return out


def light_sdf(lamp):
    parts = [f'<light name="{lamp["name"]}" type="{lamp["type"]}">',
             f'<diffuse>{rgba(lamp["diffuse"])}</diffuse><specular>{rgba(lamp["specular"])}</specular>']
    if lamp['type'] != 'directional':
        parts.append('<pose>%g %g %g 0 0 0</pose>' % tuple(lamp['position']))
        parts.append('<attenuation><range>%g</range><constant>%g</constant><linear>%g</linear>'
                     '<quadratic>%g</quadratic></attenuation>' % tuple(lamp['attenuation']))
    if lamp['type'] != 'point':
        parts.append('<direction>%g %g %g</direction>' % tuple(lamp['direction']))
    if lamp['type'] == 'spot':
        parts.append('<spot><inner_angle>%g</inner_angle><outer_angle>%g</outer_angle><falloff>%g</falloff></spot>'
                     % (lamp['inner'], lamp['outer'], lamp['falloff']))
    return ''.join(parts) + '</light>'


# A point lamp whose range ends in view (it reaches 1.6 m about the point below it), with specular.
POINT = dict(name='lamp', type='point', position=[0.5, 0.3, 1.5], diffuse=[0.7, 0.6, 0.5], specular=[0.5, 0.5, 0.5],
             attenuation=[2.2, 0.5, 0.2, 0.1])
# A spot aslant whose cone's edge and falloff lie in view.
SPOT = dict(name='spot', type='spot', position=[-0.4, -0.5, 2.0], direction=[0.25, 0.1, -1.0],
            diffuse=[0.3, 0.5, 0.8], specular=[0.3, 0.3, 0.3], attenuation=[10, 1.0, 0.0, 0.05],
            inner=0.35, outer=0.9, falloff=2.0)


def expect_pixels(seen, expected, away_from=(), tolerance=2.5, share=1.0):
    """Every pixel (but those within a few centimetres of the given surfaces in the floor, where a
    light's range or cone ends) within `tolerance` levels of what is expected."""
    keep = np.ones((HEIGHT, WIDTH), bool)
    for v in range(HEIGHT):
        for u in range(WIDTH):
            p = floor_point(u, v)
            keep[v, u] = all(abs(edge(p)) > 0.03 for edge in away_from)
    close = np.abs(seen - expected).max(axis=2) <= tolerance
    assert keep.mean() > 0.8
    assert close[keep].mean() >= share, 'worst %.1f levels off at %s (of %d compared)' % (
        np.abs(seen - expected).max(axis=2)[keep].max(), np.unravel_index(
            np.argmax(np.where(keep, np.abs(seen - expected).max(axis=2), 0)), keep.shape), keep.sum())


def range_edge(lamp):
    return lambda p: np.linalg.norm(np.asarray(lamp['position']) - p) - lamp['attenuation'][0]


def cone_edge(lamp):
    def edge(p):
        l = unit(np.asarray(lamp['position']) - p)
        return (np.dot(-l, unit(lamp['direction'])) - np.cos(lamp['outer'] / 2)) * 3  # about metres on the floor
    return edge


@pytest.mark.parametrize('vector_width', [None, '128'], ids=['native', 'llvmpipe128'])
def test_a_point_and_a_spot_light_each_pixel_as_ogres_formula(vector_width):
    seen, _, _ = render(light_sdf(POINT) + light_sdf(SPOT), vector_width)
    expected = expected_floor([POINT, SPOT])
    # the pools of light and their edges are in view: lit, dark, and the spot's falloff between
    point_reach = np.array([[range_edge(POINT)(floor_point(u, v)) < 0 for u in range(WIDTH)] for v in range(HEIGHT)])
    assert 0.2 < point_reach.mean() < 0.9
    assert expected.max() < 250, 'no pixel saturated: every share is seen'
    expect_pixels(seen, expected, away_from=(range_edge(POINT), cone_edge(SPOT)))


def test_the_specular_highlight_follows_the_half_vector():
    """Without specular (a black material specular) the floor is the same but for the highlight: the
    difference at each pixel is the two lamps' specular share alone."""
    matte = dict(FLOOR, specular=np.zeros(3))
    shiny, _, _ = render(light_sdf(POINT) + light_sdf(SPOT))
    dull, _, _ = render(light_sdf(POINT) + light_sdf(SPOT) + floor_model(matte), floor=False)
    highlight = shiny - dull
    expected = expected_floor([POINT, SPOT]) - expected_floor([POINT, SPOT], material=matte)
    assert expected.max() > 20, 'a highlight of some levels'
    expect_pixels(highlight, expected, away_from=(range_edge(POINT), cone_edge(SPOT)), tolerance=3.0)


def test_a_directional_light_lights_in_its_own_colour_everywhere():
    sun = dict(name='sun', type='directional', direction=[0.3, -0.2, -1.0], diffuse=[0.9, 0.6, 0.3],
               specular=[0.0, 0.0, 0.0])
    seen, _, _ = render(light_sdf(sun))
    expect_pixels(seen, expected_floor([sun]))
    # a directional light is not attenuated: the same at every pixel
    assert np.ptp(seen.reshape(-1, 3), axis=0).max() <= 1


def test_a_world_without_a_directional_light_is_lit_by_its_ambient_light_and_lamps_alone():
    far = dict(POINT, position=[1.5, 1.5, 1.0], attenuation=[1.3, 1.0, 0.0, 0.0])
    seen, _, said = render(light_sdf(far))
    dark = np.clip(FLOOR['emissive'] + AMBIENT * FLOOR['ambient'], 0, 1) * 255
    outside = np.array([[range_edge(far)(floor_point(u, v)) > 0.03 for u in range(WIDTH)] for v in range(HEIGHT)])
    assert outside.mean() > 0.5
    assert np.abs(seen[outside] - dark).max() <= 1, 'out of the lamp\'s range: ambient and emissive light alone'
    expect_pixels(seen, expected_floor([far]), away_from=(range_edge(far),))
    # and a world with no light at all is lit by its ambient light alone
    none, _, _ = render('')
    assert np.abs(none - dark).max() <= 1


def test_gazebos_attenuation_factors_are_clamped_as_its_light_sets_them():
    """rendering/Light.cc's SetAttenuation clamps the constant and linear factors to [0, 1]."""
    lamp = dict(POINT, attenuation=[10, 3.0, 2.0, 0.1])
    seen, _, _ = render(light_sdf(lamp))
    expect_pixels(seen, expected_floor([dict(lamp, attenuation=[10, 1.0, 1.0, 0.1])]))


def test_a_light_that_lights_nothing_is_named_and_left_out():
    world = bullet_plant.World.from_sdf("""<sdf version="1.6"><world name="w">
<light name="dud" type="point"><attenuation><range>5</range><constant>0</constant><linear>0</linear><quadratic>0</quadratic></attenuation></light>
</world></sdf>""")
    world.echo = False
    assert [m for level, m in world.messages() if level == 'WARN' and "light 'dud'" in m and 'left dark' in m]
    # a direction that is none: said, and the light shines straight down
    seen, _, said = render(light_sdf(dict(SUN_DOWN, direction=[0, 0, 0])))
    assert [m for m in said if "light 'sun'" in m and 'not a direction' in m], said
    expect_pixels(seen, expected_floor([SUN_DOWN]))


# ---------------------------------------------------------------------------------------- materials
SUN_DOWN = dict(name='sun', type='directional', direction=[0, 0, -1], diffuse=[0.8, 0.8, 0.8], specular=[0.2, 0.2, 0.2])


def block(name, material_xml, x=0.0, geometry='<box><size>1.2 1.2 0.2</size></box>', extra=''):
    """A static block 0.2 m tall standing on the floor at (x, 0), its top 1.2 m square."""
    return f"""<model name="{name}"><static>true</static><pose>{x} 0 0.1 0 0 0</pose><link name="link">
  <visual name="visual"><geometry>{geometry}</geometry>{material_xml}{extra}</visual></link></model>"""


def centre_of_block(rgb, x=0.0):
    """The mean colour of the middle of the block's top (at 0.2 m, x) in the image."""
    f = (WIDTH / 2) / np.tan(FOV / 2)
    v = int(round((HEIGHT - 1) / 2 - x * f / (EYE - 0.2)))
    u = (WIDTH - 1) // 2
    return rgb[v - 2:v + 3, u - 2:u + 3].reshape(-1, 3).mean(axis=0)


def lit_top(material, sun=SUN_DOWN, ambient=AMBIENT):
    """A block top's colour (levels) under the straight-down sun, seen from straight above (n . l =
    n . h = 1), as pinhole.h has it."""
    m = {k: np.asarray(material.get(k, d), float) for k, d in
         (('ambient', (1, 1, 1)), ('diffuse', (1, 1, 1)), ('specular', (0, 0, 0)), ('emissive', (0, 0, 0)))}
    shininess = material.get('shininess', 0)
    colour = m['emissive'] + ambient * m['ambient'] + m['diffuse'] * np.asarray(sun['diffuse'])
    if shininess > 0:
        colour = colour + m['specular'] * np.asarray(sun['specular'])
    return np.clip(colour, 0, 1) * 255


def test_sdf_material_colours_each_as_gazebos_visual_applies_them():
    """<ambient> and <diffuse> given; only <diffuse> (the others are an OGRE pass's own: ambient
    white); <emissive>; <specular> with <shininess> (a highlight) and without (none, Gazebo's
    shininess 0); <transparency> and a diffuse alpha below 1."""
    cases = [
        ('both', '<material><ambient>0.2 0.3 0.4 1</ambient><diffuse>0.5 0.2 0.1 1</diffuse></material>',
         dict(ambient=(0.2, 0.3, 0.4), diffuse=(0.5, 0.2, 0.1))),
        ('diffuse_only', '<material><diffuse>0.5 0.2 0.1 1</diffuse></material>', dict(diffuse=(0.5, 0.2, 0.1))),
        ('emissive', '<material><ambient>0.1 0.1 0.1 1</ambient><diffuse>0.2 0.2 0.2 1</diffuse>'
                     '<emissive>0.3 0.1 0.0 1</emissive></material>',
         dict(ambient=(0.1, 0.1, 0.1), diffuse=(0.2, 0.2, 0.2), emissive=(0.3, 0.1, 0.0))),
        ('shiny', '<material><ambient>0.1 0.1 0.1 1</ambient><diffuse>0.3 0.3 0.3 1</diffuse>'
                  '<specular>0.9 0.5 0.2 1</specular><shininess>20</shininess></material>',
         dict(ambient=(0.1, 0.1, 0.1), diffuse=(0.3, 0.3, 0.3), specular=(0.9, 0.5, 0.2), shininess=20)),
        ('specular_without_shininess', '<material><ambient>0.1 0.1 0.1 1</ambient><diffuse>0.3 0.3 0.3 1</diffuse>'
                                       '<specular>0.9 0.5 0.2 1</specular></material>',
         dict(ambient=(0.1, 0.1, 0.1), diffuse=(0.3, 0.3, 0.3))),
        ('none', '', dict(specular=(0.1, 0.1, 0.1), shininess=128)),  # Gazebo/White
        ('script', '<material><script><uri>file://media/materials/scripts/gazebo.material</uri>'
                   '<name>Gazebo/Gold</name></script></material>',
         dict(ambient=(0.4, 0.24869, 0.020759), diffuse=(0.8, 0.64869, 0.120759), specular=(0.4, 0.4, 0.4),
              shininess=12.5)),
        ('script_then_ambient', '<material><script><uri>file://media/materials/scripts/gazebo.material</uri>'
                                '<name>Gazebo/Gold</name></script><ambient>0 0 1 1</ambient></material>',
         dict(ambient=(0, 0, 1), diffuse=(0.8, 0.64869, 0.120759), specular=(0.4, 0.4, 0.4), shininess=12.5)),
    ]
    for name, xml, material in cases:
        seen, _, _ = render(light_sdf(SUN_DOWN) + block('block', xml), floor=False)
        assert centre_of_block(seen) == pytest.approx(lit_top(material), abs=1.5), name


def test_transparent_surfaces_are_blended_over_what_is_behind_them():
    """A visual whose <transparency> is 0.6 (or whose <diffuse> alpha is 0.4) over the floor: its
    colour at 0.4 over the floor's, as OGRE's transparent_alpha blend; the depth image sees the floor."""
    glass = dict(ambient=(0.0, 0.0, 0.0), diffuse=(0.1, 0.3, 0.9))
    floor_only, _, _ = render(light_sdf(SUN_DOWN))
    behind = centre_of_block(floor_only)
    front = lit_top(glass)
    for xml in ('<material><ambient>0 0 0 1</ambient><diffuse>0.1 0.3 0.9 1</diffuse></material>'
                '<transparency>0.6</transparency>',
                '<material><ambient>0 0 0 1</ambient><diffuse>0.1 0.3 0.9 0.4</diffuse></material>'):
        seen, depth, _ = render(light_sdf(SUN_DOWN) + block('glass', xml))
        assert centre_of_block(seen) == pytest.approx(0.4 * front + 0.6 * behind, abs=2.0), xml
        assert depth[HEIGHT // 2, WIDTH // 2] == pytest.approx(EYE, abs=1e-3), 'the depth image sees the floor'
    opaque, depth, _ = render(light_sdf(SUN_DOWN) + block(
        'glass', '<material><ambient>0 0 0 1</ambient><diffuse>0.1 0.3 0.9 1</diffuse></material>'))
    assert centre_of_block(opaque) == pytest.approx(front, abs=1.5)
    assert depth[HEIGHT // 2, WIDTH // 2] == pytest.approx(EYE - 0.2, abs=1e-3)


def write_mesh_files(directory):
    """A 1.2 m square 0.2 m above its origin as an OBJ with a material file (Ka Kd Ks Ke Ns), and as a
    Collada file with a phong effect, and one whose texture image is nowhere."""
    square = 'v -0.6 -0.6 0.2\nv 0.6 -0.6 0.2\nv 0.6 0.6 0.2\nv -0.6 0.6 0.2\n'
    with open(os.path.join(directory, 'tile.mtl'), 'w') as f:
        f.write('newmtl tile\nKa 0.3 0.2 0.1\nKd 0.2 0.4 0.6\nKs 0.6 0.6 0.6\nKe 0.1 0.0 0.05\nNs 30\n')
    with open(os.path.join(directory, 'tile.obj'), 'w') as f:
        f.write('mtllib tile.mtl\n' + square + 'usemtl tile\nf 1 2 3\nf 1 3 4\n')

    def collada(name, effect, images=''):
        with open(os.path.join(directory, name), 'w') as f:
            f.write(f"""<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <asset><unit name="meter" meter="1"/><up_axis>Z_UP</up_axis></asset>
  <library_images>{images}</library_images>
  <library_effects><effect id="fx"><profile_COMMON>
    <newparam sid="surface"><surface type="2D"><init_from>picture</init_from></surface></newparam>
    <newparam sid="sampler"><sampler2D><source>surface</source></sampler2D></newparam>
    <technique sid="common">{effect}</technique></profile_COMMON></effect></library_effects>
  <library_materials><material id="paint-id" name="paint"><instance_effect url="#fx"/></material></library_materials>
  <library_geometries><geometry id="g"><mesh>
    <source id="p"><float_array id="pa" count="12">-0.6 -0.6 0.2 0.6 -0.6 0.2 0.6 0.6 0.2 -0.6 0.6 0.2</float_array>
      <technique_common><accessor source="#pa" count="4" stride="3"><param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/></accessor></technique_common></source>
    <source id="t"><float_array id="ta" count="8">0 0 1 0 1 1 0 1</float_array>
      <technique_common><accessor source="#ta" count="4" stride="2"><param name="S" type="float"/><param name="T" type="float"/></accessor></technique_common></source>
    <vertices id="v"><input semantic="POSITION" source="#p"/></vertices>
    <triangles material="m" count="2"><input semantic="VERTEX" source="#v" offset="0"/><input semantic="TEXCOORD" source="#t" offset="0" set="0"/><p>0 1 2 0 2 3</p></triangles>
  </mesh></geometry></library_geometries>
  <library_visual_scenes><visual_scene id="s"><node id="n"><instance_geometry url="#g"><bind_material><technique_common>
    <instance_material symbol="m" target="#paint-id"/></technique_common></bind_material></instance_geometry></node></visual_scene></library_visual_scenes>
  <scene><instance_visual_scene url="#s"/></scene>
</COLLADA>""")
    collada('tile.dae', '<phong><emission><color>0.05 0.1 0 1</color></emission><ambient><color>0.2 0.2 0.3 1</color></ambient>'
                        '<diffuse><color>0.6 0.3 0.2 1</color></diffuse><specular><color>0.5 0.5 0.5 1</color></specular>'
                        '<shininess><float>25</float></shininess></phong>')
    collada('lost.dae', '<phong><diffuse><texture texture="sampler" texcoord="UVMap"/></diffuse></phong>',
            '<image id="picture" name="picture"><init_from>lost_picture.png</init_from></image>')


def mesh_block(name, uri, material_xml=''):
    return f"""<model name="{name}"><static>true</static><link name="link">
  <visual name="visual"><geometry><mesh><uri>{uri}</uri></mesh></geometry>{material_xml}</visual></link></model>"""


def test_collada_and_obj_materials_light_as_gazebos_loaders_read_them(tmp_path):
    write_mesh_files(str(tmp_path))
    obj = dict(ambient=(0.3, 0.2, 0.1), diffuse=(0.2, 0.4, 0.6), specular=(0.6, 0.6, 0.6), emissive=(0.1, 0.0, 0.05),
               shininess=30)
    dae = dict(ambient=(0.2, 0.2, 0.3), diffuse=(0.6, 0.3, 0.2), specular=(0.5, 0.5, 0.5), emissive=(0.05, 0.1, 0.0),
               shininess=25)
    for uri, material in ((str(tmp_path / 'tile.obj'), obj), (str(tmp_path / 'tile.dae'), dae)):
        seen, _, _ = render(light_sdf(SUN_DOWN) + mesh_block('tile', uri), floor=False)
        assert centre_of_block(seen) == pytest.approx(lit_top(material), abs=1.5), uri
    # an SDF <emissive> alone keeps the file's material; an SDF <ambient> replaces it with a fresh pass
    seen, _, _ = render(light_sdf(SUN_DOWN) + mesh_block(
        'tile', str(tmp_path / 'tile.dae'), '<material><emissive>0.2 0 0 1</emissive></material>'), floor=False)
    assert centre_of_block(seen) == pytest.approx(lit_top(dict(dae, emissive=(0.2, 0, 0))), abs=1.5)
    seen, _, _ = render(light_sdf(SUN_DOWN) + mesh_block(
        'tile', str(tmp_path / 'tile.dae'), '<material><ambient>0 0 0 1</ambient></material>'), floor=False)
    assert centre_of_block(seen) == pytest.approx(lit_top(dict(ambient=(0, 0, 0))), abs=1.5)


def test_a_texture_that_cannot_be_found_is_named_once_with_its_visual(tmp_path):
    write_mesh_files(str(tmp_path))
    seen, _, said = render(light_sdf(SUN_DOWN) + mesh_block('shelf', str(tmp_path / 'lost.dae')), floor=False)
    warnings = [m for m in said if 'lost_picture.png' in m]
    assert len(warnings) == 1, said
    assert "shelf::link::visual" in warnings[0] and 'lost.dae' in warnings[0], warnings[0]
    # drawn in its material without the texture: Gazebo's Collada defaults, ambient 0.4, diffuse 0.5
    assert centre_of_block(seen) == pytest.approx(lit_top(dict(ambient=(0.4,) * 3, diffuse=(0.5,) * 3)), abs=1.5)
