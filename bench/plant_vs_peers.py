"""How fast the Bullet plant steps the Tianracer next to MuJoCo and PyBullet, and how fast its lidar casts.

Measured side by side in one run on this machine (`make bench`):
  ours, per-step   the Tianracer (URDF from xacro, the YAML's pid_gains on the rear wheels, steering
                   held by a stiffness 4 / damping 1 effort law) in an empty world, Python calling
                   `world.step()` once per step
  ours, batched    the same car, one `world.step(N)` call
  ours, controllers  the full plant: the tutorial's five controllers (config/smart_control_config.yaml)
                   spawned in the plant's controller manager and commanded like cmdvel2gazebo.py does,
                   Python calling `world.step()` once per step
  mujoco           the same car in MJCF (bench/tianracer_mjcf.xml), `mujoco.mj_step` once per step
  pybullet         PyBullet's bundled racecar (racecar/racecar.urdf on plane.urdf, DIRECT mode), rear
                   wheels driven, front wheels free, steering held at 0, `stepSimulation` once per step
  lidar            two identical cars on worlds/race_track.world, one with its lidar on, stepped in
                   turns of `world.step(25)` (one lidar period: one scan per turn); the twins are
                   deterministic, so their turns differ only by the scan: a scan costs the median
                   difference, and rays/s = 1081 / that (the scan path: ray casting in C++ and filling
                   the scan, as the plant runs it; a Python loop of `world.cast_ray` would time Python)
  all sensors      the same twins with the colour camera, the depth camera and the lidar on, in turns
                   of 100 steps: their cost per simulated second is the share of one core they need at
                   real time, and rays/s = all their rays (URDF sizes and rates) / that cost
Every car drives straight at 1 m/s (rear wheel rate = 1 m/s / its wheel radius) on 1 ms steps.
The machine is shared and noisy, so every measurement is repeated over ROUNDS rounds that visit the
simulators in turn; the table gives medians over rounds, and each ratio is taken within a round, then
the median over rounds. Each car's speed over its timed windows is printed as a sanity check (a stuck
car is cheap to simulate). The figures also go to bench/out/plant_vs_peers.json.
"""
import json
import os
import platform
import statistics
import time

import mujoco
import pybullet
import pybullet_data
import yaml

from tianracer_description import bullet_plant
from tianracer_description.tianracer import (CONFIG_YAML, RACE_TRACK_WORLD, REAR_WHEEL_CONTROLLERS, REAR_WHEEL_JOINTS,
                                            STEERING_JOINTS, TUTORIAL_CONTROLLERS, tianracer_urdf)
from tianracer_description.urdf_geometry import ackermann_geometry

BENCH = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(BENCH)
MJCF = os.path.join(BENCH, 'tianracer_mjcf.xml')
OUTPUT_JSON = os.path.join(BENCH, 'out', 'plant_vs_peers.json')

SPEED = 1.0            # m/s, every car
TIME_STEP = 0.001      # s, every simulator
WARMUP_STEPS = 1000    # before the first timed window, so every car is up to speed
STEPS = 5000           # per timed window
ROUNDS = 7             # odd, so a median is one round's figure
LIDAR_PERIOD_STEPS = 25  # 40 Hz at 1 ms steps
LIDAR_TURNS = 80         # per round: 2 s of driving, within the track's first straight
# steps/s ratios, each taken within a round; the last shows what the per-step Python calls cost
RATIOS = (('ours_per_step', 'mujoco'), ('ours_per_step', 'pybullet'), ('ours_batched', 'mujoco'),
          ('ours_batched', 'pybullet'), ('ours_controllers', 'mujoco'), ('ours_controllers', 'pybullet'),
          ('ours_per_step', 'ours_batched'))


