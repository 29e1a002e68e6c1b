"""What the three environments share: N cars on a track as one bullet_plant.CarBatch, and everything
about them as arrays, one row per car: their commands from actions, their observations, their progress
along the centre line (the reward) and their ends. RaceEnv is one car, RaceVectorEnv N cars in N
worlds, RaceParallelEnv N cars in one world.

Observation (a dict): "scan", the lidar's ranges (m; no return reads as its range_max) at the lidar's
own rate (the Tianracer's 40 Hz: between scans the last one stays); "speed", the forward speed (m/s);
"steering", the mean of the two steering joints' angles (rad); "imu", the IMU's angular velocity
(rad/s) and linear acceleration (m/s^2) in its frame (zeros for a car without one); with
observe_pose, "pose": x, y, yaw in the world; with observe_frenet, "frenet": s (m along the line from
the start line), ey (m, left of the line positive), epsi (the heading less the line's, rad in [-pi,
pi]); with curvature_ahead (distances, m), "curvature_ahead": the line's curvature (1/m, left turns
positive) that far ahead of s. The line of these two: frenet_line, 'centerline' (the default) or
'raceline' (the track's race line; the centre line where it has none).

Info: progress, laps (track lengths travelled since the start), lap_count, last_lap_time,
best_lap_time (bullet_plant.LapTimer's, counted by the CarBatch), time, crashed, car_params (the car's
parameters, CAR_PARAMS).

Starts (reset's options={'start': ...}): None, the environment's default; 'grid', the staggered grid
behind the start line (one car alone: the pole); 'random', a uniformly random point of the centre line
(several cars: the grid there), drawn from the environment's generator.
"""
import math

import numpy as np
from gymnasium import spaces

from tianracer_description import bullet_plant
from tianracer_description.racing.car import CAR_PARAMS, CarModel, new_world
from tianracer_description.racing.f1tenth_map import WALL_HEIGHT, MapTrack
from tianracer_description.racing.track import Centerline, centerline_file

STATE = {name: k for k, name in enumerate(bullet_plant.CarBatch.STATE)}
# The state's columns an observation holds, in this order: speed, steering, the IMU's six; and observe_pose's.
OBSERVED = [STATE['speed']] + list(range(STATE['steering'], STATE['linear_acceleration_z'] + 1))
POSE = [STATE['x'], STATE['y'], STATE['yaw']]
def draw_noise_seed(rng):
    """A seed for a new world's sensor noise, drawn from an environment's generator (never 0, the
    plant's unseeded default)."""
    return int(rng.integers(1, 2 ** 32))


# Where a seeded start lands around the track's start (s = 0 on the centre line): uniform within these.
START_SPREAD = {'along': 0.2, 'offset': 0.1, 'yaw': 0.1}  # m, m, rad
# The grid: two staggered columns behind the start line, f1tenth-style.
GRID_SPACING = 0.6  # m between a car and the one behind it, along the centre line
GRID_OFFSET = 0.25  # m either side of the centre line: the two columns
GRID_SPREAD = 0.25  # of the start spread, each car's own
STARTS = (None, 'grid', 'random')
FRENET_LINES = ('centerline', 'raceline')


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


def observation_space(lidar, observe_pose, frenet=None):
    """The observation's Dict space; frenet: a FrenetObserver, or None."""
    parts = {
        'scan': spaces.Box(0.0, lidar.range_max, (lidar.rays,), np.float32),
        'speed': spaces.Box(-np.inf, np.inf, (1,), np.float32),
        'steering': spaces.Box(-np.pi, np.pi, (1,), np.float32),
        'imu': spaces.Box(-np.inf, np.inf, (6,), np.float32),
    }
    if observe_pose:
        parts['pose'] = spaces.Box(-np.inf, np.inf, (3,), np.float32)
    if frenet is not None:
        parts.update(frenet.spaces())
    return spaces.Dict(parts)


