"""What a race track made of meshes costs (`make bench-meshes`): an oval of STL walls (~500
triangles) on an OBJ floor, written here, against the empty world.

- instructions per step (callgrind, as bench/step_cost.py counts them): the car driving at 1 m/s
  with the five controllers on the mesh track's straight, and in the empty world; their ratio.
- lidar rays/s on the mesh track: two identical cars on it, one with its lidar on, stepped in turns
  of one lidar period (25 steps); a scan costs the median difference of their turns, and rays/s is
  1081 / that (the twin method of bench/plant_vs_peers.py).
"""
import math
import os
import statistics
import tempfile
import time

from step_cost import driving_car, instructions_per_step
from tianracer_description.tianracer import tianracer_urdf

HALF_WIDTH = 0.6        # m, centre line to each wall
STRAIGHT = 10.0         # m
RADIUS = 3.0            # m, of the centre line in the bends
SEGMENTS_STRAIGHT, SEGMENTS_BEND = 2, 9  # wall boxes per straight and per bend, per wall
WALL_HEIGHT, WALL_THICKNESS = 0.2, 0.05
ROUNDS, TURNS = 7, 40


def centre_line():
    """Points of the oval's centre line, counter-clockwise from the origin along +x."""
    points = [(STRAIGHT * i / SEGMENTS_STRAIGHT, 0.0) for i in range(SEGMENTS_STRAIGHT)]
    for i in range(SEGMENTS_BEND):
        a = -math.pi / 2 + math.pi * i / SEGMENTS_BEND
        points.append((STRAIGHT + RADIUS * math.cos(a), RADIUS + RADIUS * math.sin(a)))
    points += [(STRAIGHT - STRAIGHT * i / SEGMENTS_STRAIGHT, 2 * RADIUS) for i in range(SEGMENTS_STRAIGHT)]
    for i in range(SEGMENTS_BEND):
        a = math.pi / 2 + math.pi * i / SEGMENTS_BEND
        points.append((RADIUS * math.cos(a), RADIUS + RADIUS * math.sin(a)))
    return points


def box_triangles(a, b, side):
    """A wall box along the segment a-b, offset `side` metres to its left (negative: right)."""
    dx, dy = b[0] - a[0], b[1] - a[1]
    length = math.hypot(dx, dy)
    nx, ny = -dy / length, dx / length
    inner, outer = side - WALL_THICKNESS / 2, side + WALL_THICKNESS / 2
    base = [(p[0] + nx * o, p[1] + ny * o) for p in (a, b) for o in (inner, outer)]
    corners = [(x, y, z) for (x, y) in base for z in (0.0, WALL_HEIGHT)]  # 8 corners
    faces = [(0, 2, 3), (0, 3, 1), (4, 5, 7), (4, 7, 6), (0, 1, 5), (0, 5, 4),
             (2, 6, 7), (2, 7, 3), (0, 4, 6), (0, 6, 2), (1, 3, 7), (1, 7, 5)]
    return [[corners[i] for i in f] for f in faces]


def write_track(directory):
    points = centre_line()
    triangles = []
    for k in range(len(points)):
        a, b = points[k], points[(k + 1) % len(points)]
        for side in (HALF_WIDTH, -HALF_WIDTH):
            triangles += box_triangles(a, b, side)
    walls = os.path.join(directory, 'walls.stl')
    with open(walls, 'w') as f:
        f.write('solid walls\n')
        for t in triangles:
            f.write('facet normal 0 0 0\nouter loop\n')
            for v in t:
                f.write('vertex %.6f %.6f %.6f\n' % v)
            f.write('endloop\nendfacet\n')
        f.write('endsolid walls\n')
    floor = os.path.join(directory, 'floor.obj')
    with open(floor, 'w') as f:  # a 20 x 10 grid of quads under the whole oval
        x0, x1, y0, y1 = -RADIUS - 1, STRAIGHT + RADIUS + 1, -1.0, 2 * RADIUS + 1
        for j in range(11):
            for i in range(21):
                f.write('v %.4f %.4f 0\n' % (x0 + (x1 - x0) * i / 20, y0 + (y1 - y0) * j / 10))
        for j in range(10):
            for i in range(20):
                v = j * 21 + i + 1
                f.write('f %d %d %d\nf %d %d %d\n' % (v, v + 1, v + 22, v, v + 22, v + 21))
    world = os.path.join(directory, 'mesh_track.world')
    with open(world, 'w') as f:
        f.write(f"""<?xml version="1.0"?><sdf version="1.6"><world name="mesh_track">
  <physics type="ode"><max_step_size>0.001</max_step_size><real_time_factor>1</real_time_factor></physics>
  <model name="below"><static>true</static><pose>0 0 -1 0 0 0</pose><link name="link">
    <collision name="plane"><geometry><plane><normal>0 0 1</normal></plane></geometry></collision></link></model>
  <model name="track"><static>true</static><link name="link">
    <collision name="floor"><geometry><mesh><uri>file://{floor}</uri></mesh></geometry></collision>
    <collision name="walls"><geometry><mesh><uri>file://{walls}</uri></mesh></geometry></collision>
  </link></model>
</world></sdf>""")
    return world, len(triangles)


def lidar_rays_per_second(urdf, world_path):
    with open(world_path) as f:
        sdf = f.read()
    scanning, silent = driving_car(urdf, sdf), driving_car(urdf, sdf)
    scanning[1].enable_sensor('lidar')
    rounds = []
    for _ in range(ROUNDS):
        for world, _, _ in (scanning, silent):
            world.reset_world()
        differences = []
        for turn in range(TURNS):
            took = {}
            for name, (world, _, _) in (('scanning', scanning), ('silent', silent))[::1 if turn % 2 == 0 else -1]:
                start = time.perf_counter()
                world.step(25)
                took[name] = time.perf_counter() - start
            differences.append(took['scanning'] - took['silent'])
        rounds.append(1081 / statistics.median(differences))
    return statistics.median(rounds)


def main():
    urdf = tianracer_urdf()
    with tempfile.TemporaryDirectory() as workdir:
        world_path, wall_triangles = write_track(workdir)
        urdf_path = os.path.join(workdir, 'tianracer.urdf')
        with open(urdf_path, 'w') as f:
            f.write(urdf)
        empty = instructions_per_step(urdf_path, workdir)
        track = instructions_per_step(urdf_path, workdir, world_path)
        print('mesh track: %d wall triangles (STL), a 400-triangle floor (OBJ)' % wall_triangles)
        print('instructions per step: empty world %.1fk, mesh track %.1fk, ratio %.2f'
              % (empty / 1000, track / 1000, track / empty))
        print('lidar on the mesh track: %.1f M rays/s (median of %d rounds)'
              % (lidar_rays_per_second(urdf, world_path) / 1e6, ROUNDS))


if __name__ == '__main__':
    main()
