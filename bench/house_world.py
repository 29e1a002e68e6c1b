"""A furnished room as robotics teams ship them, generated: the heavy world of `make bench`.

write_house(directory) writes house.world and its meshes (Wavefront OBJ with MTL materials and PNG
textures, made here from numbers: no one's files are copied): a 14 x 9 m room with a textured wooden
floor mesh and no ground plane, textured walls, 16 bookshelves of 168 books each (every book a
box with its own cover in a texture atlas), 8 round tables, 24 chairs, 30 vases and 20 crates, six
ceiling lamps as point lights and a spot light over the counter, the scene's ambient, no sun: as a
shop or an office world lights itself. Every model is a static <model> of its own with a mesh
visual and a box collision, so the world holds 100+ textured meshes; write_house returns its size.
"""
import math
import os

import matplotlib
matplotlib.use('Agg')
import matplotlib.image  # noqa: E402 (after choosing the backend)
import numpy as np  # noqa: E402

ROOM = (14.0, 9.0, 3.0)  # m: x, y, height
TEXTURE = 256            # texels a side


class ObjWriter:
    """One OBJ: vertices, texture coordinates and triangles, in one material."""

    def __init__(self):
        self.v, self.vt, self.f = [], [], []

    def quad(self, corners, uvs):
        base_v, base_t = len(self.v), len(self.vt)
        self.v += corners
        self.vt += uvs
        for a, b, c in ((0, 1, 2), (0, 2, 3)):
            self.f.append(((base_v + a, base_t + a), (base_v + b, base_t + b), (base_v + c, base_t + c)))

    def box(self, centre, size, uv_box=(0, 0, 1, 1), yaw=0.0):
        """An axis box turned by yaw about z, each face mapped onto uv_box (u0 v0 u1 v1)."""
        cx, cy, cz = centre
        hx, hy, hz = (s / 2 for s in size)
        c, s = math.cos(yaw), math.sin(yaw)

        def at(x, y, z):
            return (cx + c * x - s * y, cy + s * x + c * y, cz + z)
        u0, v0, u1, v1 = uv_box
        uv = [(u0, v0), (u1, v0), (u1, v1), (u0, v1)]
        for sign in (1, -1):
            self.quad([at(sign * hx, -sign * hy, -hz), at(sign * hx, sign * hy, -hz), at(sign * hx, sign * hy, hz),
                       at(sign * hx, -sign * hy, hz)], uv)
            self.quad([at(sign * hx, sign * hy, -hz), at(-sign * hx, sign * hy, -hz), at(-sign * hx, sign * hy, hz),
                       at(sign * hx, sign * hy, hz)], uv)
            self.quad([at(-hx, -sign * hy, sign * hz), at(hx, -sign * hy, sign * hz), at(hx, sign * hy, sign * hz),
                       at(-hx, sign * hy, sign * hz)], uv)

    def lathe(self, profile, around, centre=(0, 0, 0)):
        """A surface of revolution about z: profile [(radius, z)], `around` segments, UV wrapped."""
        cx, cy, cz = centre
        for i in range(len(profile) - 1):
            (r0, z0), (r1, z1) = profile[i], profile[i + 1]
            for k in range(around):
                a0, a1 = 2 * math.pi * k / around, 2 * math.pi * (k + 1) / around
                u0, u1, v0, v1 = k / around, (k + 1) / around, i / (len(profile) - 1), (i + 1) / (len(profile) - 1)
                self.quad([(cx + r0 * math.cos(a0), cy + r0 * math.sin(a0), cz + z0),
                           (cx + r0 * math.cos(a1), cy + r0 * math.sin(a1), cz + z0),
                           (cx + r1 * math.cos(a1), cy + r1 * math.sin(a1), cz + z1),
                           (cx + r1 * math.cos(a0), cy + r1 * math.sin(a0), cz + z1)],
                          [(u0, v0), (u1, v0), (u1, v1), (u0, v1)])

    def triangles(self):
        return len(self.f)

    def write(self, path, material, texture):
        with open(path[:-4] + '.mtl', 'w') as f:
            f.write('newmtl %s\nKa 1 1 1\nKd 1 1 1\nKs 0.1 0.1 0.1\nNs 20\nmap_Kd %s\n' % (material, texture))
        lines = ['mtllib %s' % os.path.basename(path[:-4] + '.mtl'), 'usemtl %s' % material]
        lines += ['v %.5f %.5f %.5f' % p for p in self.v]
        lines += ['vt %.5f %.5f' % t for t in self.vt]
        lines += ['f ' + ' '.join('%d/%d' % (v + 1, t + 1) for v, t in face) for face in self.f]
        with open(path, 'w') as f:
            f.write('\n'.join(lines) + '\n')