class FrenetObserver:
    """What observe_frenet and curvature_ahead add to an observation: the cars' Frenet coordinates on a
    line of the track (the centre line: as CarBatch measured them; the race line: projected here) and
    its curvature ahead of them (track.py's Centerline does the arithmetic)."""

    def __init__(self, track, observe_frenet=False, curvature_ahead=(), frenet_line='centerline'):
        if frenet_line not in FRENET_LINES:
            raise ValueError('frenet_line is one of %s; got %r' % (', '.join(FRENET_LINES), frenet_line))
        self.ahead = np.asarray(curvature_ahead if curvature_ahead is not None else (), np.float64).reshape(-1)
        if not np.all(np.isfinite(self.ahead)):
            raise ValueError('curvature_ahead is distances ahead along the line (m); got %r' % (curvature_ahead,))
        self.observe_frenet = bool(observe_frenet)
        self.on_centerline = frenet_line == 'centerline' or track.map is None  # a world's race line is its centre line
        self.line = track.centerline if self.on_centerline else Centerline(track.raceline)

    def __bool__(self):
        return self.observe_frenet or len(self.ahead) > 0

    def spaces(self):
        parts = {}
        if self.observe_frenet:
            parts['frenet'] = spaces.Box(np.array([0.0, -np.inf, -np.pi], np.float32),
                                         np.array([self.line.length, np.inf, np.pi], np.float32), dtype=np.float32)
        if len(self.ahead):
            parts['curvature_ahead'] = spaces.Box(-np.inf, np.inf, (len(self.ahead),), np.float32)
        return parts

    def observations(self, state):
        """The observations' frenet and curvature_ahead entries, a row per car of `state` (one car's
        row, 1-D: that car's)."""
        if state.ndim == 1:
            return {key: value[0] for key, value in self.observations(state[np.newaxis]).items()}
        x, y, yaw = state[:, STATE['x']], state[:, STATE['y']], state[:, STATE['yaw']]
        if self.on_centerline:
            s, ey = state[:, STATE['centerline_s']], state[:, STATE['centerline_offset']]
            frenet = [self.line.frenet(*pose, s=si, offset=oi) for *pose, si, oi in zip(x, y, yaw, s, ey)]
        else:
            frenet = [self.line.frenet(*pose) for pose in zip(x, y, yaw)]
        frenet = np.array(frenet, np.float64).reshape(-1, 3)
        parts = {}
        if self.observe_frenet:
            parts['frenet'] = frenet.astype(np.float32)
        if len(self.ahead):
            parts['curvature_ahead'] = self.line.curvature_at(frenet[:, :1] + self.ahead).astype(np.float32)
        return parts


def action_space():
    """Steering, then speed, each a share of the car's largest; a space of its own per environment
    (spaces carry their own generators)."""
    return spaces.Box(-1.0, 1.0, (2,), np.float32)


def steps_per_action(control_period, time_step):
    steps = int(round(control_period / time_step))
    if steps < 1 or abs(steps * time_step - control_period) > 1e-9:
        raise ValueError('control_period %g s is not a whole number of the world\'s %g s steps (physics_dt)'
                         % (control_period, time_step))
    return steps


