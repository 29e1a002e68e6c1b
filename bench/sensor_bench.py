"""The sensors' cost (`make bench`, after the plant against its peers).

1. The real Tianracer's sensors rendered from the car on worlds/race_track.world and on a race track
   made of meshes (the same walls as one OBJ, a textured OBJ floor): the 1081-ray lidar's rays per
   second through Embree with one thread and with all, per CPU second (what one core does) and per
   wall second; an 800 x 800 colour camera (80 degrees) and a 640 x 480 depth camera (60 degrees,
   0.3 to 8 m) through OpenGL on llvmpipe, pixels per CPU second without noise and with the URDF's,
   with the sun's shadows and without,
   at llvmpipe's 256-bit width (what AVX2 and AVX-512 CPUs run) and its 128-bit one (SSE CPUs),
   medians of ISA_RUNS, with a frame's CPU and the cores it takes at the real car's rate. The
   subject is bench/sensor_cost.cpp (built by `make build`). The ray caster Embree replaced is gone
   from bench/; its figures, measured beside Embree's, are data (bench/data/previous_ray_caster.csv),
   printed after the tables.
2. The real car's sensor set at its rates (800 x 800 colour at 30 Hz, 640 x 480 depth at 20 Hz, the
   1081-ray lidar at 40 Hz, the 100 Hz IMU, all subscribed) on the mesh race track while the car drives: simulated
   seconds per wall second unpaced (the real time factor the node can hold is the smaller of that and
   1) and process CPU seconds per simulated second (at real time: the cores' worth of CPU it takes);
   then the same through the ROS node, paced at real time, with every sensor topic subscribed; with
   the sun's shadows (Gazebo's default) and without.
   `bench/sensor_bench.py --real-car` runs only this part.
3. The lidar's rays per CPU second of one thread on each instruction set of Embree's kernels this CPU runs
   (TIANRACER_EMBREE_ISA: SSE 4-wide, AVX 8-wide, AVX-512 16-wide), on the mesh race track, side by
   side, medians of ISA_RUNS runs taken in turn: Embree runs the widest by default, so the figures
   above are those of the widest ISA, and a user's CPU may have a narrower one.
"""
import csv
import math
import os
import subprocess
import sys
import tempfile
import time
import xml.etree.ElementTree as ET

import matplotlib
matplotlib.use('Agg')
import matplotlib.image  # noqa: E402 (after choosing the backend)
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), os.pardir, 'test', 'helpers'))
from mesh_cost import write_obj  # noqa: E402  (beside this file)
from ros_harness import RosSystem, tianracer_plant  # noqa: E402  (the test harness)
from ros_plant_bench import plant_pid  # noqa: E402
from tianracer_description import bullet_plant  # noqa: E402
from tianracer_description.tianracer import (CONFIG_YAML, MODEL_XACRO, RACE_TRACK_WORLD,  # noqa: E402
                                             REAR_WHEEL_CONTROLLERS, TUTORIAL_CONTROLLERS, run_xacro)

FRAMES = 10
SIM_SECONDS = 10.0
SPEED = 0.25  # m/s: the car stays on the start straight for the whole run
WHEEL_RADIUS = 0.032
REAL_CAR = {'camera': (800, 800, 30.0), 'depth': (640, 480, 20.0)}  # width, height, Hz
FLOOR_TOP = 0.002  # above the ground plane the world gets anyway
NODE_WINDOW = 20.0  # s of wall time
ISA_RUNS = 3

