"""Racing on the plant as a Gymnasium environment: one car on a track, a lidar, its speed and steering
and IMU observed, an action of steering and speed, rewarded for progress along the track's centre line.

Observation: see cars.py. Action: a Box in [-1, 1]^2, steering then speed, each a share of the car's
largest (the steering at which the inside wheel reaches its limit; max_speed), driven through the
converter's Ackermann conversion into the tutorial's four controllers. Each step holds the action for
control_period seconds of simulated time. Reward: metres gained along the centre line. Terminated when
the car touches anything but the ground (a wall, a cone, another car); truncated by the time limit
(max_episode_steps, registered). reset(seed=...) seeds the env's own generator (self.np_random), which
places the start near the track's start line and seeds the sensors' noise; options={"pose": (x, y,
yaw)} puts the car there instead, options={"start": "grid"} on the grid's pole behind the start line
and {"start": "random"} on a random point of the centre line (cars.py); options={"car_params": {...}}
gives the car other parameters for the episode (mass, mu, max_speed, max_steering: car.py), recorded in
info["car_params"]; a reset without them gives it the defaults again. observe_frenet=True,
curvature_ahead=(metres, ...) and frenet_line= add the car's Frenet coordinates and the line's curvature
ahead to the observation; the info holds lap_count, last_lap_time and best_lap_time (cars.py).
Every reset makes the world anew (a few milliseconds), so an episode depends on nothing before it: the
same seed and actions give the same observations, bit for bit. render_mode "rgb_array": the frames of
a chase camera behind the car (the plant's OpenGL cameras).
The track: world_file (an SDF world, its centre line beside it or centerline=), or map= (a map of
f1tenth's: map_server's YAML and image, its centre line and race line CSVs beside it or centerline=
and raceline=; walls wall_height high; see f1tenth_map.py). RaceVectorEnv and RaceParallelEnv take
the same.
"""
import gymnasium
import numpy as np

from tianracer_description.racing.car import CHASE_CAMERA, CHASE_CAMERA_SIZE
from tianracer_description.racing.cars import (FrenetObserver, RaceCars, action_space, draw_noise_seed,
                                               observation_space, race_parts, row, steps_per_action)
from tianracer_description.racing.f1tenth_map import WALL_HEIGHT


class RaceEnv(gymnasium.Env):
    """One car racing on a track (see the module's text)."""

    metadata = {'render_modes': ['rgb_array'], 'render_fps': 30}

    def __init__(self, world_file=None, centerline=None, urdf=None, controllers=None, max_speed=2.0,
                 control_period=0.01, observe_pose=False, render_mode=None, map=None, raceline=None,
                 wall_height=WALL_HEIGHT, observe_frenet=False, curvature_ahead=(), frenet_line='centerline'):
        if render_mode not in (None, 'rgb_array'):
            raise ValueError("render_mode is None or 'rgb_array'; got %r" % (render_mode,))
        self.track, self.model, self.lidar = race_parts(world_file, centerline, urdf, controllers, max_speed,
                                                        map, raceline, wall_height)
        self.render_mode = render_mode
        self.control_period = control_period
        frenet = FrenetObserver(self.track, observe_frenet, curvature_ahead, frenet_line)
        self.observation_space = observation_space(self.lidar, observe_pose, frenet)
        self.action_space = action_space()
        self._cars = RaceCars(self.track, self.model, self.lidar, ['car'], observe_pose,
                              chase_camera=render_mode == 'rgb_array', frenet=frenet)
        self._steps = None

    def reset(self, *, seed=None, options=None):
        super().reset(seed=seed)
        options = options or {}
        if options.get('pose') is not None and options.get('start') is not None:
            raise ValueError("options: 'pose' or 'start', not both")
        self._cars.set_params(0, self._cars.car_params(options.get('car_params'), None)[0])
        pose, = self.track.start_poses(self.np_random, options.get('start'), [options.get('pose')],
                                       lambda rng, index: self.track.start_pose(rng))
        self._cars.place(0, pose, noise_seed=draw_noise_seed(self.np_random))
        self._steps = steps_per_action(self.control_period, self._cars.worlds[0].time_step)
        scans, state = self._cars.settle()
        return row(self._cars.observations(scans, state), 0), row(self._cars.infos(state), 0)

    def step(self, action):
        if self._steps is None:
            raise RuntimeError('call reset() before step()')
        scans, state, rewards = self._cars.step(action, self._steps)
        info = row(self._cars.infos(state), 0)
        return row(self._cars.observations(scans, state), 0), float(rewards[0]), bool(info['crashed']), False, info

    def render(self):
        robot = self._cars.robots[0]
        if self.render_mode != 'rgb_array' or robot is None:
            return None
        frame = robot.image(CHASE_CAMERA)
        width, height = CHASE_CAMERA_SIZE
        return np.zeros((height, width, 3), np.uint8) if frame is None else np.array(frame['rgb'])  # none yet

    def close(self):
        self._cars.worlds[0] = self._cars.robots[0] = None