def check_physics_dt(physics_dt, control_period):
    """physics_dt None (the world file's step) or a step that divides control_period; ValueError names
    what is wrong."""
    if physics_dt is not None:
        if not physics_dt > 0:
            raise ValueError('physics_dt is a physics step in seconds (> 0), or None for the world file\'s; got %r'
                             % (physics_dt,))
        steps_per_action(control_period, physics_dt)
    return physics_dt


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

    def grid_pose(self, rng, index, at=0.0):
        """Where car `index` of a grid whose pole is `at` (m along the centre line) starts: behind it,
        the left and right columns by turns, each moved by GRID_SPREAD of the start spread."""
        offset = GRID_OFFSET if index % 2 == 0 else -GRID_OFFSET
        return self.start_pose(rng, along=at - GRID_SPACING * index, offset=offset, spread=GRID_SPREAD)

    def start_poses(self, rng, start, given, default):
        """The cars' poses for reset's options['start'] (one of STARTS), drawn from `rng` in the cars'
        order: `given` holds a pose or None for each car, and only those with none are drawn; a start of
        None draws `default`(rng, index)."""
        if start not in STARTS:
            raise ValueError("options['start'] is one of %s; got %r" % (', '.join(map(repr, STARTS)), start))
        if start is None:
            draw = default
        elif start == 'grid':
            draw = self.grid_pose
        else:  # random: a point of the centre line and its heading; several cars, the grid there
            at = rng.uniform(0.0, self.centerline.length)
            draw = ((lambda rng, index: self.centerline.pose_at(at)) if len(given) == 1
                    else (lambda rng, index: self.grid_pose(rng, index, at)))
        return [pose if pose is not None else draw(rng, index) for index, pose in enumerate(given)]

    @property
    def description(self):
        """The world file parsed (a bullet_plant.WorldDescription), once: every reset makes its world
        from it without parsing the file again."""
        if not hasattr(self, '_description'):
            self._description = bullet_plant.WorldDescription.from_file(self.world_file)
        return self._description

    @property
    def ground_mu(self):
        """The ground's friction coefficient: the smallest of the world's planes' (inf: no plane)."""
        if not hasattr(self, '_ground_mu'):
            planes = [c['mu'] for c in bullet_plant.World(self.description).static_collisions()
                      if c['kind'] == 'plane']
            self._ground_mu = min(planes) if planes else math.inf
        return self._ground_mu


def race_parts(world_file, centerline, urdf, controllers, max_speed, map=None, raceline=None,
               wall_height=WALL_HEIGHT):
    """(track, car model, lidar): what every environment starts from, from its arguments."""
    track = RaceTrack(world_file, centerline, map, raceline, wall_height)
    model = CarModel(urdf, controllers, max_speed)
    return track, model, LidarDescription(model)


