#!/usr/bin/env python3
"""Writes compat/gazebo_ros/worlds/rubble.world: Gazebo's worlds/rubble.world for the plant
(rubble_world.launch), its pile of rubble written out as models.

Gazebo's world asks its libRubblePlugin (a world plugin) for COUNT pieces at load, each drawn afresh
on every run: 2x4 boards (0.6096 to 2.4384 m long, 0.1016 x 0.0508 m) or cinder blocks (0.2032 x
0.2032 x 0.4064 m), one or the other with even odds, of a mass uniform in [MIN_MASS, MAX_MASS], placed
uniformly in the box BOTTOM_RIGHT..TOP_LEFT (raised where its half height would put it below the
box's floor), turned by roll in [0, pi], pitch in [-0.1, 0.1], yaw in [0, pi]; named rubble_0,
rubble_1, ... The plant has no world plugins: this draws the pieces once, from those distributions
with a fixed seed, and writes them as the models the plugin would insert, so every run starts from
the same pile. Three things differ:
- The plugin lets pieces start inside one another, the walls and the ground (it lifts a piece by
  half its unturned height only), and the first steps fling them apart at up to 100 m/s (the plant
  warns of each; in a trial most of the pile left the world). Here a piece inside the ground is
  lifted clear; one across a wall is drawn again; one inside an earlier piece is drawn again where
  the plugin draws (REDRAWS times), then along SPREAD_X of the walls' length (REDRAWS times more),
  then raised until clear. The pile lies some 3 m along the walls, not 1, and settles within 2 s.
- The plugin's inertia swaps ixx and iyy (a board's moment about its length is taken as the one
  about its width): with it the plant's pile kept chattering (pieces at 0.1 to 1.5 m/s after 6 s);
  here each box has its own moments.
- The plugin's <velocity_decay> (0.01) is left out: the plant has no velocity decay.
Run it again after changing SEED or the numbers below; the world file is committed.
"""
import itertools
import math
import os
import random

SEED = 41
COUNT = 100
BOTTOM_RIGHT = (-0.5, -1.0, 0.0)
TOP_LEFT = (0.5, 1.0, 0.4)
MIN_MASS, MAX_MASS = 0.1, 1.0
BOARD = (0.6096, 2.4384, 0.1016, 0.0508)  # a 2x4: 2 to 8 feet long, 4 by 2 inches
CINDER_BLOCK = (0.2032, 0.2032, 0.4064)   # a standard US cinder block
WALLS = (((0.0, -1.1, 0.5), (5.0, 0.2, 1.0)), ((0.0, 1.1, 0.5), (5.0, 0.2, 1.0)))  # centre, size
REDRAWS = 20      # draws of a piece inside earlier ones before it is drawn along the walls instead
SPREAD_X = (-1.5, 1.5)  # m, where along the walls then (REDRAWS times more)
RAISE_STEP = 0.01  # m, how far a piece with no room at all is raised at a time
OUT = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))),
                   'compat', 'gazebo_ros', 'worlds', 'rubble.world')

HEADER = """<?xml version="1.0"?>
<!-- Gazebo's worlds/rubble.world for the plant (rubble_world.launch), written by
     tools/make_rubble_world.py: the ground plane, the sun, two static walls (right_wall and
     left_wall, 5 x 0.2 x 1 m at y -1.1 and 1.1) and between them a pile of %d free pieces of rubble,
     rubble_0 to rubble_%d, 2x4 boards and cinder blocks that fall into place.
     What differs: Gazebo's pile is made at load by its libRubblePlugin, drawn afresh on every run
     and starting with pieces inside one another; the plant has no world plugins, so this pile was
     drawn once (seed %d) from the plugin's distributions of size, mass, place and turn, the same on
     every run, each piece clear of the others (redrawn or raised: the pile lies some 3 m along the
     walls, not 1), with its box's own moments of inertia (the plugin swaps ixx and iyy) and no
     velocity decay. The walls are Gazebo/Wood, a textured material the plant does not read: here a
     plain wood colour. -->
<sdf version="1.6">
  <world name="default">
    <include>
      <uri>model://ground_plane</uri>
    </include>
    <include>
      <uri>model://sun</uri>
    </include>
"""

WALL = """    <model name="{name}">
      <static>true</static>
      <pose>0 {y} 0.5 0 0 0</pose>
      <link name="link">
        <collision name="collision">
          <geometry><box><size>5 0.2 1.0</size></box></geometry>
        </collision>
        <visual name="visual">
          <geometry><box><size>5 0.2 1.0</size></box></geometry>
          <material><ambient>0.5 0.36 0.22 1</ambient><diffuse>0.5 0.36 0.22 1</diffuse></material>
        </visual>
      </link>
    </model>
"""