# Subscribes to every sensor topic of the car (a Python subscriber, as rviz or a user's node would;
# spawned as the tutorial spawns it, no robotNamespace, so the plugins' topics are at the root),
# waits until the sensors run, then measures over NODE_WINDOW s: simulated / wall time, the plant
# process's CPU time (from /proc) per simulated second and the rates received.
NODE_PROBE = """
import json, os, time, rospy
from rosgraph_msgs.msg import Clock
from sensor_msgs.msg import Image, Imu, LaserScan, PointCloud2
def cpu():
    with open('/proc/{pid}/stat') as f:
        fields = f.read().rsplit(')', 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf('SC_CLK_TCK')
rospy.init_node('sensor_probe', anonymous=True)
clock = []
rospy.Subscriber('/clock', Clock, lambda m: clock.append(m.clock.to_sec()))
topics = {{'/camera/image_raw': Image, '/depth_camera/depth/image_raw': Image, '/depth_camera/rgb/image_raw': Image,
          '/depth_camera/depth/points': PointCloud2, '/scan': LaserScan, '/imu': Imu}}
counts = dict.fromkeys(topics, 0)
def counter(topic):
    def count(message):
        counts[topic] += 1
    return count
for topic, kind in topics.items():
    rospy.Subscriber(topic, kind, counter(topic), queue_size=2, buff_size=2 ** 25)
time.sleep(5.0)
wall0, sim0, cpu0, counts0 = time.monotonic(), clock[-1], cpu(), dict(counts)
time.sleep({window})
wall, sim, used = time.monotonic() - wall0, clock[-1] - sim0, cpu() - cpu0
print(json.dumps(dict(rtf=sim / wall, cpu_per_sim_s=used / sim,
                      rates={{t: (counts[t] - counts0[t]) / sim for t in topics}})))
"""


def binary():
    devel = os.environ.get('CATKIN_DEVEL_PREFIX') or next(
        p for p in os.environ.get('CMAKE_PREFIX_PATH', '').split(':') if p.endswith('devel'))
    return os.path.join(devel, 'lib', 'tianracer_description', 'sensor_cost')


def real_car_urdf():
    """The car's URDF with its IMU and its cameras at the real car's sizes and rates (the lidar already is)."""
    root = ET.fromstring(run_xacro(MODEL_XACRO, 'imu:=true').stdout)
    for sensor in root.iter('sensor'):
        if sensor.get('type') in REAL_CAR:
            width, height, rate = REAL_CAR[sensor.get('type')]
            sensor.find('update_rate').text = str(rate)
            sensor.find('camera/image/width').text = str(width)
            sensor.find('camera/image/height').text = str(height)
    return ET.tostring(root, encoding='unicode')


def track_boxes():
    """The walls of worlds/race_track.world: (centre, size, yaw) of each box."""
    boxes = []
    for model in ET.parse(RACE_TRACK_WORLD).getroot().iter('model'):
        size = model.findtext('link/collision/geometry/box/size')
        if size:
            x, y, z, _, _, yaw = map(float, model.findtext('pose').split())
            boxes.append(((x, y, z), tuple(map(float, size.split())), yaw))
    return boxes


def write_floor(directory, lo, hi, n=16):
    """A textured floor OBJ over [lo, hi] (x, y) at FLOOR_TOP: an asphalt-grey checker of 0.5 m
    squares (a 64 x 64 PNG repeated every metre) with a white line every metre."""
    texture = np.full((64, 64, 3), 0.35)
    texture[:32, :32] = texture[32:, 32:] = 0.28
    texture[:2, :] = texture[:, :2] = 0.9
    matplotlib.image.imsave(os.path.join(directory, 'asphalt.png'), texture)
    with open(os.path.join(directory, 'floor.mtl'), 'w') as f:
        f.write('newmtl asphalt\nKd 1 1 1\nmap_Kd asphalt.png\n')
    lines = ['mtllib floor.mtl', 'usemtl asphalt']
    for i in range(n + 1):
        for j in range(n + 1):
            x, y = lo[0] + (hi[0] - lo[0]) * i / n, lo[1] + (hi[1] - lo[1]) * j / n
            lines += ['v %f %f %f' % (x, y, FLOOR_TOP), 'vt %f %f' % (x, y)]
    for i in range(n):
        for j in range(n):
            a = i * (n + 1) + j + 1
            b, c, d = a + n + 1, a + n + 2, a + 1
            lines += ['f %d/%d %d/%d %d/%d' % (a, a, b, b, c, c), 'f %d/%d %d/%d %d/%d' % (a, a, c, c, d, d)]
    with open(os.path.join(directory, 'floor.obj'), 'w') as f:
        f.write('\n'.join(lines) + '\n')


def mesh_model(name, mesh, colour=None):
    material = '<material><diffuse>%s</diffuse></material>' % colour if colour else ''
    return f"""<model name="{name}"><static>true</static><link name="link">
      <collision name="collision"><geometry><mesh><uri>{mesh}</uri></mesh></geometry></collision>
      <visual name="visual"><geometry><mesh><uri>{mesh}</uri></mesh></geometry>{material}</visual>
    </link></model>"""