class RaceCars:
    """N cars on a track, the N cars of one CarBatch (see the module's text)."""

    def __init__(self, track, model, lidar, names, observe_pose=False, threads=1, chase_camera=False, frenet=None,
                 physics_dt=None):
        self.track, self.model, self.lidar, self.names = track, model, lidar, list(names)
        self.physics_dt = physics_dt  # the worlds' physics step (None: the world file's)
        self.observe_pose, self.chase_camera = observe_pose, chase_camera
        self.frenet = frenet if frenet else None  # a FrenetObserver that observes something, or None
        self.batch = bullet_plant.CarBatch(len(self.names), threads)
        count = len(self.names)
        self.worlds, self.robots = [None] * count, [None] * count
        self.params = [model.default_params() for _ in range(count)]
        self._set_param_columns()
        self._still = np.zeros((count, 2))  # the actions that hold the cars still

    def car_params(self, given, keys):
        """Each car's parameters from reset's options['car_params'] (`given`): None (the defaults), one
        dict of CAR_PARAMS for every car, or one per car, a list (or tuple) in the cars' order or a dict
        by `keys` (the agents' names; a car left out gets the defaults). ValueError names what is wrong."""
        count = len(self.names)
        if given is None:
            per_car = [None] * count
        elif isinstance(given, (list, tuple)):
            if len(given) != count:
                raise ValueError("options['car_params'] as a list has a dict for each of the %d cars; got %d"
                                 % (count, len(given)))
            per_car = list(given)
        elif isinstance(given, dict) and keys is not None and given and set(given) <= set(keys):
            per_car = [given.get(key) for key in keys]
        elif isinstance(given, dict):
            per_car = [given] * count
        else:
            raise ValueError("options['car_params'] is a dict of %s, or one per car; got %r" % (', '.join(CAR_PARAMS), given))
        return [self.model.params(params, self.track.ground_mu) for params in per_car]

    def set_params(self, i, params):
        """Car i's parameters (a dict of CAR_PARAMS, complete: model.params'), from its next placing on."""
        self.params[i] = dict(params)
        self._set_param_columns()

    def _set_param_columns(self):
        """The infos' car_params, a column per parameter, made when a parameter changes."""
        self._param_columns = {name: np.array([p[name] for p in self.params]) for name in CAR_PARAMS}

    def _cars(self, i):
        """All the cars (i None) or car i, as a slice: views of the per-car arrays, not copies."""
        return slice(None) if i is None else slice(i, i + 1)

    def new_world(self, noise_seed):
        """A world of the track for the cars, its sensors' noise seeded by `noise_seed`."""
        return new_world(self.track.description, self.model.controllers, noise_seed, self.physics_dt)

    def place(self, i, pose, world=None, noise_seed=0):
        """Car i spawned at pose (x, y, yaw) into `world` (shared with other cars), or into a new world
        of the track whose sensors' noise is seeded by `noise_seed`, with its parameters; its progress
        and laps start there."""
        pose = tuple(float(v) for v in pose)
        world = world or self.new_world(noise_seed)
        self.worlds[i] = world
        self.robots[i] = self.model.spawn(world, self.names[i], pose, self.chase_camera, self.params[i])
        self.model.bind(self.batch, i, world, self.robots[i], self.track.centerline, self.params[i])

    def settle(self, i=None):
        """(scans, state) after one physics step with the cars held still (their first scan, their
        controllers' first update): all cars, or car i alone (its world stepped; the others' are not)."""
        if i is None:
            return self.batch.drive(self._still, 1)
        return self.batch.drive(self._still[i:i + 1], 1, [i])

    def step(self, actions, steps):
        """(scans, state, rewards) after every car's action held for `steps` physics steps (an action
        (0, 0) holds a car still). The rewards: metres gained along the centre line."""
        scans, state = self.batch.drive(np.asarray(actions, np.float64).reshape(-1, 2), steps)
        return scans, state, state[:, STATE['centerline_gained']]

    def observations(self, scans, state):
        """The cars' observations, a dict of arrays with a row per car; for one car's scan and state
        rows (1-D), its observation."""
        observed = state[..., OBSERVED].astype(np.float32)
        observations = {'scan': scans, 'speed': observed[..., 0:1], 'steering': observed[..., 1:2],
                        'imu': observed[..., 2:]}
        if self.observe_pose:
            observations['pose'] = state[..., POSE].astype(np.float32)
        if self.frenet is not None:
            observations.update(self.frenet.observations(state))
        return observations

    def infos(self, state, i=None):
        """The infos of the cars whose rows `state` holds (all, or car i alone), a dict of arrays:
        progress (m along the centre line), laps (track lengths travelled since the car was placed),
        lap_count, last_lap_time and best_lap_time (bullet_plant.LapTimer's), time (s, simulated),
        crashed, and car_params (a dict of arrays: the cars' parameters). For car i's state row alone
        (1-D), its info, a dict of numbers."""
        if state.ndim == 1:
            params = {name: column[i] for name, column in self._param_columns.items()}
        else:
            cars = self._cars(i)
            params = {name: column[cars].copy() for name, column in self._param_columns.items()}
        return {'progress': state[..., STATE['centerline_s']],
                'laps': state[..., STATE['centerline_travelled']] / self.track.centerline.length,
                'lap_count': np.int64(state[..., STATE['lap_count']]),
                'last_lap_time': state[..., STATE['last_lap_time']], 'best_lap_time': state[..., STATE['best_lap_time']],
                'time': state[..., STATE['time']], 'crashed': self.crashed(state), 'car_params': params}

    def crashed(self, state):
        return state[..., STATE['crashed']] > 0


def row(arrays, i):
    """Car i's entry of a dict of arrays (an observation or an info; a dict in it, its own entry)."""
    return {key: row(value, i) if isinstance(value, dict) else value[i] for key, value in arrays.items()}


def rows(arrays, cars):
    """Every car's entry of a dict of arrays with a row per car, as row() gives each: a list of `cars`
    dicts, the arrays' rows taken by numpy's iteration (a PettingZoo step's observations and infos)."""
    entries = [{} for _ in range(cars)]
    for key, value in arrays.items():
        for entry, item in zip(entries, rows(value, cars) if isinstance(value, dict) else value):
            entry[key] = item
    return entries