def textures(directory, rng):
    """The PNGs: wood, plaster, a book-cover atlas (8 x 8 covers), glaze, cardboard, fabric."""
    n = TEXTURE
    y, x = np.mgrid[0:n, 0:n] / n
    images = {
        'wood': np.stack([0.55 + 0.1 * np.sin(40 * y + 3 * np.sin(6 * x)), 0.40 + 0.08 * np.sin(40 * y),
                          0.25 + 0.05 * np.sin(40 * y)], axis=2),
        'plaster': np.stack([0.85 + 0.04 * rng.random((n, n))] * 2 + [0.78 + 0.04 * rng.random((n, n))], axis=2),
        'glaze': np.stack([0.3 + 0.3 * np.sin(12 * x) ** 2, 0.35 + 0.2 * y, 0.6 + 0.3 * np.cos(9 * y) ** 2], axis=2),
        'cardboard': np.stack([0.62 + 0.05 * np.sin(80 * x), 0.48 + 0.04 * np.sin(80 * x), 0.30 + 0 * x], axis=2),
        'fabric': np.stack([0.2 + 0.1 * ((np.floor(16 * x) + np.floor(16 * y)) % 2), 0.25 + 0 * x, 0.45 + 0 * x], axis=2),
    }
    covers = np.zeros((n, n, 3))
    cell = n // 8
    for i in range(8):
        for j in range(8):
            colour = rng.random(3) * 0.7 + 0.15
            covers[i * cell:(i + 1) * cell, j * cell:(j + 1) * cell] = colour
            covers[i * cell + cell // 4:i * cell + cell // 3, j * cell + 2:(j + 1) * cell - 2] = 1 - colour
    images['books'] = covers
    for name, image in images.items():
        matplotlib.image.imsave(os.path.join(directory, name + '.png'), np.clip(image, 0, 1))


def model_sdf(name, pose, mesh, collision_size, collision_offset=(0, 0, 0)):
    ox, oy, oz = collision_offset
    return """  <model name="{name}"><static>true</static><pose>{pose}</pose><link name="link">
    <collision name="collision"><pose>{ox} {oy} {oz} 0 0 0</pose><geometry><box><size>{size}</size></box></geometry></collision>
    <visual name="visual"><geometry><mesh><uri>meshes/{mesh}</uri></mesh></geometry></visual>
  </link></model>
""".format(name=name, pose=' '.join('%.4f' % v for v in pose), mesh=mesh, ox=ox, oy=oy, oz=oz,
           size=' '.join('%.4f' % s for s in collision_size))


def write_house(directory, seed=7):
    """Writes directory/house.world and directory/meshes/; returns {'models', 'triangles', 'lights'}."""
    rng = np.random.default_rng(seed)
    meshes = os.path.join(directory, 'meshes')
    os.makedirs(meshes, exist_ok=True)
    textures(meshes, rng)
    lx, ly, lz = ROOM
    models, triangles = [], 0

    def add(name, obj, texture, pose, collision_size, collision_offset=(0, 0, 0)):
        nonlocal triangles
        obj.write(os.path.join(meshes, name + '.obj'), name, texture + '.png')
        triangles += obj.triangles()
        models.append(model_sdf(name, pose, name + '.obj', collision_size, collision_offset))

    floor = ObjWriter()
    for i in range(14):  # boards, each its own strip of the texture
        floor.quad([(-lx / 2 + i, -ly / 2, 0), (-lx / 2 + i + 1, -ly / 2, 0), (-lx / 2 + i + 1, ly / 2, 0),
                    (-lx / 2 + i, ly / 2, 0)], [(0, 0), (1, 0), (1, 4), (0, 4)])
    add('floor', floor, 'wood', (0, 0, 0, 0, 0, 0), (lx, ly, 0.1), (0, 0, -0.05))
    for k, (x, y, sx, sy) in enumerate([(0, ly / 2, lx, 0.2), (0, -ly / 2, lx, 0.2), (lx / 2, 0, 0.2, ly),
                                        (-lx / 2, 0, 0.2, ly)]):
        wall = ObjWriter()
        wall.box((0, 0, lz / 2), (sx, sy, lz), (0, 0, max(sx, sy) / 2, lz / 2))
        add('wall_%d' % k, wall, 'plaster', (x, y, 0, 0, 0, 0), (sx, sy, lz), (0, 0, lz / 2))
    # bookshelves: a carcass and 4 rows of 42 books, each book a box with a cover of the atlas
    shelf_places = [(-5.5 + 2.2 * (k % 6), -4.1 if k < 6 else 4.1, 0 if k < 6 else math.pi) for k in range(12)]
    shelf_places += [(-2.0 + 2.2 * k, 0.0, math.pi / 2 * (k % 2)) for k in range(4)]
    for k, (x, y, yaw) in enumerate(shelf_places):
        shelf = ObjWriter()
        for z in (0.05, 0.55, 1.05, 1.55, 2.05):
            shelf.box((0, 0, z), (2.0, 0.4, 0.04), (0, 0, 0.2, 0.05))
        for side in (-1, 1):
            shelf.box((side * 1.0, 0, 1.05), (0.04, 0.4, 2.1), (0, 0, 0.05, 0.2))
        for row, z in enumerate((0.07, 0.57, 1.07, 1.57)):
            position = -0.95
            for b in range(42):
                width, height = 0.03 + 0.015 * rng.random(), 0.25 + 0.15 * rng.random()
                cover = rng.integers(64)
                u0, v0 = (cover % 8) / 8, (cover // 8) / 8
                shelf.box((position + width / 2, 0, z + height / 2), (width, 0.28, height),
                          (u0, v0, u0 + 0.125, v0 + 0.125), yaw=0.05 * (rng.random() - 0.5))
                position += width + 0.002
                if position > 0.95:
                    break
        add('bookshelf_%d' % k, shelf, 'books', (x, y, 0, 0, 0, yaw), (2.0, 0.4, 2.1), (0, 0, 1.05))
    # round tables: a lathed top and column, 96 segments
    for k in range(8):
        table = ObjWriter()
        table.lathe([(0.0, 0.75), (0.6, 0.75), (0.6, 0.72), (0.08, 0.70), (0.06, 0.05), (0.3, 0.02), (0.3, 0.0)], 96)
        add('table_%d' % k, table, 'wood', (-4.5 + 3.0 * (k % 4), -1.8 if k < 4 else 2.0, 0, 0, 0, 0),
            (1.2, 1.2, 0.75), (0, 0, 0.375))
    for k in range(24):
        chair = ObjWriter()
        chair.box((0, 0, 0.45), (0.45, 0.45, 0.05), (0, 0, 1, 1))
        chair.box((0, 0.2, 0.75), (0.45, 0.05, 0.6), (0, 0, 1, 1))
        for dx in (-0.2, 0.2):
            for dy in (-0.2, 0.2):
                chair.lathe([(0.02, 0.0), (0.02, 0.43)], 24, (dx, dy, 0))
        t = k // 3
        angle = 2 * math.pi * (k % 3) / 3
        add('chair_%d' % k, chair, 'fabric',
            (-4.5 + 3.0 * (t % 4) + 0.9 * math.cos(angle), (-1.8 if t < 4 else 2.0) + 0.9 * math.sin(angle), 0, 0, 0,
             angle + math.pi / 2), (0.45, 0.45, 1.0), (0, 0, 0.5))
    # vases: lathed bodies of 160 x 23 quads on the tables, the shelves' tops and the floor
    for k in range(30):
        vase = ObjWriter()
        profile = [(0.06 + 0.05 * math.sin(math.pi * i / 23) + 0.02 * math.sin(3 * math.pi * i / 23), 0.4 * i / 23)
                   for i in range(24)]
        vase.lathe(profile, 160)
        if k < 8:
            place = (-4.5 + 3.0 * (k % 4), -1.8 if k < 4 else 2.0, 0.75)
        elif k < 24:
            x, y, _ = shelf_places[k - 8]
            place = (x, y, 2.07)
        else:
            place = (-6.2 + 2.4 * (k - 24), 3.2, 0.0)
        add('vase_%d' % k, vase, 'glaze', place + (0, 0, 0), (0.24, 0.24, 0.4), (0, 0, 0.2))
    for k in range(20):
        crate = ObjWriter()
        crate.box((0, 0, 0.25), (0.6, 0.4, 0.5), (0, 0, 1, 1))
        for dz in (0.1, 0.4):
            crate.lathe([(0.31, dz), (0.31, dz + 0.02)], 4)  # straps
        add('crate_%d' % k, crate, 'cardboard', (5.2 + 0.7 * (k % 3), -3.6 + 0.8 * (k // 3), 0, 0, 0, 0.3 * k),
            (0.6, 0.4, 0.5), (0, 0, 0.25))
    lamps = []
    for k in range(6):
        x, y = -4.5 + 4.5 * (k % 3), -2.2 if k < 3 else 2.2
        lamps.append("""  <light name="ceiling_lamp_{k}" type="point"><pose>{x} {y} 2.9 0 0 0</pose>
    <diffuse>0.5 0.5 0.45 1</diffuse><specular>0.1 0.1 0.1 1</specular>
    <attenuation><range>20</range><constant>0.32</constant><linear>0.01</linear><quadratic>0.03</quadratic></attenuation>
    <cast_shadows>false</cast_shadows></light>
""".format(k=k, x=x, y=y))
    lamps.append("""  <light name="counter_spot" type="spot"><pose>5.5 -1.0 2.9 0 0 0</pose><direction>0 0 -1</direction>
    <diffuse>0.8 0.7 0.5 1</diffuse><specular>0.2 0.2 0.2 1</specular>
    <attenuation><range>10</range><constant>0.5</constant><linear>0.05</linear><quadratic>0.0</quadratic></attenuation>
    <spot><inner_angle>0.6</inner_angle><outer_angle>1.0</outer_angle><falloff>1.0</falloff></spot>
    <cast_shadows>false</cast_shadows></light>
""")
    with open(os.path.join(directory, 'house.world'), 'w') as f:
        f.write("""<?xml version="1.0"?>
<sdf version="1.6"><world name="house">
  <scene><ambient>0.4 0.4 0.4 1</ambient><background>0.7 0.7 0.7 1</background><shadows>true</shadows></scene>
  <physics type="ode"><max_step_size>0.001</max_step_size><real_time_factor>1</real_time_factor>
    <real_time_update_rate>1000</real_time_update_rate></physics>
""" + ''.join(lamps) + ''.join(models) + '</world></sdf>\n')
    return {'models': len(models), 'triangles': triangles, 'lights': len(lamps)}


if __name__ == '__main__':
    import sys
    print(write_house(sys.argv[1] if len(sys.argv) > 1 else '.'))
