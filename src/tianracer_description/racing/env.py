"""Racing on the plant as a Gymnasium environment: one car on a track, a lidar, its speed and steering
and IMU observed, an action of steering and speed, rewarded for progress along the track's centre line.

Observation (a dict): "scan", the lidar's ranges (m; no return reads as its range_max) at the lidar's
own rate (the Tianracer's 40 Hz: between scans the last one stays); "speed", the forward speed (m/s);
"steering", the mean of the two steering joints' angles (rad); "imu", the IMU's angular velocity
(rad/s) and linear acceleration (m/s^2) in its frame (zeros for a car without one); with
observe_pose, "pose": x, y, yaw in the world. Action: a Box in [-1, 1]^2, steering then speed, each a
share of the car's largest (the steering at which the inside wheel reaches its limit; max_speed),
driven through the converter's Ackermann conversion into the tutorial's four controllers. Each step
holds the action for control_period seconds of simulated time. Reward: metres gained along the
centre line. Terminated when the car touches anything but the ground (a wall, a cone, another car);
truncated by the time limit (max_episode_steps, registered). reset(seed=...) seeds the env's own
generator (self.np_random), which places the start near the track's start line; options={"pose":
(x, y, yaw)} puts it there instead. The plant is deterministic: the same seed and actions give the
same observations, bit for bit.
"""
import gymnasium
import numpy as np
from gymnasium import spaces

from tianracer_description import bullet_plant
from tianracer_description.racing.car import CHASE_CAMERA, CHASE_CAMERA_SIZE, CarModel, new_world
from tianracer_description.racing.track import Centerline, centerline_file

STATE = {name: k for k, name in enumerate(bullet_plant.CarBatch.STATE)}
# Where a seeded start lands around the track's start (s = 0 on the centre line): uniform within these.
START_SPREAD = {'along': 0.2, 'offset': 0.1, 'yaw': 0.1}  # m, m, rad


class LidarDescription:
    """What the car's lidar scans: its rays, range_max, angle_min and angle_increment, from its first
    scan in an empty world made for the asking."""

    def __init__(self, model):
        scan = first_scan(model)
        self.rays, self.range_max = len(scan['ranges']), float(scan['range_max'])
        self.angle_min, self.angle_increment = float(scan['angle_min']), float(scan['angle_increment'])


def first_scan(model):
    world = new_world(None, model.controllers)
    robot = model.spawn(world, 'probe', (0.0, 0.0, 0.0))
    robot.enable_sensor(model.lidar)
    while robot.scan(model.lidar) is None:
        world.step(1)
    return robot.scan(model.lidar)


def observation_space(rays, range_max, observe_pose):
    parts = {
        'scan': spaces.Box(0.0, range_max, (rays,), np.float32),
        'speed': spaces.Box(-np.inf, np.inf, (1,), np.float32),
        'steering': spaces.Box(-np.pi, np.pi, (1,), np.float32),
        'imu': spaces.Box(-np.inf, np.inf, (6,), np.float32),
    }
    if observe_pose:
        parts['pose'] = spaces.Box(-np.inf, np.inf, (3,), np.float32)
    return spaces.Dict(parts)


def observe(scan, state, range_max, observe_pose):
    """The observation dict of one car from its row of CarBatch.step's scans and state."""
    observation = {
        'scan': np.minimum(scan, np.float32(range_max)),  # no return (inf) reads as range_max
        'speed': np.array([state[STATE['speed']]], np.float32),
        'steering': np.array([(state[STATE['steer_left']] + state[STATE['steer_right']]) / 2], np.float32),
        'imu': state[STATE['angular_velocity_x']:STATE['linear_acceleration_z'] + 1].astype(np.float32),
    }
    if observe_pose:
        observation['pose'] = np.array([state[STATE['x']], state[STATE['y']], state[STATE['yaw']]], np.float32)
    return observation


class RaceTrack:
    """A world file and its centre line, and the spawn poses around its start."""

    def __init__(self, world_file, centerline=None):
        self.world_file = world_file
        if centerline is None:
            centerline = Centerline.from_file(centerline_file(world_file))
        elif isinstance(centerline, str):
            centerline = Centerline.from_file(centerline)
        elif not isinstance(centerline, Centerline):
            centerline = Centerline(centerline)
        self.centerline = centerline

    def start_pose(self, rng):
        """A start near the start line, drawn from `rng` (a numpy Generator)."""
        s = rng.uniform(-START_SPREAD['along'], START_SPREAD['along'])
        offset = rng.uniform(-START_SPREAD['offset'], START_SPREAD['offset'])
        x, y, yaw = self.centerline.pose_at(s, offset)
        return x, y, yaw + rng.uniform(-START_SPREAD['yaw'], START_SPREAD['yaw'])


