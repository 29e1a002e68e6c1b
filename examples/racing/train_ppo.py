"""PPO on the vector environment with stable-baselines3 (PyTorch on the CPU): the worked example, a
program of its own (examples/, as f1tenth_gym keeps its examples), run with the workspace sourced:

    /usr/bin/python3 examples/racing/train_ppo.py --envs 4 --timesteps 100000 --out ppo_race.zip

trains a MultiInputPolicy on RaceVectorEnv (all cars stepped in one C++ call) and prints the mean
return of the untrained and the trained policy over the same seeded evaluation episodes.

stable-baselines3 has a vector env of its own (VecEnv); Sb3VecEnv presents a Gymnasium VectorEnv
that resets in the same step (AutoresetMode.SAME_STEP, as RaceVectorEnv does, and as SB3 expects)
as one: the ended episode's last observation goes in "terminal_observation", a time limit's end is
"TimeLimit.truncated".
"""
import argparse
import time

import numpy as np
from gymnasium.vector import AutoresetMode
from stable_baselines3 import PPO
from stable_baselines3.common.vec_env import VecEnv, VecMonitor

from tianracer_description.racing import MAX_EPISODE_STEPS, TRACKS
from tianracer_description.racing.env import RaceEnv
from tianracer_description.racing.vector_env import RaceVectorEnv


class Sb3VecEnv(VecEnv):
    """A Gymnasium VectorEnv with SAME_STEP autoreset as stable-baselines3's VecEnv."""

    def __init__(self, vector_env):
        if vector_env.metadata.get('autoreset_mode') != AutoresetMode.SAME_STEP:
            raise ValueError('stable-baselines3 resets an ended episode in the same step: the vector env must '
                             'declare AutoresetMode.SAME_STEP; %r declares %r'
                             % (type(vector_env).__name__, vector_env.metadata.get('autoreset_mode')))
        self.vector_env = vector_env
        super().__init__(vector_env.num_envs, vector_env.single_observation_space, vector_env.single_action_space)
        self._actions = None

    def reset(self):
        seed = self._seeds[0] if self._seeds and self._seeds[0] is not None else None
        observations, _ = self.vector_env.reset(seed=seed)
        self._reset_seeds()
        return observations

    def step_async(self, actions):
        self._actions = actions

    def step_wait(self):
        observations, rewards, terminated, truncated, infos = self.vector_env.step(self._actions)
        done = terminated | truncated
        per_env = [{} for _ in range(self.num_envs)]
        for i in np.flatnonzero(done):
            per_env[i]['terminal_observation'] = infos['final_obs'][i]
            per_env[i]['TimeLimit.truncated'] = bool(truncated[i] and not terminated[i])
        return observations, rewards.astype(np.float32), done, per_env

    def close(self):
        self.vector_env.close()

    # What SB3 asks of the sub-envs; the cars of a RaceVectorEnv share its attributes.
    def get_attr(self, attr_name, indices=None):
        return [getattr(self.vector_env, attr_name)] * len(self._get_indices(indices))

    def set_attr(self, attr_name, value, indices=None):
        setattr(self.vector_env, attr_name, value)

    def env_method(self, method_name, *method_args, indices=None, **method_kwargs):
        return [getattr(self.vector_env, method_name)(*method_args, **method_kwargs)]

    def env_is_wrapped(self, wrapper_class, indices=None):
        return [False] * len(self._get_indices(indices))


def evaluate(policy, world_file, episodes, seed, steps=MAX_EPISODE_STEPS):
    """The mean return of `policy` (observation -> action) over `episodes` seeded episodes of RaceEnv."""
    env = RaceEnv(world_file)
    returns = []
    for episode in range(episodes):
        observation, _ = env.reset(seed=seed + episode)
        total = 0.0
        for _ in range(steps):
            observation, reward, terminated, truncated, _ = env.step(policy(observation))
            total += reward
            if terminated or truncated:
                break
        returns.append(total)
    return float(np.mean(returns))


def model_policy(model):
    return lambda observation: model.predict(observation, deterministic=True)[0]


def train(world_file, envs=4, timesteps=100_000, seed=0, n_steps=256, threads=0):
    """A PPO model trained on `envs` cars of RaceVectorEnv for `timesteps` steps."""
    vector_env = VecMonitor(Sb3VecEnv(RaceVectorEnv(envs, world_file, max_episode_steps=MAX_EPISODE_STEPS,
                                                    threads=threads)))
    model = PPO('MultiInputPolicy', vector_env, n_steps=n_steps, batch_size=256, seed=seed, device='cpu', verbose=0)
    return model.learn(total_timesteps=timesteps)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('--track', default='RaceTrack', help='one of %s, or a world file' % sorted(TRACKS))
    parser.add_argument('--envs', type=int, default=4, help='cars of the vector env')
    parser.add_argument('--timesteps', type=int, default=100_000)
    parser.add_argument('--seed', type=int, default=0)
    parser.add_argument('--episodes', type=int, default=5, help='evaluation episodes, before and after')
    parser.add_argument('--eval-steps', type=int, default=MAX_EPISODE_STEPS)
    parser.add_argument('--out', help='save the trained model here (.zip)')
    args = parser.parse_args(argv)
    world_file = TRACKS.get(args.track, args.track)

    untrained = PPO('MultiInputPolicy', Sb3VecEnv(RaceVectorEnv(1, world_file)), seed=args.seed, device='cpu')
    before = evaluate(model_policy(untrained), world_file, args.episodes, 1000, args.eval_steps)
    print('untrained policy: mean return %.2f m over %d episodes' % (before, args.episodes), flush=True)
    start = time.perf_counter()
    model = train(world_file, args.envs, args.timesteps, args.seed)
    elapsed = time.perf_counter() - start
    print('trained %d steps on %d cars in %.0f s (%.0f steps/s)' % (args.timesteps, args.envs, elapsed,
                                                                   args.timesteps / elapsed), flush=True)
    after = evaluate(model_policy(model), world_file, args.episodes, 1000, args.eval_steps)
    print('trained policy: mean return %.2f m over the same %d episodes' % (after, args.episodes))
    if args.out:
        model.save(args.out)
        print('saved %s' % args.out)
    return 0


if __name__ == '__main__':
    raise SystemExit(main())