class OurCar:
    """The Tianracer in the Bullet plant, driving straight."""

    def __init__(self, urdf, world_sdf=None, controllers=False):
        self.world = bullet_plant.World.from_sdf(world_sdf) if world_sdf else bullet_plant.World()
        self.world.echo = False
        with open(CONFIG_YAML) as f:
            self.world.load_params(yaml.safe_load(f))
        self.robot = self.world.spawn(urdf, 'tianracer', pose=(0, 0, 0, 0, 0, 0))
        wheel_rate = SPEED / ackermann_geometry(urdf).wheel_radius
        if controllers:
            manager = self.robot.controller_manager
            manager.spawn(list(TUTORIAL_CONTROLLERS))
            self.world.step(2)  # the switch happens in the control loop
            for name in REAR_WHEEL_CONTROLLERS:
                manager.command(name, wheel_rate)
            return
        for joint in REAR_WHEEL_JOINTS:
            self.robot.set_command(joint, wheel_rate)
        for joint in STEERING_JOINTS:
            self.robot.set_effort_law(joint, stiffness=4.0, damping=1.0)

    def step_per_call(self, n):
        step = self.world.step
        for _ in range(n):
            step()

    def step_batched(self, n):
        self.world.step(n)

    def xy(self):
        return self.robot.base_pose()[:2]


class MujocoCar:
    """The Tianracer of bench/tianracer_mjcf.xml, driving straight."""

    def __init__(self):
        self.model = mujoco.MjModel.from_xml_path(MJCF)
        self.data = mujoco.MjData(self.model)
        wheel_body = self.model.body('left_rear_wheel').id
        wheel_radius = self.model.geom_size[self.model.geom_bodyid == wheel_body][0][0]
        for actuator in ('left_rear_wheel', 'right_rear_wheel'):
            self.data.actuator(actuator).ctrl = SPEED / wheel_radius
        for actuator in ('left_steering', 'right_steering'):
            self.data.actuator(actuator).ctrl = 0.0

    def step_per_call(self, n):
        model, data, step = self.model, self.data, mujoco.mj_step
        for _ in range(n):
            step(model, data)

    def xy(self):
        return self.data.body('base_link').xpos[:2].copy()


class PybulletRacecar:
    """PyBullet's bundled racecar, driving straight on its rear wheels."""

    def __init__(self):
        self.client = pybullet.connect(pybullet.DIRECT)
        data = pybullet_data.getDataPath()
        pybullet.setGravity(0, 0, -9.8, physicsClientId=self.client)
        pybullet.setTimeStep(TIME_STEP, physicsClientId=self.client)
        pybullet.loadURDF(os.path.join(data, 'plane.urdf'), physicsClientId=self.client)
        self.car = pybullet.loadURDF(os.path.join(data, 'racecar', 'racecar.urdf'), physicsClientId=self.client)
        joints = {}  # name -> (index, the URDF's effort limit)
        for index in range(pybullet.getNumJoints(self.car, physicsClientId=self.client)):
            info = pybullet.getJointInfo(self.car, index, physicsClientId=self.client)
            joints[info[1].decode()] = (index, info[10])
        # The wheels are meshes: their radius is half the height of a wheel's bounding box.
        aabb_min, aabb_max = pybullet.getAABB(self.car, joints['left_rear_wheel_joint'][0],
                                              physicsClientId=self.client)
        wheel_rate = SPEED / ((aabb_max[2] - aabb_min[2]) / 2)
        for name, (index, max_force) in joints.items():
            if 'wheel' in name:
                driven = 'rear' in name  # as ours; force 0 frees the front wheels of PyBullet's default motor
                pybullet.setJointMotorControl2(self.car, index, pybullet.VELOCITY_CONTROL,
                                               targetVelocity=wheel_rate if driven else 0.0,
                                               force=max_force if driven else 0.0, physicsClientId=self.client)
            elif 'steering' in name:
                pybullet.setJointMotorControl2(self.car, index, pybullet.POSITION_CONTROL, targetPosition=0.0,
                                               force=max_force, physicsClientId=self.client)

    def step_per_call(self, n):
        step, client = pybullet.stepSimulation, self.client
        for _ in range(n):
            step(physicsClientId=client)

    def xy(self):
        return pybullet.getBasePositionAndOrientation(self.car, physicsClientId=self.client)[0][:2]


def distance(a, b):
    return ((b[0] - a[0]) ** 2 + (b[1] - a[1]) ** 2) ** 0.5


def timed_window(car, step):
    """Steps/s of `step(STEPS)`, and the car's speed over the window (m per s of simulated time)."""
    start_xy = car.xy()
    start = time.perf_counter()
    step(STEPS)
    elapsed = time.perf_counter() - start
    return STEPS / elapsed, distance(start_xy, car.xy()) / (STEPS * TIME_STEP)


