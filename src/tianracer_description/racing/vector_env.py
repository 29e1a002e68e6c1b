"""N cars racing, each on its own copy of the track, stepped in one C++ call (bullet_plant.CarBatch:
the worlds side by side on a thread pool with the GIL released) and observed as arrays: Gymnasium's
VectorEnv, registered as the environments' vector_entry_point, so gymnasium.make_vec(
'Tianracer-RaceTrack-v0', num_envs=N) makes one. Each car is RaceEnv's (same observations, actions,
rewards and ends; see env.py).

Autoreset is SAME_STEP (declared in metadata): a car whose episode ends is reset within the same
step; the step returns its first observation of the next episode, and infos carry "final_obs" and
"final_info" (with the "_final_obs" / "_final_info" masks) of the one that ended. Each car has a
generator of its own, seeded from reset(seed=) as seed, seed + 1, ...

reset(options=) takes "poses" (a pose or None for each car), "start" (None, "grid": each car, alone in
its world, on the grid's pole; "random"), which the autoresets keep until the next reset(), and
"car_params" (one dict for every car or a list of one per car, None: the defaults), which each car
keeps through its autoresets. The info's "car_params" is a dict of arrays, one per parameter.

Rendering (RaceEnv's render_mode and view=, views.py): render() returns a tuple of the cars' frames,
one per env, as Gymnasium's vector environments do (gymnasium.wrappers.vector.RecordVideo tiles
them); render_mode "human" shows them tiled in one window after every step.
"""
import numpy as np
from gymnasium.utils import seeding
from gymnasium.vector import AutoresetMode, VectorEnv
from gymnasium.vector.utils import batch_space

from tianracer_description.racing.cars import (FrenetObserver, RaceCars, action_space, check_physics_dt, draw_noise_seed,
                                               observation_space, race_parts, row, steps_per_action)
from tianracer_description.racing.f1tenth_map import WALL_HEIGHT
from tianracer_description.racing.views import RENDER_MODES, RaceViews, check_render, frames_per_second, tile