def write_mesh_track(directory):
    """The race track's walls as one OBJ and a textured floor OBJ, in a world file."""
    boxes = track_boxes()
    write_obj(os.path.join(directory, 'walls.obj'), boxes)
    xs = [c[0] for c, _, _ in boxes]
    ys = [c[1] for c, _, _ in boxes]
    write_floor(directory, (min(xs) - 1, min(ys) - 1), (max(xs) + 1, max(ys) + 1))
    world = os.path.join(directory, 'mesh_race_track.world')
    with open(world, 'w') as f:
        f.write(f"""<?xml version="1.0"?>
<sdf version="1.6"><world name="mesh_race_track">
  <include><uri>model://ground_plane</uri></include>
  <include><uri>model://sun</uri></include>
  <scene><ambient>0.4 0.4 0.4 1</ambient><background>0.7 0.7 0.7 1</background></scene>
  {mesh_model('floor', 'floor.obj')}
  {mesh_model('walls', 'walls.obj', '0.8 0.1 0.1 1')}
</world></sdf>""")
    return world, len(boxes)


def rays_per_second(urdf_file, world, env=None, one_thread=False):
    """(isa, {(sensor, threads): (rays per CPU second, rays per wall second)}) of one sensor_cost run:
    the lidar's rays by Embree threads, the cameras' pixels under (camera, 0) and (depth, 0) (0: the
    GL renderer's own threads), and the GL renderer under 'gl'."""
    out = subprocess.run([binary(), urdf_file, world, str(FRAMES)] + (['--one-thread'] if one_thread else []),
                         capture_output=True, text=True, check=True, env=env).stdout.split('\n')
    isa = out[0].split()[1]
    rates = {}
    for line in out[1:]:
        words = line.split()
        if words and words[0] == 'gl':
            rates['gl'] = line.split(' ', 1)[1]
        elif len(words) == 4:
            rates[(words[0], int(words[1]))] = (float(words[2]), float(words[3]))
    return isa, rates


def print_rates(title, rates):
    threads = max(key[1] for key in rates if isinstance(key, tuple))
    print(title)
    print('  %-26s %16s %17s   (M rays per CPU second / per wall second)'
          % ('', 'Embree, 1 thread', 'Embree, %d threads' % threads))
    cells = ['%6.1f / %5.1f' % (rates[('lidar', t)][0] / 1e6, rates[('lidar', t)][1] / 1e6) for t in (1, threads)]
    print('  %-26s %16s %17s' % ('lidar 1081 rays', cells[0], cells[1]))


def camera_costs(urdf_file, world, width):
    """{(camera, noisy): M pixels per CPU second}, medians of ISA_RUNS sensor_cost runs, the cameras
    rendered by llvmpipe at `width` bits (LP_NATIVE_VECTOR_WIDTH: 256 on AVX2 and AVX-512 CPUs, 128 on
    SSE ones), without noise and with the URDF's (the colour camera's), and the renderer's name."""
    samples, renderer = {}, '?'
    for _ in range(ISA_RUNS):
        for noisy in (False, True):
            env = dict(os.environ, LP_NATIVE_VECTOR_WIDTH=str(width), TIANRACER_GL_DEVICE='cpu')
            if noisy:
                env['SENSOR_COST_NOISE'] = '1'
            _, rates = rays_per_second(urdf_file, world, env=env, one_thread=True)
            renderer = rates['gl']
            for camera in ('camera', 'depth'):
                samples.setdefault((camera, noisy), []).append(rates[(camera, 0)][0])
    return {key: float(np.median(values)) for key, values in samples.items()}, renderer


def without_shadows(world_file, directory):
    """A copy of the world file in `directory` with <scene><shadows>false</shadows>."""
    tree = ET.parse(world_file)
    world = tree.getroot().find('world')
    scene = world.find('scene') if world.find('scene') is not None else ET.SubElement(world, 'scene')
    shadows = scene.find('shadows') if scene.find('shadows') is not None else ET.SubElement(scene, 'shadows')
    shadows.text = 'false'
    path = os.path.join(directory, 'without_shadows_' + os.path.basename(world_file))
    tree.write(path)
    return path


