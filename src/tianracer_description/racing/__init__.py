"""Racing on the plant for learning at scale: Gymnasium environments (one car: RaceEnv; N cars in N
worlds stepped in one C++ call: RaceVectorEnv), a PettingZoo multi-car race (RaceParallelEnv), the
follow-the-gap baseline, and the tracks' centre lines.

Importing this registers the environments with Gymnasium:

    import gymnasium
    import tianracer_description.racing
    env = gymnasium.make('Tianracer-RaceTrack-v0')                   # worlds/race_track.world
    env = gymnasium.make('Tianracer-RaceCircuit-v0')                 # worlds/race_circuit.world
    envs = gymnasium.make_vec('Tianracer-RaceTrack-v0', num_envs=8)  # RaceVectorEnv

(or gymnasium.make('tianracer_description.racing:Tianracer-RaceTrack-v0'), which imports it).
"""
import gymnasium

from tianracer_description.tianracer import RACE_CIRCUIT_WORLD, RACE_TRACK_WORLD

MAX_EPISODE_STEPS = 2000  # 20 s of racing at the default 10 ms control period

# Our tracks, by the name Gymnasium knows them by: Tianracer-<name>-v0.
TRACKS = {'RaceTrack': RACE_TRACK_WORLD, 'RaceCircuit': RACE_CIRCUIT_WORLD}

for _name, _world in TRACKS.items():
    gymnasium.register(
        id='Tianracer-%s-v0' % _name,
        entry_point='tianracer_description.racing.env:RaceEnv',
        vector_entry_point='tianracer_description.racing.vector_env:RaceVectorEnv',
        max_episode_steps=MAX_EPISODE_STEPS,
        kwargs={'world_file': _world},
    )