def lidar_round(scanning, silent):
    """Both track cars from the spawn pose, stepped in alternating turns of one lidar period.
    Returns the wall time of a scan (median over turns of scanning - silent), the scans made, the
    metres driven and whether the twins still agree."""
    for car in (scanning, silent):
        car.world.reset_world()
    scans_before = scanning.robot.sensor_updates('lidar')
    start_xy = scanning.xy()
    scan_times = []
    for turn in range(LIDAR_TURNS):
        turn_time = {}
        for car in ((scanning, silent) if turn % 2 == 0 else (silent, scanning)):
            start = time.perf_counter()
            car.world.step(LIDAR_PERIOD_STEPS)
            turn_time[car] = time.perf_counter() - start
        scan_times.append(turn_time[scanning] - turn_time[silent])
    twins_agree = bool((scanning.robot.base_pose() == silent.robot.base_pose()).all())
    return (statistics.median(scan_times), scanning.robot.sensor_updates('lidar') - scans_before,
            distance(start_xy, scanning.xy()), twins_agree)


SENSOR_TURNS, SENSOR_STEPS = 20, 100   # 2 s of driving per round


def sensors_round(sensing, silent):
    """Both track cars from the spawn pose, in alternating turns; the sensing car's extra wall time
    per simulated second (= the share of one core its sensors take at real time)."""
    for car in (sensing, silent):
        car.world.reset_world()
    extra = 0.0
    for turn in range(SENSOR_TURNS):
        turn_time = {}
        for car in ((sensing, silent) if turn % 2 == 0 else (silent, sensing)):
            start = time.perf_counter()
            car.world.step(SENSOR_STEPS)
            turn_time[car] = time.perf_counter() - start
        extra += turn_time[sensing] - turn_time[silent]
    return extra / (SENSOR_TURNS * SENSOR_STEPS * TIME_STEP)


def sensor_rays_per_sim_second(urdf):
    """Rays all sensors of the URDF cast per simulated second, at their sizes and rates."""
    import xml.etree.ElementTree as ET
    rays = 0.0
    for sensor in ET.fromstring(urdf).iter('sensor'):
        rate = float(sensor.findtext('update_rate'))
        if sensor.get('type') == 'ray':
            rays += rate * int(sensor.findtext('ray/scan/horizontal/samples'))
        else:
            rays += rate * int(sensor.findtext('camera/image/width')) * int(sensor.findtext('camera/image/height'))
    return rays