def print_camera_costs(world_name, urdf_file, world, directory):
    """The cameras' costs with the sun's shadows (Gazebo's default; the car stands, so its shadow map
    is drawn once) and without, at llvmpipe's two widths."""
    for shadows, world_file in ((True, world), (False, without_shadows(world, directory))):
        for width in (256, 128):
            print_camera_cost_table(world_name + (', shadows' if shadows else ', no shadows'), urdf_file, world_file,
                                    width)


def print_camera_cost_table(world_name, urdf_file, world, width):
    costs, renderer = camera_costs(urdf_file, world, width)
    print('the cameras with OpenGL on %s, %s, median of %d: M pixels per CPU second, a frame\'s CPU and the'
          ' cores at the real car\'s rate' % (world_name, renderer, ISA_RUNS))
    for camera, label, pixels, rate in (('camera', 'colour 800 x 800', 800 * 800, 30),
                                        ('depth', 'depth 640 x 480', 640 * 480, 20)):
        for noisy in (False, True):
            cpu = costs[(camera, noisy)]
            print('  %-16s %-13s %6.1f   %5.2f ms a frame: %.3f of a core at %d Hz'
                  % (label, 'with noise' if noisy else 'without noise', cpu / 1e6, 1e3 * pixels / cpu,
                     rate * pixels / cpu, rate))


def print_previous_ray_caster():
    """The figures of the ray caster Embree replaced, as recorded beside Embree's (bench/data)."""
    path = os.path.join(os.path.dirname(os.path.abspath(__file__)), 'data', 'previous_ray_caster.csv')
    with open(path) as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith('#')))
    print('the previous ray caster (one ray at a time; removed), as recorded beside Embree on one thread '
          '(bench/data/previous_ray_caster.csv; M rays per CPU second):')
    for row in rows:
        agree = ', images agree within 2/255: %.1f %%' % (100 * float(row['images_agree'])) if row['images_agree'] else ''
        print('  %-13s %-17s %-17s previous %5.1f, Embree %5.1f (x %.1f)%s' % (
            row['machine'], row['world'], row['sensor'], float(row['previous_m_rays_per_cpu_s']),
            float(row['embree_m_rays_per_cpu_s']),
            float(row['embree_m_rays_per_cpu_s']) / float(row['previous_m_rays_per_cpu_s']), agree))


def rays_per_cpu_second_by_isa(urdf_file, world):
    """{isa: the lidar's rays per CPU second of one thread}, medians of ISA_RUNS runs of every ISA in turn."""
    isas = bullet_plant.embree_isas()
    samples = {isa: [] for isa in isas}
    for _ in range(ISA_RUNS):
        for isa in isas:
            ran, rates = rays_per_second(urdf_file, world, env=dict(os.environ, TIANRACER_EMBREE_ISA=isa),
                                         one_thread=True)
            assert ran == isa, 'sensor_cost ran %s, not %s' % (ran, isa)
            samples[isa].append(rates[('lidar', 1)][0])
    return {isa: float(np.median(rates)) for isa, rates in samples.items()}


def print_rates_by_isa(title, rates):
    isas = list(rates)
    print(title)
    print('  %-26s' % 'M rays per CPU second' + ''.join('%9s' % isa for isa in isas))
    print('  %-26s' % 'lidar 1081 rays' + ''.join('%9.1f' % (rates[isa] / 1e6) for isa in isas))


def cpu_name():
    with open('/proc/cpuinfo') as f:
        return next((line.split(':', 1)[1].strip() for line in f if line.startswith('model name')), '?')


