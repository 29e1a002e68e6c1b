"""What meshes cost the car (`make bench-meshes`).

Instructions per step, counted under callgrind as bench/step_cost.py counts them ((Ir(long) -
Ir(short)) / (long - short) steps): the Tianracer driving its rear wheels at 1 m/s on the empty world
(a ground plane) and on a world of meshes in its place: a 10 m square floor of 128 triangles and a
ring of 42 wall segments (504 triangles) 3 m around the car. And the lidar's rays per second (1081
rays over 270 degrees, 10 m) on the mesh world, timed (this machine, whatever else runs on it).
The subject is the C++ program bench/mesh_world_cost.cpp (built by `make build`).
"""
import math
import os
import subprocess
import tempfile

from step_cost import callgrind_total  # beside this file
from tianracer_description.tianracer import tianracer_urdf

STEPS_SHORT, STEPS_LONG = 500, 1500
WALL_SEGMENTS, WALL_RADIUS = 42, 3.0


def write_obj(path, boxes=(), grid=None):
    """An OBJ of axis boxes turned about z ((centre, size, yaw) each) and/or a floor grid (half, n)."""
    lines, count = [], 0
    for (cx, cy, cz), (sx, sy, sz), yaw in boxes:
        c, s = math.cos(yaw), math.sin(yaw)
        for i in range(8):
            x, y, z = (sx if i & 4 else -sx) / 2, (sy if i & 2 else -sy) / 2, (sz if i & 1 else -sz) / 2
            lines.append('v %f %f %f' % (cx + c * x - s * y, cy + s * x + c * y, cz + z))
        for a, b, d in [(0, 1, 3), (0, 3, 2), (4, 6, 7), (4, 7, 5), (0, 4, 5), (0, 5, 1),
                        (2, 3, 7), (2, 7, 6), (0, 2, 6), (0, 6, 4), (1, 5, 7), (1, 7, 3)]:
            lines.append('f %d %d %d' % (count + a + 1, count + b + 1, count + d + 1))
        count += 8
    if grid:
        half, n = grid
        for i in range(n + 1):
            for j in range(n + 1):
                lines.append('v %f %f 0' % (-half + 2 * half * i / n, -half + 2 * half * j / n))
        for i in range(n):
            for j in range(n):
                a = count + i * (n + 1) + j + 1
                lines += ['f %d %d %d' % (a, a + n + 1, a + n + 2), 'f %d %d %d' % (a, a + n + 2, a + 1)]
    with open(path, 'w') as f:
        f.write('\n'.join(lines) + '\n')


def binary():
    devel = os.environ.get('CATKIN_DEVEL_PREFIX') or next(
        p for p in os.environ.get('CMAKE_PREFIX_PATH', '').split(':') if p.endswith('devel'))
    return os.path.join(devel, 'lib', 'tianracer_description', 'mesh_world_cost')


def instructions(args, workdir, tag):
    return callgrind_total([binary()] + args, os.path.join(workdir, 'callgrind.' + tag))


def per_step(urdf, meshes, workdir, tag):
    short = instructions([urdf, str(STEPS_SHORT)] + meshes, workdir, tag + '.short')
    long = instructions([urdf, str(STEPS_LONG)] + meshes, workdir, tag + '.long')
    return (long - short) / (STEPS_LONG - STEPS_SHORT)


def main():
    with tempfile.TemporaryDirectory() as workdir:
        urdf = os.path.join(workdir, 'tianracer.urdf')
        with open(urdf, 'w') as f:
            f.write(tianracer_urdf())
        floor, walls = os.path.join(workdir, 'floor.obj'), os.path.join(workdir, 'walls.obj')
        write_obj(floor, grid=(5.0, 8))
        length = 2 * math.pi * WALL_RADIUS / WALL_SEGMENTS
        write_obj(walls, boxes=[((WALL_RADIUS * math.cos(a), WALL_RADIUS * math.sin(a), 0.15), (0.05, length, 0.3), a)
                                for a in (2 * math.pi * k / WALL_SEGMENTS for k in range(WALL_SEGMENTS))])
        empty = per_step(urdf, [], workdir, 'empty')
        meshes = per_step(urdf, [floor, walls], workdir, 'meshes')
        print('instructions per step, the car driving: empty world %.1fk, mesh floor (128 triangles) and '
              'walls (%d triangles) %.1fk: %.2fx' % (empty / 1000, 12 * WALL_SEGMENTS, meshes / 1000, meshes / empty))
        rays = subprocess.run([binary(), urdf, '--rays', '200', floor, walls], check=True, capture_output=True,
                              text=True).stdout.strip()
        print('lidar on the mesh world: ' + rays)


if __name__ == '__main__':
    main()