class CarRun:
    """One car on a track in a world of its own, as one slot of a CarBatch: made anew on every reset
    (a few milliseconds), so an episode depends on nothing before it. Keeps the progress."""

    def __init__(self, track, model, name='car', chase_camera=False):
        self.track, self.model, self.name, self.chase_camera = track, model, name, chase_camera
        self.world = self.robot = None
        self.s = 0.0
        self.segment = None  # of the centre line, the car's nearest
        self.laps = 0.0  # centre line lengths gained since the reset

    def reset(self, batch, index, pose):
        """A new world of the track with the car at `pose`, car `index` of `batch`."""
        self.join(new_world(self.track.world_file, self.model.controllers), batch, index, pose)

    def join(self, world, batch, index, pose):
        """The car spawned at `pose` into `world` (which other cars may share), car `index` of `batch`."""
        self.world = world
        self.robot = self.model.spawn(world, self.name, pose, self.chase_camera)
        self.model.bind(batch, index, world, self.robot)
        self.s, _, self.segment = self.track.centerline.project(pose[0], pose[1])
        self.laps = 0.0

    def advance(self, state):
        """The reward of a step (metres gained along the centre line) from the car's new state row."""
        s, _, self.segment = self.track.centerline.project(state[STATE['x']], state[STATE['y']], self.segment)
        gained = self.track.centerline.progress(self.s, s)
        self.s = s
        self.laps += gained / self.track.centerline.length
        return gained

    def info(self, state):
        return {'progress': self.s, 'laps': self.laps, 'time': self.world.time, 'crashed': bool(state[STATE['crashed']])}


def steps_per_action(control_period, time_step):
    steps = int(round(control_period / time_step))
    if steps < 1 or abs(steps * time_step - control_period) > 1e-9:
        raise ValueError('control_period %g s is not a whole number of the world\'s %g s steps'
                         % (control_period, time_step))
    return steps


class RaceEnv(gymnasium.Env):
    """One car racing on a track (see the module's text)."""

    metadata = {'render_modes': ['rgb_array'], 'render_fps': 30}

    def __init__(self, world_file, centerline=None, urdf=None, controllers=None, max_speed=2.0,
                 control_period=0.01, observe_pose=False, render_mode=None):
        if render_mode not in (None, 'rgb_array'):
            raise ValueError("render_mode is None or 'rgb_array'; got %r" % (render_mode,))
        self.track = RaceTrack(world_file, centerline)
        self.model = CarModel(urdf, controllers, max_speed)
        self.render_mode = render_mode
        self.observe_pose = observe_pose
        self.control_period = control_period
        self._run = CarRun(self.track, self.model, chase_camera=render_mode == 'rgb_array')
        self._batch = bullet_plant.CarBatch(1, 1)
        self.lidar = LidarDescription(self.model)
        self.range_max = self.lidar.range_max
        self.observation_space = observation_space(self.lidar.rays, self.range_max, observe_pose)
        self.action_space = spaces.Box(-1.0, 1.0, (2,), np.float32)
        self._steps = None
        self._state = None

    def reset(self, *, seed=None, options=None):
        super().reset(seed=seed)
        pose = (options or {}).get('pose') or self.track.start_pose(self.np_random)
        self._run.reset(self._batch, 0, tuple(float(v) for v in pose))
        self._steps = steps_per_action(self.control_period, self._run.world.time_step)
        # One step with the car held still: the first scan and the controllers' first update.
        scans, state = self._batch.step(np.array([self.model.commands((0.0, 0.0))]), 1)
        self._state = state[0]
        return observe(scans[0], state[0], self.range_max, self.observe_pose), self._run.info(state[0])

    def step(self, action):
        if self._steps is None:
            raise RuntimeError('call reset() before step()')
        scans, state = self._batch.step(np.array([self.model.commands(action)]), self._steps)
        self._state = state[0]
        reward = self._run.advance(state[0])
        terminated = bool(state[0][STATE['crashed']])
        return (observe(scans[0], state[0], self.range_max, self.observe_pose), reward, terminated, False,
                self._run.info(state[0]))

    def render(self):
        if self.render_mode != 'rgb_array' or self._run.robot is None:
            return None
        frame = self._run.robot.image(CHASE_CAMERA)
        width, height = CHASE_CAMERA_SIZE
        return np.zeros((height, width, 3), np.uint8) if frame is None else np.array(frame['rgb'])  # none yet

    def close(self):
        self._run.world = self._run.robot = None
