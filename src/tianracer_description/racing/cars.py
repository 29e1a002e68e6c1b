"""What the three environments share: N cars on a track as one bullet_plant.CarBatch, and everything
about them as arrays, one row per car: their commands from actions, their observations, their progress
along the centre line (the reward) and their ends. RaceEnv is one car, RaceVectorEnv N cars in N
worlds, RaceParallelEnv N cars in one world.

Observation (a dict): "scan", the lidar's ranges (m; no return reads as its range_max) at the lidar's
own rate (the Tianracer's 40 Hz: between scans the last one stays); "speed", the forward speed (m/s);
"steering", the mean of the two steering joints' angles (rad); "imu", the IMU's angular velocity
(rad/s) and linear acceleration (m/s^2) in its frame (zeros for a car without one); with
observe_pose, "pose": x, y, yaw in the world.
"""
import numpy as np
from gymnasium import spaces

from tianracer_description import bullet_plant
from tianracer_description.racing.car import CarModel, new_world
from tianracer_description.racing.f1tenth_map import WALL_HEIGHT, MapTrack
from tianracer_description.racing.track import Centerline, centerline_file

STATE = {name: k for k, name in enumerate(bullet_plant.CarBatch.STATE)}
# The state's columns an observation holds, in this order: speed, steering, the IMU's six.
OBSERVED = [STATE['speed']] + list(range(STATE['steering'], STATE['linear_acceleration_z'] + 1))
def draw_noise_seed(rng):
    """A seed for a new world's sensor noise, drawn from an environment's generator (never 0, the
    plant's unseeded default)."""
    return int(rng.integers(1, 2 ** 32))


# Where a seeded start lands around the track's start (s = 0 on the centre line): uniform within these.
START_SPREAD = {'along': 0.2, 'offset': 0.1, 'yaw': 0.1}  # m, m, rad


class LidarDescription:
    """What the car's lidar scans: its rays, range_max, angle_min and angle_increment, from its first
    scan in an empty world made for the asking."""

    def __init__(self, model):
        world = new_world(None, model.controllers)
        robot = model.spawn(world, 'probe', (0.0, 0.0, 0.0))
        robot.enable_sensor(model.lidar)
        while robot.scan(model.lidar) is None:
            world.step(1)
        scan = robot.scan(model.lidar)
        self.rays, self.range_max = len(scan['ranges']), float(scan['range_max'])
        self.angle_min, self.angle_increment = float(scan['angle_min']), float(scan['angle_increment'])


def observation_space(lidar, observe_pose):
    parts = {
        'scan': spaces.Box(0.0, lidar.range_max, (lidar.rays,), np.float32),
        'speed': spaces.Box(-np.inf, np.inf, (1,), np.float32),
        'steering': spaces.Box(-np.pi, np.pi, (1,), np.float32),
        'imu': spaces.Box(-np.inf, np.inf, (6,), np.float32),
    }
    if observe_pose:
        parts['pose'] = spaces.Box(-np.inf, np.inf, (3,), np.float32)
    return spaces.Dict(parts)


def action_space():
    """Steering, then speed, each a share of the car's largest; a space of its own per environment
    (spaces carry their own generators)."""
    return spaces.Box(-1.0, 1.0, (2,), np.float32)


def steps_per_action(control_period, time_step):
    steps = int(round(control_period / time_step))
    if steps < 1 or abs(steps * time_step - control_period) > 1e-9:
        raise ValueError('control_period %g s is not a whole number of the world\'s %g s steps'
                         % (control_period, time_step))
    return steps


