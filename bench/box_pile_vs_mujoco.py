"""What free SDF bodies cost the plant next to MuJoCo on the same scene, measured side by side in one run.

Two scenes of 100 free boxes (0.2 m cubes, 1 kg, friction 1) on a ground plane, 1 ms steps, each
built once for each simulator from the same numbers: the plant reads an SDF world (each box a
<model> that is not <static>), MuJoCo an MJCF (each box a body with a free joint).
  falling pile   the boxes in a 5 x 5 x 4 block, 2 cm apart, dropped from 0.5 m: they land on the
                 floor and on each other. Steps per second over the first simulated second.
  resting        the boxes 0.5 m apart on the floor, settled for 2 simulated s first: the share of one
                 core each simulator needs to keep real time once they are at rest (Gazebo's ODE
                 auto-disables resting bodies; the plant deactivates them as Bullet does).
The machine is shared and noisy: every figure is the median over ROUNDS rounds that visit both
simulators in turn, each ratio taken within a round. MuJoCo steps through `mujoco.mj_step`, one
Python call a step (about a microsecond of the hundreds a step of this scene costs); the plant
through `world.step(n)`. The figures also go to bench/out/box_pile_vs_mujoco.json. Run:
`source .ws/devel/setup.bash; /usr/bin/python3 bench/box_pile_vs_mujoco.py`.
"""
import json
import os
import platform
import statistics
import time

import mujoco

from tianracer_description import bullet_plant

BENCH = os.path.dirname(os.path.abspath(__file__))
OUTPUT_JSON = os.path.join(BENCH, 'out', 'box_pile_vs_mujoco.json')
ROUNDS = int(os.environ.get("ROUNDS", "5"))
TIME_STEP = 0.001
SIZE, MASS, MU = 0.2, 1.0, 1.0
INERTIA = MASS * 2 * SIZE * SIZE / 12  # a solid cube's, about any axis through its centre
PILE_STEPS = 1000
SETTLE_STEPS = 2000
RESTING_STEPS = 2000


def pile_positions():
    """5 x 5 x 4 boxes, 2 cm apart, the lowest layer 0.5 m up."""
    pitch = SIZE + 0.02
    return [((i - 2) * pitch, (j - 2) * pitch, 0.5 + k * pitch) for k in range(4) for j in range(5) for i in range(5)]


def resting_positions():
    """10 x 10 boxes 0.5 m apart, just above the floor."""
    return [((i - 4.5) * 0.5, (j - 4.5) * 0.5, SIZE / 2 + 0.001) for j in range(10) for i in range(10)]


def plant_world(positions):
    box = f'<box><size>{SIZE} {SIZE} {SIZE}</size></box>'
    models = ''.join(f"""
<model name="box_{n}"><pose>{x} {y} {z} 0 0 0</pose><link name="link">
  <inertial><mass>{MASS}</mass><inertia><ixx>{INERTIA}</ixx><iyy>{INERTIA}</iyy><izz>{INERTIA}</izz></inertia></inertial>
  <collision name="collision"><geometry>{box}</geometry>
    <surface><friction><ode><mu>{MU}</mu><mu2>{MU}</mu2></ode></friction></surface></collision>
  <visual name="visual"><geometry>{box}</geometry></visual></link></model>""" for n, (x, y, z) in enumerate(positions))
    world = bullet_plant.World.from_sdf(f"""<sdf version="1.6"><world name="boxes">
<physics type="ode"><max_step_size>{TIME_STEP}</max_step_size></physics>
<include><uri>model://ground_plane</uri></include>{models}</world></sdf>""")
    world.echo = False
    return world


def mujoco_model(positions):
    h = SIZE / 2
    bodies = ''.join(f"""
<body name="box_{n}" pos="{x} {y} {z}"><freejoint/>
  <geom type="box" size="{h} {h} {h}" mass="{MASS}" friction="{MU} 0.005 0.0001"/></body>"""
                     for n, (x, y, z) in enumerate(positions))
    return mujoco.MjModel.from_xml_string(f"""<mujoco><option timestep="{TIME_STEP}"/>
<worldbody><geom type="plane" size="0 0 1" friction="{MU} 0.005 0.0001"/>{bodies}</worldbody></mujoco>""")


def plant_heights(world):
    return [world.robot(name).base_pose()[2] for name in world.robots]


def timed(step, n):
    start = time.perf_counter()
    step(n)
    return time.perf_counter() - start


def mujoco_stepper(model, data):
    def step(n):
        for _ in range(n):
            mujoco.mj_step(model, data)
    return step


def pile_round():
    world = plant_world(pile_positions())
    model = mujoco_model(pile_positions())
    data = mujoco.MjData(model)
    ours = PILE_STEPS / timed(world.step, PILE_STEPS)
    theirs = PILE_STEPS / timed(mujoco_stepper(model, data), PILE_STEPS)
    # sanity: everything fell and stopped above the floor (a box through the floor is cheap)
    lowest = min(plant_heights(world)), min(data.xpos[1:, 2])
    return ours, theirs, lowest


def resting_round():
    world = plant_world(resting_positions())
    model = mujoco_model(resting_positions())
    data = mujoco.MjData(model)
    world.step(SETTLE_STEPS)
    mujoco_stepper(model, data)(SETTLE_STEPS)
    simulated = RESTING_STEPS * TIME_STEP
    ours = timed(world.step, RESTING_STEPS) / simulated
    theirs = timed(mujoco_stepper(model, data), RESTING_STEPS) / simulated
    return ours, theirs, (min(plant_heights(world)), min(data.xpos[1:, 2]))


def main():
    pile, resting = [], []
    for _ in range(ROUNDS):
        pile.append(pile_round())
        resting.append(resting_round())
    figures = {
        'machine': f'{platform.processor() or platform.machine()}, {os.cpu_count()} cores',
        'falling_pile_steps_per_s': {'ours': statistics.median(r[0] for r in pile),
                                     'mujoco': statistics.median(r[1] for r in pile)},
        'falling_pile_ratio_ours_over_mujoco': statistics.median(r[0] / r[1] for r in pile),
        'resting_core_share_at_real_time': {'ours': statistics.median(r[0] for r in resting),
                                            'mujoco': statistics.median(r[1] for r in resting)},
        'resting_ratio_ours_over_mujoco': statistics.median(r[0] / r[1] for r in resting),
        'lowest_box_centre_m': {'pile': pile[-1][2], 'resting': resting[-1][2]},
    }
    print(f"100 free boxes, 1 ms steps, medians of {ROUNDS} rounds on {figures['machine']}")
    print(f"  falling pile  steps/s  ours {figures['falling_pile_steps_per_s']['ours']:9.0f}   "
          f"mujoco {figures['falling_pile_steps_per_s']['mujoco']:9.0f}   "
          f"ours/mujoco {figures['falling_pile_ratio_ours_over_mujoco']:.2f}")
    print(f"  resting       core share at real time  ours {100 * figures['resting_core_share_at_real_time']['ours']:6.1f} %   "
          f"mujoco {100 * figures['resting_core_share_at_real_time']['mujoco']:6.1f} %   "
          f"ours/mujoco {figures['resting_ratio_ours_over_mujoco']:.2f}")
    print(f"  lowest box centre (ours, mujoco; {SIZE / 2} m is on the floor): pile {pile[-1][2]}, "
          f"resting {resting[-1][2]}")
    os.makedirs(os.path.dirname(OUTPUT_JSON), exist_ok=True)
    with open(OUTPUT_JSON, 'w') as out:
        json.dump(figures, out, indent=2)


if __name__ == '__main__':
    main()