PIECE = """    <model name="{name}">
      <pose>{pose}</pose>
      <link name="link">
        <inertial>
          <mass>{mass:.4f}</mass>
          <inertia>
            <ixx>{ixx:.6g}</ixx><iyy>{iyy:.6g}</iyy><izz>{izz:.6g}</izz><ixy>0</ixy><ixz>0</ixz><iyz>0</iyz>
          </inertia>
        </inertial>
        <collision name="collision">
          <geometry><box><size>{size}</size></box></geometry>
        </collision>
        <visual name="visual">
          <geometry><box><size>{size}</size></box></geometry>
        </visual>
      </link>
    </model>
"""


def axes(rpy):
    """The columns of the rotation of an SDF pose's roll, pitch, yaw (Rz Ry Rx): the box's own axes."""
    (cr, sr), (cp, sp), (cy, sy) = [(math.cos(a), math.sin(a)) for a in rpy]
    return ((cy * cp, sy * cp, -sp), (cy * sp * sr - sy * cr, sy * sp * sr + cy * cr, cp * sr),
            (cy * sp * cr + sy * sr, sy * sp * cr - cy * sr, cp * cr))


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def overlap(a, b):
    """Whether two turned boxes (centre, axes, half sizes) intersect: no separating axis among their
    face normals and the cross products of their edges."""
    (ca, ua, ha), (cb, ub, hb) = a, b
    between = [q - p for p, q in zip(ca, cb)]
    crosses = [(u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])
               for u, v in itertools.product(ua, ub)]
    candidates = list(ua) + list(ub) + crosses
    for axis in candidates:
        if dot(axis, axis) < 1e-12:
            continue  # parallel edges: their faces' normals already test it
        reach = sum(h * abs(dot(u, axis)) for h, u in zip(ha + hb, ua + ub))
        if abs(dot(between, axis)) > reach:
            return False
    return True


def lowest_point(box):
    centre, u, half = box
    return centre[2] - sum(h * abs(v[2]) for h, v in zip(half, u))


def piece(rng, i, placed):
    board = rng.randint(0, 1) == 0
    mass = rng.uniform(MIN_MASS, MAX_MASS)
    w, d, h = (rng.uniform(BOARD[0], BOARD[1]), BOARD[2], BOARD[3]) if board else CINDER_BLOCK
    half = (w / 2, d / 2, h / 2)
    walls = [(c, ((1, 0, 0), (0, 1, 0), (0, 0, 1)), tuple(v / 2 for v in size)) for c, size in WALLS]
    for attempt in itertools.count():
        xyz = [rng.uniform(lo, hi) for lo, hi in zip(BOTTOM_RIGHT, TOP_LEFT)]
        if attempt >= REDRAWS:  # no room where the plugin draws: along the walls' length
            xyz[0] = rng.uniform(*SPREAD_X)
        rpy = (rng.uniform(0.0, 3.1415), rng.uniform(-0.1, 0.1), rng.uniform(0.0, 3.1415))
        # the plugin's rule: the piece's half height above the floor of the box it is drawn in
        xyz[2] = max(xyz[2], BOTTOM_RIGHT[2] + h * 0.5)
        box = (xyz, axes(rpy), half)
        # inside the ground: the plugin lifts by the unturned half height only
        xyz[2] += max(0.0, -lowest_point(box))
        # across a wall (raising would leave it on the wall's top): drawn again; inside an earlier
        # piece: drawn again (REDRAWS times where the plugin draws, REDRAWS more along the walls)
        if any(overlap(box, wall) for wall in walls):
            continue
        if attempt >= 2 * REDRAWS or not any(overlap(box, other) for other in placed):
            break
    while any(overlap(box, other) for other in placed):  # no room there either: on top of the pile
        xyz[2] += RAISE_STEP
    placed.append(box)
    return PIECE.format(name='rubble_%d' % i, pose=' '.join('%.4f' % v for v in xyz + list(rpy)), mass=mass,
                        size='%.4f %.4f %.4f' % (w, d, h), ixx=mass / 12 * (d * d + h * h),
                        iyy=mass / 12 * (h * h + w * w), izz=mass / 12 * (w * w + d * d))


def main():
    rng = random.Random(SEED)
    text = HEADER % (COUNT, COUNT - 1, SEED)
    text += WALL.format(name='right_wall', y=-1.1) + WALL.format(name='left_wall', y=1.1)
    placed = []
    text += ''.join(piece(rng, i, placed) for i in range(COUNT))
    text += '  </world>\n</sdf>\n'
    with open(OUT, 'w') as f:
        f.write(text)
    print('wrote %s (%d pieces)' % (OUT, COUNT))


if __name__ == '__main__':
    main()