class RaceTrack:
    """A world file and its centre line, and the spawn poses around its start; or a map of f1tenth's
    (map_server's YAML and image, f1tenth_map.py) made into a world, with its centre line and race
    line found beside it. raceline: the points a waypoint follower drives (the centre line's where
    the track has no race line); raceline_speeds: their speeds (m/s), or None."""

    def __init__(self, world_file=None, centerline=None, map=None, raceline=None, wall_height=WALL_HEIGHT):
        self.raceline_speeds = None
        if map is not None:
            if world_file is not None:
                raise ValueError('pass world_file= or map=, not both (got %s and %s)' % (world_file, map))
            explicit = centerline if isinstance(centerline, Centerline) else None
            track = MapTrack(map, None if explicit is not None else centerline, raceline, wall_height)
            world_file, self.map = track.world_file, track.spec
            centerline = explicit if explicit is not None else Centerline(track.centerline.points)
            self.raceline, self.raceline_speeds = track.raceline.points, track.raceline.vxs
        elif world_file is None:
            raise ValueError('pass world_file= (an SDF world with its centre line) or map= (a map_server YAML of '
                             'f1tenth\'s)')
        else:
            self.map = None
            if raceline is not None:
                raise ValueError('raceline= goes with map=; a world file\'s track drives its centre line')
        self.world_file = world_file
        if centerline is None:
            centerline = Centerline.from_file(centerline_file(world_file))
        elif isinstance(centerline, str):
            centerline = Centerline.from_file(centerline)
        elif not isinstance(centerline, Centerline):
            centerline = Centerline(centerline)
        self.centerline = centerline
        if map is None:
            self.raceline = np.asarray(centerline.points, np.float64)

    def start_pose(self, rng, along=0.0, offset=0.0, spread=1.0):
        """A start `along` the centre line from the start line and `offset` to its left, moved by up to
        START_SPREAD x spread, drawn from `rng` (a numpy Generator)."""
        s = along + spread * rng.uniform(-START_SPREAD['along'], START_SPREAD['along'])
        offset += spread * rng.uniform(-START_SPREAD['offset'], START_SPREAD['offset'])
        x, y, yaw = self.centerline.pose_at(s, offset)
        return x, y, yaw + spread * rng.uniform(-START_SPREAD['yaw'], START_SPREAD['yaw'])


def race_parts(world_file, centerline, urdf, controllers, max_speed, map=None, raceline=None,
               wall_height=WALL_HEIGHT):
    """(track, car model, lidar): what every environment starts from, from its arguments."""
    track = RaceTrack(world_file, centerline, map, raceline, wall_height)
    model = CarModel(urdf, controllers, max_speed)
    return track, model, LidarDescription(model)


class RaceCars:
    """N cars on a track, the N cars of one CarBatch (see the module's text)."""

    def __init__(self, track, model, lidar, names, observe_pose=False, threads=1, chase_camera=False):
        self.track, self.model, self.lidar, self.names = track, model, lidar, list(names)
        self.observe_pose, self.chase_camera = observe_pose, chase_camera
        self.batch = bullet_plant.CarBatch(len(self.names), threads)
        count = len(self.names)
        self.worlds, self.robots = [None] * count, [None] * count
        self._still = self.model.commands(np.zeros((count, 2)))

    def place(self, i, pose, world=None, noise_seed=0):
        """Car i spawned at pose (x, y, yaw) into `world` (shared with other cars), or into a new world
        of the track whose sensors' noise is seeded by `noise_seed`; its progress starts there."""
        pose = tuple(float(v) for v in pose)
        world = world or new_world(self.track.world_file, self.model.controllers, noise_seed)
        self.worlds[i], self.robots[i] = world, self.model.spawn(world, self.names[i], pose, self.chase_camera)
        self.model.bind(self.batch, i, world, self.robots[i], self.track.centerline)

    def settle(self, i=None):
        """(scans, state) after one physics step with the cars held still (their first scan, their
        controllers' first update): all cars, or car i alone (its world stepped; the others' are not)."""
        if i is None:
            return self.batch.step(self._still, 1)
        return self.batch.step(self._still[i:i + 1], 1, [i])

    def step(self, actions, steps, still=None):
        """(scans, state, rewards) after every car's action held for `steps` physics steps; cars where
        `still` is True are held still. The rewards: metres gained along the centre line."""
        commands = self.model.commands(actions)
        if still is not None:
            commands[still] = self._still[still]
        scans, state = self.batch.step(commands, steps)
        return scans, state, state[:, STATE['centerline_gained']]

    def observations(self, scans, state):
        """The cars' observations, a dict of arrays with a row per car."""
        observed = state[:, OBSERVED].astype(np.float32)
        observations = {'scan': scans, 'speed': observed[:, 0:1], 'steering': observed[:, 1:2], 'imu': observed[:, 2:]}
        if self.observe_pose:
            observations['pose'] = state[:, [STATE['x'], STATE['y'], STATE['yaw']]].astype(np.float32)
        return observations

    def infos(self, state):
        """The infos of the cars whose rows `state` holds, a dict of arrays: progress (m along the centre
        line), laps (since the car was placed), time (s, simulated), crashed."""
        return {'progress': state[:, STATE['centerline_s']],
                'laps': state[:, STATE['centerline_travelled']] / self.track.centerline.length,
                'time': state[:, STATE['time']], 'crashed': self.crashed(state)}

    def crashed(self, state):
        return state[:, STATE['crashed']] > 0


def row(arrays, i):
    """Car i's entry of a dict of arrays (an observation or an info)."""
    return {key: value[i] for key, value in arrays.items()}
