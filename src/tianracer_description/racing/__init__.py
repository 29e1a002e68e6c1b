"""Racing on the plant for learning at scale: Gymnasium environments (one car: RaceEnv; N cars in N
worlds stepped in one C++ call: RaceVectorEnv), a PettingZoo multi-car race (RaceParallelEnv), the
follow-the-gap baseline and pure pursuit, the tracks' centre lines, and f1tenth's maps as tracks.

Importing this registers the environments with Gymnasium:

    import gymnasium
    import tianracer_description.racing
    env = gymnasium.make('Tianracer-RaceTrack-v0')                   # worlds/race_track.world
    env = gymnasium.make('Tianracer-RaceCircuit-v0')                 # worlds/race_circuit.world
    envs = gymnasium.make_vec('Tianracer-RaceTrack-v0', num_envs=8)  # RaceVectorEnv
    env = gymnasium.make('Tianracer-Map-v0', map='Spielberg/Spielberg_map.yaml')  # f1tenth's tracks

(or gymnasium.make('tianracer_description.racing:Tianracer-RaceTrack-v0'), which imports it).
"""
import gymnasium

from tianracer_description.tianracer import PEANUT_MAP, RACE_CIRCUIT_WORLD, RACE_TRACK_WORLD

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

# A map in f1tenth's format (map_server's YAML and image, with <name>_centerline.csv or
# <name>_raceline.csv beside it): map= its YAML; worlds/peanut_map.yaml when none is given.
gymnasium.register(
    id='Tianracer-Map-v0',
    entry_point='tianracer_description.racing.env:RaceEnv',
    vector_entry_point='tianracer_description.racing.vector_env:RaceVectorEnv',
    max_episode_steps=MAX_EPISODE_STEPS,
    kwargs={'map': PEANUT_MAP},
)