def main():
    urdf = tianracer_urdf()
    with open(RACE_TRACK_WORLD) as f:
        track_sdf = f.read()
    # Each sensing car has a silent twin of its own: twins stepped alike stay bit-identical, while a
    # car that also drove other rounds carries Bullet's broadphase order from them past reset_world.
    scanning_car, silent_car = OurCar(urdf, track_sdf), OurCar(urdf, track_sdf)
    scanning_car.robot.enable_sensor('lidar', True)
    sensing_car, sensing_twin = OurCar(urdf, track_sdf), OurCar(urdf, track_sdf)
    for sensor in sensing_car.robot.sensors:
        sensing_car.robot.enable_sensor(sensor, True)
    ours_per_step, ours_batched, ours_controllers = OurCar(urdf), OurCar(urdf), OurCar(urdf, controllers=True)
    mujoco_car, pybullet_car = MujocoCar(), PybulletRacecar()
    measurements = {  # name -> (car, how it is stepped)
        'ours_per_step': (ours_per_step, ours_per_step.step_per_call),
        'ours_batched': (ours_batched, ours_batched.step_batched),
        'ours_controllers': (ours_controllers, ours_controllers.step_per_call),
        'mujoco': (mujoco_car, mujoco_car.step_per_call),
        'pybullet': (pybullet_car, pybullet_car.step_per_call),
    }
    for car, step in measurements.values():
        step(WARMUP_STEPS)

    steps_per_s = {name: [] for name in measurements}
    speeds = {name: [] for name in measurements}
    scan_times, scans_made, lidar_metres, twins_agreed = [], [], [], []
    sensor_shares = []
    for _ in range(ROUNDS):
        for name, (car, step) in measurements.items():
            rate, speed = timed_window(car, step)
            steps_per_s[name].append(rate)
            speeds[name].append(speed)
        scan_time, scans, metres, twins_agree = lidar_round(scanning_car, silent_car)
        scan_times.append(scan_time)
        scans_made.append(scans)
        lidar_metres.append(metres)
        twins_agreed.append(twins_agree)
        sensor_shares.append(sensors_round(sensing_car, sensing_twin))
    sensor_share = statistics.median(sensor_shares)
    sensor_rays = sensor_rays_per_sim_second(urdf)
    rays_per_scan = len(scanning_car.robot.scan('lidar')['ranges'])

    medians = {name: statistics.median(rates) for name, rates in steps_per_s.items()}
    ratios = {'%s / %s' % (a, b): statistics.median(x / y for x, y in zip(steps_per_s[a], steps_per_s[b]))
              for a, b in RATIOS}
    # rays/s falls as the scan time rises, so with an odd number of rounds the median of the rounds'
    # rays/s is rays_per_scan / the median scan time (and a round whose noise gave a scan time <= 0
    # counts as fastest instead of failing).
    median_scan_time = statistics.median(scan_times)
    lidar_rays_per_s = rays_per_scan / median_scan_time if median_scan_time > 0 else float('inf')

    print('Benchmark: %d rounds of %d steps (1 ms) per simulator after %d warm-up steps; %s, %d cores; '
          'mujoco %s, pybullet API %d' % (ROUNDS, STEPS, WARMUP_STEPS, platform.python_version(), os.cpu_count(),
                                          mujoco.__version__, pybullet.getAPIVersion()))
    print()
    print('%-15s %14s %22s %10s %18s' % ('simulator', 'median steps/s', 'min .. max steps/s', 'x realtime',
                                          'speed m/s (sanity)'))
    for name, rates in steps_per_s.items():
        print('%-15s %14.0f %10.0f .. %-9.0f %10.1f %9.3f .. %.3f' % (
            name, medians[name], min(rates), max(rates), medians[name] * TIME_STEP, min(speeds[name]),
            max(speeds[name])))
    print()
    print('ratios (per round, median over rounds):')
    for name, ratio in ratios.items():
        print('  %-30s %6.3f' % (name, ratio))
    print()
    print('lidar on the race track: %.2f M rays/s median (%d rays per scan, %.1f us per scan; min .. max '
          '%.1f .. %.1f us)' % (lidar_rays_per_s / 1e6, rays_per_scan, median_scan_time * 1e6,
                                min(scan_times) * 1e6, max(scan_times) * 1e6))
    print('  sanity: %d .. %d scans per round (expected %d), car drove %.2f .. %.2f m per round, '
          'twin cars in the same pose after every round: %s' % (
              min(scans_made), max(scans_made), LIDAR_TURNS, min(lidar_metres), max(lidar_metres),
              'yes' if all(twins_agreed) else 'NO (the scan times compare different physics)'))

    print('all sensors (%s) at the URDF sizes and rates: %.1f %% of one core at real time (median; min .. max '
          '%.1f .. %.1f %%), %.2f M rays/s' % (', '.join(sensing_car.robot.sensors), 100 * sensor_share,
                                               100 * min(sensor_shares), 100 * max(sensor_shares),
                                               sensor_rays / sensor_share / 1e6 if sensor_share > 0 else float('inf')))

    os.makedirs(os.path.dirname(OUTPUT_JSON), exist_ok=True)
    with open(OUTPUT_JSON, 'w') as f:
        json.dump({
            'settings': {'rounds': ROUNDS, 'steps_per_window': STEPS, 'warmup_steps': WARMUP_STEPS,
                         'time_step_s': TIME_STEP, 'speed_m_per_s': SPEED, 'python': platform.python_version(),
                         'cpu_count': os.cpu_count(), 'mujoco': mujoco.__version__,
                         'pybullet_api': pybullet.getAPIVersion()},
            'median_steps_per_s': medians,
            'steps_per_s': steps_per_s,
            'speed_m_per_s': speeds,
            'ratios': ratios,
            'lidar': {'median_rays_per_s': lidar_rays_per_s, 'rays_per_scan': rays_per_scan,
                      'median_scan_time_s': median_scan_time, 'scan_time_s': scan_times,
                      'scans_per_round': scans_made, 'metres_per_round': lidar_metres,
                      'twins_agreed': twins_agreed},
            'all_sensors': {'median_share_of_a_core': sensor_share, 'share_of_a_core': sensor_shares,
                            'rays_per_sim_second': sensor_rays},
        }, f, indent=2)
    print('\nwrote %s' % os.path.relpath(OUTPUT_JSON, REPO))


if __name__ == '__main__':
    main()
