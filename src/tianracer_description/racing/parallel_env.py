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
elsewhere than on the grid. One CarBatch steps the world once per step and reads every
car. The same seed and actions give the same observations, bit for bit.
"""
import functools

import numpy as np
from gymnasium import spaces
from gymnasium.utils import seeding
from pettingzoo import ParallelEnv

from tianracer_description import bullet_plant
from tianracer_description.racing import MAX_EPISODE_STEPS
from tianracer_description.racing.car import CarModel, new_world
from tianracer_description.racing.env import (STATE, START_SPREAD, CarRun, LidarDescription, RaceTrack,
                                              observation_space, observe, steps_per_action)

GRID_SPACING = 0.6  # m between a car and the one behind it, along the centre line
GRID_OFFSET = 0.25  # m either side of the centre line: the two columns


class RaceParallelEnv(ParallelEnv):
    metadata = {'name': 'tianracer_race_v0', 'render_modes': []}

    def __init__(self, world_file, cars=2, centerline=None, urdf=None, controllers=None, max_speed=2.0,
                 control_period=0.01, observe_pose=False, max_cycles=MAX_EPISODE_STEPS):
        if cars < 1:
            raise ValueError('a race has 1 car or more; got %r' % (cars,))
        self.track = RaceTrack(world_file, centerline)
        self.model = CarModel(urdf, controllers, max_speed)
        self.control_period, self.observe_pose, self.max_cycles = control_period, observe_pose, max_cycles
        self.possible_agents = ['car_%d' % i for i in range(cars)]
        self.agents = []
        self.lidar = LidarDescription(self.model)
        self.range_max = self.lidar.range_max
        self._observation_space = observation_space(self.lidar.rays, self.range_max, observe_pose)
        self._action_space = spaces.Box(-1.0, 1.0, (2,), np.float32)
        self._runs = {}
        self._batch = None
        self._rng = seeding.np_random()[0]
        self._cycles = 0

    @functools.lru_cache(maxsize=None)
    def observation_space(self, agent):
        return self._observation_space

    @functools.lru_cache(maxsize=None)
    def action_space(self, agent):
        return self._action_space

    def grid_pose(self, index):
        """Where car `index` starts: behind the start line, left and right column by turns, each car
        nudged by the env's generator as RaceEnv's start is."""
        along = -GRID_SPACING * index + self._rng.uniform(-START_SPREAD['along'], START_SPREAD['along']) / 4
        offset = (GRID_OFFSET if index % 2 == 0 else -GRID_OFFSET) + \
            self._rng.uniform(-START_SPREAD['offset'], START_SPREAD['offset']) / 4
        x, y, yaw = self.track.centerline.pose_at(along, offset)
        return x, y, yaw + self._rng.uniform(-START_SPREAD['yaw'], START_SPREAD['yaw']) / 4

    def reset(self, seed=None, options=None):
        if seed is not None:
            self._rng = seeding.np_random(seed)[0]
        world = new_world(self.track.world_file, self.model.controllers)
        self._batch = bullet_plant.CarBatch(len(self.possible_agents), 1)  # one world: one thread steps it
        self._runs = {}
        poses = (options or {}).get('poses') or {}
        for index, agent in enumerate(self.possible_agents):
            run = CarRun(self.track, self.model, name=agent)
            run.join(world, self._batch, index, poses.get(agent) or self.grid_pose(index))
            self._runs[agent] = run
        self.agents = list(self.possible_agents)
        self._steps = steps_per_action(self.control_period, world.time_step)
        self._cycles = 0
        self._stopped = {agent: False for agent in self.possible_agents}
        scans, state = self._batch.step(self._commands({}), 1)
        observations = {agent: self._observe(scans, state, i) for i, agent in enumerate(self.possible_agents)}
        infos = {agent: self._runs[agent].info(state[i]) for i, agent in enumerate(self.possible_agents)}
        return observations, infos

    def _observe(self, scans, state, index):
        return observe(scans[index], state[index], self.range_max, self.observe_pose)

    def _commands(self, actions):
        """Every car's commands: its action while it races, held still once it stopped."""
        still = self.model.commands((0.0, 0.0))
        return np.array([self.model.commands(actions[agent]) if agent in actions and not self._stopped[agent]
                         else still for agent in self.possible_agents])

    def step(self, actions):
        if not self.agents:
            raise RuntimeError('the race is over: call reset()')
        scans, state = self._batch.step(self._commands(actions), self._steps)
        self._cycles += 1
        observations, rewards, terminations, truncations, infos = {}, {}, {}, {}, {}
        for index, agent in enumerate(self.possible_agents):
            if agent not in self.agents:
                continue
            run = self._runs[agent]
            observations[agent] = self._observe(scans, state, index)
            rewards[agent] = run.advance(state[index])
            terminations[agent] = bool(state[index][STATE['crashed']])
            truncations[agent] = self._cycles >= self.max_cycles and not terminations[agent]
            infos[agent] = run.info(state[index])
            if terminations[agent]:
                self._stopped[agent] = True
        self.agents = [a for a in self.agents if not (terminations[a] or truncations[a])]
        return observations, rewards, terminations, truncations, infos

    def close(self):
        self._runs = {}
        self._batch = None