def real_car_run(world_file, urdf, what):
    world = bullet_plant.World.from_file(world_file)
    world.load_params(CONFIG_YAML)
    car = world.spawn(urdf, 'tianracer', pose=(0, 0, 0.05, 0, 0, 0))
    cm = car.controller_manager
    cm.spawn(list(TUTORIAL_CONTROLLERS))
    for controller in REAR_WHEEL_CONTROLLERS:
        cm.command(controller, SPEED / WHEEL_RADIUS)
    world.step(500)
    sensors = list(car.sensors)
    steps = int(round(SIM_SECONDS / world.time_step))

    def timed(enabled):
        for sensor in sensors:
            car.enable_sensor(sensor, enabled)
        updates = {s: car.sensor_updates(s) for s in sensors}
        wall, cpu = time.perf_counter(), time.process_time()
        world.step(steps)
        wall, cpu = time.perf_counter() - wall, time.process_time() - cpu
        return wall, cpu, {s: car.sensor_updates(s) - updates[s] for s in sensors}

    bare = timed(False)
    wall, cpu, updates = timed(True)
    sim = steps * world.time_step
    print('the real car\'s sensors on the mesh race track (%s), all subscribed, driving at %.2f m/s, %.0f s simulated:'
          % (what, SPEED, sim))
    print('  ' + ', '.join('%s %.0f Hz' % (s, updates[s] / sim) for s in sensors))
    print('  simulated seconds per wall second (unpaced): %.2f -> real time factor held: %.2f '
          '(load average %.1f on %d cores: other jobs take their share)'
          % (sim / wall, min(1.0, sim / wall), os.getloadavg()[0], os.cpu_count()))
    print('  process CPU time / simulated time: %.2f (cores busy at real time; %.2f of it without sensors)'
          % (cpu / sim, bare[1] / sim))
    return {'speed': sim / wall, 'cpu_per_sim_second': cpu / sim, 'bare_cpu_per_sim_second': bare[1] / sim}


def node_run(world_file, urdf_file):
    """The same sensor set through the ROS node, paced at real time, every topic subscribed."""
    with tempfile.TemporaryDirectory() as workdir:
        ros = RosSystem(workdir)
        try:
            plant = tianracer_plant(ros, urdf_file, world=world_file)
            result = ros.python(NODE_PROBE.format(pid=plant_pid(plant.pid), window=NODE_WINDOW),
                                timeout=NODE_WINDOW + 60)
        finally:
            ros.close()
    print('the same through the ROS node (bullet_plant), paced, each topic subscribed by a Python node, %.0f s:'
          % NODE_WINDOW)
    print('  real time factor %.3f, plant process CPU time / simulated time %.2f (load average %.1f)'
          % (result['rtf'], result['cpu_per_sim_s'], os.getloadavg()[0]))
    print('  received per simulated second: ' + ', '.join('%s %.1f' % (topic.lstrip('/'), rate)
                                                         for topic, rate in result['rates'].items()))
    return result


def main():
    urdf = real_car_urdf()
    with tempfile.TemporaryDirectory() as directory:
        urdf_file = os.path.join(directory, 'tianracer.urdf')
        with open(urdf_file, 'w') as f:
            f.write(urdf)
        mesh_world, walls = write_mesh_track(directory)
        isa = bullet_plant.embree_isa()['name']
        print('CPU: %s, %d cores; the instruction sets of Embree\'s kernels it runs: %s; the plant uses %s'
              % (cpu_name(), os.cpu_count(), ', '.join(bullet_plant.embree_isas()), isa))
        if sys.argv[1:] != ['--real-car']:
            print_rates('lidar rays on worlds/race_track.world (boxes and a plane), Embree on %s:' % isa,
                        rays_per_second(urdf_file, RACE_TRACK_WORLD)[1])
            print_rates('lidar rays on the mesh race track (%d walls as %d triangles, a textured floor), Embree on %s:'
                        % (walls, 12 * walls, isa), rays_per_second(urdf_file, mesh_world)[1])
            print_camera_costs('worlds/race_track.world', urdf_file, RACE_TRACK_WORLD, directory)
            print_camera_costs('the mesh race track', urdf_file, mesh_world, directory)
            print_previous_ray_caster()
        # with the sun's shadows (Gazebo's default) and without (<scene><shadows>false)
        for world, what in ((mesh_world, 'shadows'), (without_shadows(mesh_world, directory), 'no shadows')):
            real_car_run(world, urdf, what)
            node_run(world, urdf_file)
        if sys.argv[1:] != ['--real-car']:
            print_rates_by_isa('lidar rays on the mesh race track by ISA of Embree\'s kernels, one thread, median of %d:'
                               % ISA_RUNS, rays_per_cpu_second_by_isa(urdf_file, mesh_world))


if __name__ == '__main__':
    sys.exit(main())
