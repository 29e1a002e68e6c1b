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
same seed and actions give the same observations, bit for bit.
physics_dt= (s) steps the physics with that step instead of the world file's <max_step_size> (1 ms on
our tracks), for learning: fewer steps an action (it divides control_period). Closed loop its laps stay
those of 1 ms within the tolerances of docs/racing.md (measured up to 5 ms); the trajectory of a replayed
action sequence does not (docs/design.md).
Rendering (views.py): render_mode "rgb_array" returns a frame, "human" shows each step's in a window;
view= says what: "chase" (the default), a chase camera behind the car (the plant's OpenGL cameras),
or "top_down", the track from above with the car, its lidar's hits and the centre line (numpy,
top_down_scale m a pixel). metadata["render_fps"] is a frame a step (1 / control_period), so that a
video of the frames (gymnasium.wrappers.RecordVideo) plays in simulated time.
The track: world_file (an SDF world, its centre line beside it or centerline=), or map= (a map of
f1tenth's: map_server's YAML and image, its centre line and race line CSVs beside it or centerline=
and raceline=; walls wall_height high; see f1tenth_map.py). RaceVectorEnv and RaceParallelEnv take
the same.
"""
import gymnasium

from tianracer_description.racing.cars import (FrenetObserver, RaceCars, action_space, check_physics_dt, draw_noise_seed,
                                               observation_space, race_parts, steps_per_action)
from tianracer_description.racing.f1tenth_map import WALL_HEIGHT
from tianracer_description.racing.views import RENDER_MODES, RaceViews, check_render, frames_per_second


class RaceEnv(gymnasium.Env):
    """One car racing on a track (see the module's text)."""

    metadata = {'render_modes': RENDER_MODES, 'render_fps': 100}  # render_fps: 1 / control_period, set per env

    def __init__(self, world_file=None, centerline=None, urdf=None, controllers=None, max_speed=2.0,
                 control_period=0.01, observe_pose=False, render_mode=None, map=None, raceline=None,
                 wall_height=WALL_HEIGHT, observe_frenet=False, curvature_ahead=(), frenet_line='centerline',
                 view='chase', top_down_scale=None, physics_dt=None):
        check_render(render_mode, view)
        check_physics_dt(physics_dt, control_period)
        self.track, self.model, self.lidar = race_parts(world_file, centerline, urdf, controllers, max_speed,
                                                        map, raceline, wall_height)
        self.render_mode, self.view = render_mode, view
        self.metadata = dict(self.metadata, render_fps=frames_per_second(control_period))
        self.control_period = control_period
        frenet = FrenetObserver(self.track, observe_frenet, curvature_ahead, frenet_line)
        self.observation_space = observation_space(self.lidar, observe_pose, frenet)
        self.action_space = action_space()
        self._cars = RaceCars(self.track, self.model, self.lidar, ['car'], observe_pose,
                              chase_camera=render_mode is not None and view == 'chase', frenet=frenet,
                              physics_dt=physics_dt)
        self._views = RaceViews(self._cars, render_mode, view, top_down_scale, 'Tianracer',
                                self.metadata['render_fps'])
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
        if self.render_mode == 'human':
            self.render()
        return self._cars.observations(scans[0], state[0]), self._cars.infos(state[0], 0)

    def step(self, action):
        if self._steps is None:
            raise RuntimeError('call reset() before step()')
        scans, state, rewards = self._cars.step(action, self._steps)
        info = self._cars.infos(state[0], 0)
        if self.render_mode == 'human':
            self.render()
        return self._cars.observations(scans[0], state[0]), float(rewards[0]), bool(info['crashed']), False, info

    def render(self):
        """The view's frame (H x W x 3, uint8) for "rgb_array"; None for "human" (shown in the window),
        without a render_mode, and before the first reset."""
        if self.render_mode is None:
            return None
        return self._views.show(self._views.frame(0))

    def close(self):
        self._views.close()
        self._cars.worlds[0] = self._cars.robots[0] = None
