"""What free boxes as Bullet rigid bodies would give: bench/box_pile_vs_mujoco.py's falling pile (100
boxes, 1 ms steps, the first simulated second) in PyBullet, each box a btRigidBody
(useMaximalCoordinates: Bullet's rigid sequential impulse solver) or a 0-link btMultiBody, with 10
solver iterations as the plant's, beside the plant and MuJoCo in one run; medians of ROUNDS rounds,
each ratio within its round. Run: `source .ws/devel/setup.bash; ROUNDS=5 /usr/bin/python3
bench/box_pile_rigid_bodies.py` (PyBullet from PyPI, as `make bench` installs it).
"""
import os
import statistics
import sys

import mujoco
import pybullet as p

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import box_pile_vs_mujoco as b  # noqa: E402


def pybullet_pile(maximal):
    c = p.connect(p.DIRECT)
    p.setGravity(0, 0, -9.8, physicsClientId=c)
    p.setTimeStep(b.TIME_STEP, physicsClientId=c)
    p.setPhysicsEngineParameter(numSolverIterations=10, physicsClientId=c)
    plane = p.createCollisionShape(p.GEOM_PLANE, physicsClientId=c)
    p.createMultiBody(0, plane, physicsClientId=c)
    box = p.createCollisionShape(p.GEOM_BOX, halfExtents=[b.SIZE / 2] * 3, physicsClientId=c)
    for pos in b.pile_positions():
        body = p.createMultiBody(b.MASS, box, basePosition=pos, useMaximalCoordinates=maximal, physicsClientId=c)
        p.changeDynamics(body, -1, lateralFriction=b.MU, physicsClientId=c)
    def step(n):
        for _ in range(n):
            p.stepSimulation(physicsClientId=c)
    return c, step


def main():
    rounds = []
    for _ in range(int(os.environ.get('ROUNDS', '5'))):
        world = b.plant_world(b.pile_positions())
        ours = b.PILE_STEPS / b.timed(world.step, b.PILE_STEPS)
        model = b.mujoco_model(b.pile_positions())
        data = mujoco.MjData(model)
        theirs = b.PILE_STEPS / b.timed(b.mujoco_stepper(model, data), b.PILE_STEPS)
        row = [ours, theirs]
        for maximal in (True, False):
            c, step = pybullet_pile(maximal)
            row.append(b.PILE_STEPS / b.timed(step, b.PILE_STEPS))
            p.disconnect(c)
        rounds.append(row)
    med = [statistics.median(r[k] for r in rounds) for k in range(4)]
    ratio = [statistics.median(r[k] / r[1] for r in rounds) for k in range(4)]
    for name, m, q in zip(('plant', 'mujoco', 'pybullet rigid bodies', 'pybullet multibodies'), med, ratio):
        print(f'{name:24s} {m:8.0f} steps/s   {q:.2f}x mujoco')


if __name__ == '__main__':
    main()
