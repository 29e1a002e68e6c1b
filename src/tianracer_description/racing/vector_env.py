"""N cars racing, each on its own copy of the track, stepped in one C++ call (bullet_plant.CarBatch:
the worlds side by side on a thread pool with the GIL released): Gymnasium's VectorEnv, registered as
the environments' vector_entry_point, so gymnasium.make_vec('Tianracer-RaceTrack-v0', num_envs=N)
makes one. Each car is RaceEnv's (same observations, actions, rewards and ends; see env.py).

Autoreset is SAME_STEP (declared in metadata): a car whose episode ends is reset within the same
step; the step returns its first observation of the next episode, and infos carry "final_obs" and
"final_info" (with the "_final_obs" / "_final_info" masks) of the one that ended. Each sub-env has a
generator of its own, seeded from reset(seed=) as seed, seed + 1, ...
"""
import numpy as np
from gymnasium import spaces
from gymnasium.utils import seeding
from gymnasium.vector import AutoresetMode, VectorEnv
from gymnasium.vector.utils import batch_space

from tianracer_description import bullet_plant
from tianracer_description.racing.car import CarModel
from tianracer_description.racing.env import (STATE, CarRun, LidarDescription, RaceTrack, observation_space,
                                              observe, steps_per_action)


class RaceVectorEnv(VectorEnv):
    metadata = {'autoreset_mode': AutoresetMode.SAME_STEP, 'render_modes': []}

    def __init__(self, num_envs, world_file, centerline=None, urdf=None, controllers=None, max_speed=2.0,
                 control_period=0.01, observe_pose=False, max_episode_steps=None, threads=0):
        if num_envs < 1:
            raise ValueError('num_envs is 1 or more; got %r' % (num_envs,))
        self.num_envs = num_envs
        self.track = RaceTrack(world_file, centerline)
        self.model = CarModel(urdf, controllers, max_speed)
        self.control_period = control_period
        self.observe_pose = observe_pose
        self.max_episode_steps = max_episode_steps
        self.lidar = LidarDescription(self.model)
        self.range_max = self.lidar.range_max
        self.single_observation_space = observation_space(self.lidar.rays, self.range_max, observe_pose)
        self.single_action_space = spaces.Box(-1.0, 1.0, (2,), np.float32)
        self.observation_space = batch_space(self.single_observation_space, num_envs)
        self.action_space = batch_space(self.single_action_space, num_envs)
        self._batch = bullet_plant.CarBatch(num_envs, threads)
        self._runs = [CarRun(self.track, self.model) for _ in range(num_envs)]
        self._rngs = [seeding.np_random()[0] for _ in range(num_envs)]
        self._elapsed = np.zeros(num_envs, np.int64)
        self._steps = None

    def _reset_one(self, i, pose=None):
        run = self._runs[i]
        run.reset(self._batch, i, pose or self.track.start_pose(self._rngs[i]))
        self._elapsed[i] = 0

    def _stack(self, observations):
        return {key: np.stack([o[key] for o in observations]) for key in observations[0]}

    def reset(self, *, seed=None, options=None):
        super().reset(seed=seed)
        if seed is not None:
            seeds = [seed + i for i in range(self.num_envs)] if isinstance(seed, int) else list(seed)
            self._rngs = [seeding.np_random(s)[0] for s in seeds]
        poses = (options or {}).get('poses') or [None] * self.num_envs
        for i in range(self.num_envs):
            self._reset_one(i, poses[i])
        self._steps = steps_per_action(self.control_period, self._runs[0].world.time_step)
        held = np.array([self.model.commands((0.0, 0.0))] * self.num_envs)
        scans, state = self._batch.step(held, 1)
        observations = [observe(scans[i], state[i], self.range_max, self.observe_pose) for i in range(self.num_envs)]
        infos = self._infos([run.info(state[i]) for i, run in enumerate(self._runs)])
        return self._stack(observations), infos

    def _infos(self, per_env):
        infos = {}
        for i, info in enumerate(per_env):
            infos = self._add_info(infos, info, i)
        return infos

    def step(self, actions):
        if self._steps is None:
            raise RuntimeError('call reset() before step()')
        actions = np.asarray(actions, dtype=np.float64).reshape(self.num_envs, 2)
        commands = np.array([self.model.commands(a) for a in actions])
        scans, state = self._batch.step(commands, self._steps)
        self._elapsed += 1
        rewards = np.array([run.advance(state[i]) for i, run in enumerate(self._runs)])
        terminated = state[:, STATE['crashed']] > 0
        truncated = (self._elapsed >= self.max_episode_steps) & ~terminated if self.max_episode_steps else \
            np.zeros(self.num_envs, bool)
        observations = [observe(scans[i], state[i], self.range_max, self.observe_pose) for i in range(self.num_envs)]
        infos = self._infos([run.info(state[i]) for i, run in enumerate(self._runs)])
        done = np.flatnonzero(terminated | truncated)
        if len(done):
            final_obs = np.array([None] * self.num_envs, dtype=object)
            final_info = [{}] * self.num_envs
            for i in done:
                final_obs[i], final_info[i] = observations[i], {k: v[i] for k, v in infos.items() if not k.startswith('_')}
                self._reset_one(i)
            # The reset cars' first observation: one step held still, the others not stepped.
            for i in done:
                observations[i], infos = self._first_observation(i, infos)
            mask = np.zeros(self.num_envs, bool)
            mask[done] = True
            infos['final_obs'], infos['_final_obs'] = final_obs, mask
            infos['final_info'], infos['_final_info'] = self._infos(final_info), mask
        return self._stack(observations), rewards, terminated, truncated, infos

    def _first_observation(self, i, infos):
        """Car i's first observation after its reset: its world stepped once with the car held still,
        through a batch of its own (the other cars wait for the next step)."""
        single = bullet_plant.CarBatch(1, 1)
        run = self._runs[i]
        self.model.bind(single, 0, run.world, run.robot)
        scans, state = single.step(np.array([self.model.commands((0.0, 0.0))]), 1)
        return observe(scans[0], state[0], self.range_max, self.observe_pose), self._add_info(infos, run.info(state[0]), i)

    def close_extras(self, **kwargs):
        for run in self._runs:
            run.world = run.robot = None
