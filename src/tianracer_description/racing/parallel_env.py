"""A race of N cars in one world, each its own agent: PettingZoo's ParallelEnv.

    from tianracer_description.racing.parallel_env import RaceParallelEnv
    env = RaceParallelEnv(RACE_TRACK_WORLD, cars=3)
    observations, infos = env.reset(seed=1)
    observations, rewards, terminations, truncations, infos = env.step({agent: action, ...})

Each car ("car_0", "car_1", ...) is RaceEnv's car: the same observation, action and reward (see
env.py). They start on a grid behind the start line, in two staggered columns, and race in one world,
so they see each other in their lidars and collide: a car that touches anything but the ground (a
wall, a cone, another car) is terminated, stops, and stays where it is, an obstacle for the others.
All are truncated after max_cycles steps. reset(options={"poses": {agent: (x, y, yaw)}}) puts cars
elsewhere than on the grid; options={"start": "random"} puts the grid at a random point of the centre
line ("grid": the grid, the default); options={"car_params": ...} gives every car other parameters (one
dict) or each its own ({agent: dict}; one left out gets the defaults), see car.py and cars.py. One CarBatch steps the world once per step and reads every car. The same
seed and actions give the same observations, bit for bit.

Rendering (RaceEnv's render_mode, views.py): render() draws the race; view="top_down" (the default)
all the cars in one image of the track from above, view="chase" each car's chase camera, tiled.
render_mode "human" shows that in a window after every step.
"""
import functools

import numpy as np
from gymnasium.utils import seeding
from pettingzoo import ParallelEnv

from tianracer_description.racing import MAX_EPISODE_STEPS
from tianracer_description.racing.cars import (FrenetObserver, RaceCars, action_space, check_physics_dt, draw_noise_seed,
                                               observation_space, race_parts, rows, steps_per_action)
from tianracer_description.racing.f1tenth_map import WALL_HEIGHT
from tianracer_description.racing.views import RENDER_MODES, RaceViews, check_render, frames_per_second, tile


class RaceParallelEnv(ParallelEnv):
    metadata = {'name': 'tianracer_race_v0', 'render_modes': RENDER_MODES, 'render_fps': 100}

    def __init__(self, world_file=None, cars=2, centerline=None, urdf=None, controllers=None, max_speed=2.0,
                 control_period=0.01, observe_pose=False, max_cycles=MAX_EPISODE_STEPS, map=None, raceline=None,
                 wall_height=WALL_HEIGHT, observe_frenet=False, curvature_ahead=(), frenet_line='centerline',
                 render_mode=None, view='top_down', top_down_scale=None, physics_dt=None):
        if cars < 1:
            raise ValueError('a race has 1 car or more; got %r' % (cars,))
        check_render(render_mode, view)
        check_physics_dt(physics_dt, control_period)
        self.track, self.model, self.lidar = race_parts(world_file, centerline, urdf, controllers, max_speed,
                                                        map, raceline, wall_height)
        self.control_period, self.observe_pose, self.max_cycles = control_period, observe_pose, max_cycles
        self.render_mode, self.view = render_mode, view
        self.metadata = dict(self.metadata, render_fps=frames_per_second(control_period))
        self.possible_agents = ['car_%d' % i for i in range(cars)]
        self.agents = []
        frenet = FrenetObserver(self.track, observe_frenet, curvature_ahead, frenet_line)
        self._observation_space = observation_space(self.lidar, observe_pose, frenet)
        self._action_spaces = {agent: action_space() for agent in self.possible_agents}
        self._cars = RaceCars(self.track, self.model, self.lidar, self.possible_agents, observe_pose, frenet=frenet,
                              chase_camera=render_mode is not None and view == 'chase', physics_dt=physics_dt)
        self._views = RaceViews(self._cars, render_mode, view, top_down_scale, 'Tianracer race',
                                self.metadata['render_fps'])
        self._rng = seeding.np_random()[0]
        self._cycles = 0
        self._stopped = np.zeros(cars, bool)

    @functools.lru_cache(maxsize=None)
    def observation_space(self, agent):
        return self._observation_space

    @functools.lru_cache(maxsize=None)
    def action_space(self, agent):
        return self._action_spaces[agent]

    def reset(self, seed=None, options=None):
        if seed is not None:
            self._rng = seeding.np_random(seed)[0]
        options = options or {}
        for index, params in enumerate(self._cars.car_params(options.get('car_params'), self.possible_agents)):
            self._cars.set_params(index, params)
        world = self._cars.new_world(draw_noise_seed(self._rng))
        given = options.get('poses') or {}
        poses = self.track.start_poses(self._rng, options.get('start'), [given.get(agent) for agent in self.possible_agents],
                                       self.track.grid_pose)
        for index, pose in enumerate(poses):
            self._cars.place(index, pose, world)
        self.agents = list(self.possible_agents)
        self._steps = steps_per_action(self.control_period, world.time_step)
        self._cycles = 0
        self._stopped[:] = False
        scans, state = self._cars.settle()
        observations, infos = self._cars.observations(scans, state), self._cars.infos(state)
        if self.render_mode == 'human':
            self.render()
        cars = len(self.possible_agents)
        return (dict(zip(self.possible_agents, rows(observations, cars))),
                dict(zip(self.possible_agents, rows(infos, cars))))

    def step(self, actions):
        if not self.agents:
            raise RuntimeError('the race is over: call reset()')
        # A car without an action, or stopped, is held still: its action (0, 0).
        moves = np.array([actions[agent] if agent in actions and not self._stopped[i] else (0.0, 0.0)
                          for i, agent in enumerate(self.possible_agents)])
        scans, state, rewards = self._cars.step(moves, self._steps)
        self._cycles += 1
        observations, infos = self._cars.observations(scans, state), self._cars.infos(state)
        cars = len(self.possible_agents)
        car_observations, car_infos = rows(observations, cars), rows(infos, cars)
        crashed, rewards = infos['crashed'].tolist(), rewards.tolist()
        results = ({}, {}, {}, {}, {})
        for i, agent in enumerate(self.possible_agents):
            if agent not in self.agents:
                continue
            terminated = crashed[i]
            for out, value in zip(results, (car_observations[i], rewards[i], terminated,
                                            self._cycles >= self.max_cycles and not terminated, car_infos[i])):
                out[agent] = value
            self._stopped[i] |= terminated
        _, _, terminations, truncations, _ = results
        self.agents = [a for a in self.agents if not (terminations[a] or truncations[a])]
        if self.render_mode == 'human':
            self.render()
        return results

    def render(self):
        """The race's frame (H x W x 3, uint8: every car on the track from above, or their chase cameras
        tiled) for "rgb_array"; None for "human" (shown in the window), without a render_mode, and
        before the first reset."""
        if self.render_mode is None or self._cars.robots[0] is None:
            return None
        everyone = range(len(self.possible_agents))
        if self.view == 'top_down':
            frame = self._views.top_down_frame(everyone)
        else:
            frame = tile([self._views.chase_frame(i) for i in everyone])
        return self._views.show(frame)

    def close(self):
        self._views.close()
        self._cars.worlds = [None] * len(self.possible_agents)
        self._cars.robots = [None] * len(self.possible_agents)
