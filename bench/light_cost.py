"""Instructions a 640 x 480 camera frame costs on llvmpipe, by its lights: a furnished room lit by six
lamps as AWS RoboMaker's bookstore lights (no sun; ambient 0.4; diffuse 0.5, range 20, attenuation
0.32, 0.01, 0.03), and the race track under Gazebo's sun with its shadows. Counted under callgrind
inside GlRenderer::render (llvmpipe's rasterizer on the calling thread, LP_NUM_THREADS=0; Mesa's
shader cache off so every run compiles alike): the difference between a run of 6 frames and one of 1,
over the render calls between them, so what a world costs to load or a shader to compile is left
out. Instructions do not depend on the machine's load, where times on a shared VM do (and this VM
has no hardware counters for perf stat). Run: python3 bench/light_cost.py [room|track ...]."""
import os
import re
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET


def box(name, x, y, z, sx, sy, sz, rgb):
    return f"""<model name="{name}"><static>true</static><pose>{x} {y} {z} 0 0 0</pose><link name="l">
<visual name="v"><geometry><box><size>{sx} {sy} {sz}</size></box></geometry>
<material><ambient>{rgb} 1</ambient><diffuse>{rgb} 1</diffuse><specular>0.2 0.2 0.2 1</specular></material></visual></link></model>"""


def camera(x, y, z, yaw):
    return f"""<model name="eye"><static>true</static><pose>{x} {y} {z} 0 0.2 {yaw}</pose><link name="link">
<sensor name="camera" type="camera"><update_rate>10</update_rate><camera><horizontal_fov>1.3</horizontal_fov>
<image><width>640</width><height>480</height></image><clip><near>0.05</near><far>50</far></clip></camera></sensor></link></model>"""


def room_world():
    things = [box('floor', 0, 0, -0.05, 20, 16, 0.1, '0.6 0.55 0.5')]
    for k, (x, y, sx, sy) in enumerate([(0, 8, 20, 0.2), (0, -8, 20, 0.2), (10, 0, 0.2, 16), (-10, 0, 0.2, 16)]):
        things.append(box('wall%d' % k, x, y, 1.5, sx, sy, 3, '0.8 0.8 0.75'))
    k = 0
    for i in range(-4, 5):
        for j in range(-3, 4):
            k += 1
            things.append(box('shelf%d' % k, 2.0 * i, 2.0 * j, 0.6, 0.8, 0.4, 1.2,
                              '%.2f %.2f %.2f' % (0.3 + 0.05 * (i % 5), 0.4, 0.5 - 0.05 * (j % 4))))
    lamps = ''.join(f"""<light name="lamp{n}" type="point"><pose>{x} {y} 2.8 0 0 0</pose><diffuse>0.5 0.5 0.5 1</diffuse>
<specular>0.1 0.1 0.1 1</specular><attenuation><range>20</range><constant>0.32</constant><linear>0.01</linear>
<quadratic>0.03</quadratic></attenuation></light>""" for n, (x, y) in enumerate([(-6, -4), (0, -4), (6, -4), (-6, 4), (0, 4), (6, 4)]))
    return f"""<sdf version="1.6"><world name="room"><scene><ambient>0.4 0.4 0.4 1</ambient><shadows>false</shadows></scene>
{lamps}{''.join(things)}{camera(-9, -7, 1.5, 0.6)}</world></sdf>"""


def child(scene, frames):
    """Renders `frames` frames of the scene's camera (in a process of its own, under callgrind)."""
    from tianracer_description import bullet_plant
    if scene == 'room':
        world = bullet_plant.World.from_sdf(room_world())
    else:
        from tianracer_description.tianracer import RACE_TRACK_WORLD
        tree = ET.parse(RACE_TRACK_WORLD)
        tree.getroot().find('world').append(ET.fromstring(camera(0, 0, 0.3, 0)))
        path = os.path.join(tempfile.mkdtemp(), 'track.world')
        tree.write(path)
        world = bullet_plant.World.from_file(path)
    world.echo = False
    eye = world.robot('eye')
    eye.enable_sensor('camera')
    world.step(100 * frames)


def counted(scene, frames):
    """(instructions inside GlRenderer::render, its calls) of a run of `frames` frames."""
    out = os.path.join(tempfile.mkdtemp(), 'callgrind.out')
    env = dict(os.environ, MESA_SHADER_CACHE_DISABLE='true', LP_NUM_THREADS='0')
    run = subprocess.run(['valgrind', '--tool=callgrind', '--smc-check=all',
                          '--toggle-collect=bullet_plant::GlRenderer::render*', '--callgrind-out-file=' + out,
                          sys.executable, __file__, '--child', scene, str(frames)],
                         capture_output=True, text=True, env=env, check=True)
    total = int(re.search(r'Collected : (\d+)', run.stderr).group(1))
    tree = subprocess.run(['callgrind_annotate', '--inclusive=yes', '--tree=caller', out], capture_output=True,
                          text=True, check=True).stdout
    calls = int(re.search(r'< \S*bullet_plant::GlScene::render\(.*?\((\d+)x\)', tree).group(1))
    return total, calls


def main(scenes):
    for scene in scenes:
        (one, one_calls), (six, six_calls) = counted(scene, 1), counted(scene, 6)
        print('%s: %.1f M instructions a frame (%d frames against %d)' % (
            scene, (six - one) / (six_calls - one_calls) / 1e6, six_calls, one_calls), flush=True)


if __name__ == '__main__':
    if sys.argv[1:2] == ['--child']:
        child(sys.argv[2], int(sys.argv[3]))
    else:
        main(sys.argv[1:] or ['room', 'track'])