class RaceVectorEnv(VectorEnv):
    metadata = {'autoreset_mode': AutoresetMode.SAME_STEP, 'render_modes': RENDER_MODES, 'render_fps': 100}

    def __init__(self, num_envs, world_file=None, centerline=None, urdf=None, controllers=None, max_speed=2.0,
                 control_period=0.01, observe_pose=False, max_episode_steps=None, threads=0, map=None,
                 raceline=None, wall_height=WALL_HEIGHT, observe_frenet=False, curvature_ahead=(),
                 frenet_line='centerline', render_mode=None, view='chase', top_down_scale=None,
                 physics_dt=None):
        if num_envs < 1:
            raise ValueError('num_envs is 1 or more; got %r' % (num_envs,))
        check_render(render_mode, view)
        check_physics_dt(physics_dt, control_period)
        self.num_envs = num_envs
        self.track, self.model, self.lidar = race_parts(world_file, centerline, urdf, controllers, max_speed,
                                                        map, raceline, wall_height)
        self.control_period = control_period
        self.render_mode, self.view = render_mode, view
        self.metadata = dict(self.metadata, render_fps=frames_per_second(control_period))
        self.max_episode_steps = max_episode_steps
        frenet = FrenetObserver(self.track, observe_frenet, curvature_ahead, frenet_line)
        self.single_observation_space = observation_space(self.lidar, observe_pose, frenet)
        self.single_action_space = action_space()
        self.observation_space = batch_space(self.single_observation_space, num_envs)
        self.action_space = batch_space(self.single_action_space, num_envs)
        self._cars = RaceCars(self.track, self.model, self.lidar, ['car'] * num_envs, observe_pose, threads, frenet=frenet,
                              chase_camera=render_mode is not None and view == 'chase', physics_dt=physics_dt)
        self._views = RaceViews(self._cars, render_mode, view, top_down_scale, 'Tianracer x %d' % num_envs,
                                self.metadata['render_fps'])
        self._rngs = [seeding.np_random()[0] for _ in range(num_envs)]
        self._elapsed = np.zeros(num_envs, np.int64)
        self._everyone = np.ones(num_envs, bool)  # the infos' masks: every car has every key
        self._everyone.flags.writeable = False
        self._steps = None
        self._start = None  # reset's options['start'], which the autoresets keep

    def reset(self, *, seed=None, options=None):
        super().reset(seed=seed)
        if seed is not None:
            seeds = [seed + i for i in range(self.num_envs)] if isinstance(seed, int) else list(seed)
            self._rngs = [seeding.np_random(s)[0] for s in seeds]
        options = options or {}
        poses = options.get('poses') or [None] * self.num_envs
        if len(poses) != self.num_envs:
            raise ValueError("options['poses'] has a pose (or None) for each of the %d cars; got %d"
                             % (self.num_envs, len(poses)))
        for i, params in enumerate(self._cars.car_params(options.get('car_params'), None)):
            self._cars.set_params(i, params)
        self._start = options.get('start')
        for i in range(self.num_envs):
            self._cars.place(i, self._start_pose(i, poses[i]), noise_seed=draw_noise_seed(self._rngs[i]))
        self._elapsed[:] = 0
        self._steps = steps_per_action(self.control_period, self._cars.worlds[0].time_step)
        scans, state = self._cars.settle()
        if self.render_mode == 'human':
            self.render()
        return self._cars.observations(scans, state), self._with_masks(self._cars.infos(state))

    def _start_pose(self, i, pose=None):
        """Car i's start: `pose`, or one its generator draws for the start reset() was given."""
        return self.track.start_poses(self._rngs[i], self._start, [pose], lambda rng, index: self.track.start_pose(rng))[0]

    def _with_masks(self, infos):
        """Gymnasium's vector infos: each key's array, and "_key", which cars it is for (all of them);
        a dict of arrays within, the same."""
        return {**{key: self._with_masks(value) if isinstance(value, dict) else value for key, value in infos.items()},
                **{'_' + key: self._everyone for key in infos}}

    def step(self, actions):
        if self._steps is None:
            raise RuntimeError('call reset() before step()')
        scans, state, rewards = self._cars.step(actions, self._steps)
        self._elapsed += 1
        terminated = self._cars.crashed(state)
        truncated = np.zeros(self.num_envs, bool)
        if self.max_episode_steps:
            truncated = (self._elapsed >= self.max_episode_steps) & ~terminated
        observations = self._cars.observations(scans, state)
        car_infos = self._cars.infos(state)
        infos = self._with_masks(car_infos)
        ended = terminated | truncated
        for i in (np.flatnonzero(ended) if ended.any() else ()):
            infos = self._add_info(infos, {'final_obs': row(observations, i), 'final_info': row(car_infos, i)}, i)
            observations = {key: value.copy() for key, value in observations.items()}  # final_obs keeps its own
            self._cars.place(i, self._start_pose(i), noise_seed=draw_noise_seed(self._rngs[i]))
            self._elapsed[i] = 0
            first_scans, first_state = self._cars.settle(i)  # its world alone; the others wait for the next step
            for key, value in self._cars.observations(first_scans, first_state).items():
                observations[key][i] = value[0]
            self._set_row(infos, self._cars.infos(first_state, i), i)
        if self.render_mode == 'human':
            self.render()
        return observations, rewards, terminated, truncated, infos

    def _set_row(self, infos, car_infos, i):
        """Car i's entries of the infos from `car_infos` (its row alone)."""
        for key, value in car_infos.items():
            if isinstance(value, dict):
                self._set_row(infos[key], value, i)
            else:
                infos[key][i] = value[0]

    def render(self):
        """A tuple of the envs' frames (H x W x 3, uint8, one per env) for "rgb_array"; None for "human"
        (shown tiled in the window), without a render_mode, and before the first reset."""
        if self.render_mode is None or self._cars.robots[0] is None:
            return None
        frames = tuple(self._views.frame(i) for i in range(self.num_envs))
        if self.render_mode == 'human':
            return self._views.show(tile(frames))
        return frames

    def close_extras(self, **kwargs):
        self._views.close()
        self._cars.worlds = [None] * self.num_envs
        self._cars.robots = [None] * self.num_envs
