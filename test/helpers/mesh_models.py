"""Worlds of models written as Gazebo's exporters write them, for the tests of a model's free links: a
race track that is one model that is not static, its floor and its walls two 1665 kg mesh links that no
joint joins (as a robot maker ships its car's track), and meshes that no convex shape makes up."""
import math
import os
import struct
import xml.etree.ElementTree as ET

from suite_paths import REPOSITORY

RACE_TRACK = os.path.join(REPOSITORY, 'worlds', 'race_track.world')
RACE_TRACK_CENTERLINE = os.path.join(REPOSITORY, 'worlds', 'race_track.centerline.csv')
TRACK_LINK_MASS = 1665.0  # kg, each link's
FLOOR_THICKNESS = 0.02    # m: the car drives this far above the ground plane


def box_triangles(centre, size, yaw=0.0):
    """The 12 triangles of a box (outward, counter-clockwise) about z by yaw, each three (x, y, z)."""
    c, s = math.cos(yaw), math.sin(yaw)
    corners = []
    for i in range(8):
        x, y, z = (size[0] if i & 4 else -size[0]) / 2, (size[1] if i & 2 else -size[1]) / 2, \
            (size[2] if i & 1 else -size[2]) / 2
        corners.append((centre[0] + c * x - s * y, centre[1] + s * x + c * y, centre[2] + z))
    faces = [(0, 1, 3), (0, 3, 2), (4, 6, 7), (4, 7, 5), (0, 4, 5), (0, 5, 1),
             (2, 3, 7), (2, 7, 6), (0, 2, 6), (0, 6, 4), (1, 5, 7), (1, 7, 3)]
    return [tuple(corners[k] for k in face) for face in faces]


def write_stl(path, triangles):
    """A binary STL of the triangles."""
    with open(path, 'wb') as f:
        f.write(b'\0' * 80 + struct.pack('<I', len(triangles)))
        for triangle in triangles:
            f.write(struct.pack('<3f', 0, 0, 0))
            for corner in triangle:
                f.write(struct.pack('<3f', *corner))
            f.write(b'\0\0')


def race_track_walls():
    """The wall boxes of worlds/race_track.world: (centre, size, yaw) each."""
    walls = []
    for model in ET.parse(RACE_TRACK).getroot().iter('model'):
        if not model.get('name', '').startswith(('inner_', 'outer_')):
            continue
        x, y, z, _, _, yaw = (float(v) for v in model.findtext('pose').split())
        size = [float(v) for v in model.find('link/collision/geometry/box/size').text.split()]
        walls.append(((x, y, z), size, yaw))
    return walls


def mesh_link(name, mesh, mass, inertia, colour):
    ixx, iyy, izz = inertia
    return f"""      <link name="{name}">
        <inertial><mass>{mass}</mass>
          <inertia><ixx>{ixx}</ixx><ixy>0</ixy><ixz>0</ixz><iyy>{iyy}</iyy><iyz>0</iyz><izz>{izz}</izz></inertia>
        </inertial>
        <collision name="collision"><geometry><mesh><uri>{mesh}</uri></mesh></geometry></collision>
        <visual name="visual"><geometry><mesh><uri>{mesh}</uri></mesh></geometry>
          <material><diffuse>{colour}</diffuse></material></visual>
      </link>
"""


def write_mesh_race_track(directory):
    """worlds/race_track.world's walls as an exporter writes such a track: one model, `race_track`, not
    static, of two links that no joint joins, `base_link` (the floor, a slab under the whole track)
    and `wall_link` (every wall in one STL), each 1665 kg, with a <state> that puts the model and its
    links where the file does. Returns the world file's path; the centre line is RACE_TRACK_CENTERLINE."""
    walls = race_track_walls()
    xs = [x for (x, _, _), _, _ in walls]
    ys = [y for (_, y, _), _, _ in walls]
    low_x, high_x, low_y, high_y = min(xs) - 1, max(xs) + 1, min(ys) - 1, max(ys) + 1
    floor_size = (high_x - low_x, high_y - low_y, FLOOR_THICKNESS)
    write_stl(os.path.join(directory, 'floor.stl'),
              box_triangles(((low_x + high_x) / 2, (low_y + high_y) / 2, FLOOR_THICKNESS / 2), floor_size))
    write_stl(os.path.join(directory, 'walls.stl'),
              [t for centre, size, yaw in walls for t in box_triangles(centre, size, yaw)])
    # A slab's and a ring's inertia, roughly: what an exporter computes does not matter at rest.
    m = TRACK_LINK_MASS
    slab = (m * floor_size[1] ** 2 / 12, m * floor_size[0] ** 2 / 12, m * (floor_size[0] ** 2 + floor_size[1] ** 2) / 12)
    path = os.path.join(directory, 'mesh_race_track.world')
    link_state = '<link name="{}"><pose>0 0 0 0 0 0</pose><velocity>0 0 0 0 0 0</velocity></link>'
    with open(path, 'w') as f:
        f.write(f"""<?xml version="1.0"?>
<sdf version="1.6">
  <world name="mesh_race_track">
    <include><uri>model://ground_plane</uri></include>
    <include><uri>model://sun</uri></include>
    <physics type="ode"><max_step_size>0.001</max_step_size><real_time_factor>1</real_time_factor></physics>
    <model name="race_track">
      <pose>0 0 0 0 0 0</pose>
{mesh_link('base_link', 'floor.stl', m, slab, '0.3 0.3 0.3 1')}{mesh_link('wall_link', 'walls.stl', m, slab, '0.8 0.1 0.1 1')}    </model>
    <state world_name="mesh_race_track">
      <model name="race_track"><pose>0 0 0 0 0 0</pose>{link_state.format('base_link')}{link_state.format('wall_link')}</model>
    </state>
  </world>
</sdf>
""")
    return path


def u_channel_triangles(length=1.0, width=0.6, height=0.4, wall=0.1):
    """A closed U-shaped channel along x (a floor and two side walls, one solid): no convex shape makes
    it up, and its hull would fill the channel."""
    # The U's cross-section in (y, z), counter-clockwise, extruded along x.
    w, h, t = width / 2, height, wall
    section = [(-w, 0), (w, 0), (w, h), (w - t, h), (w - t, t), (-w + t, t), (-w + t, h), (-w, h)]
    x0, x1 = -length / 2, length / 2
    triangles = []
    n = len(section)
    for i in range(n):  # the sides
        (ya, za), (yb, zb) = section[i], section[(i + 1) % n]
        triangles += [((x0, ya, za), (x0, yb, zb), (x1, yb, zb)), ((x0, ya, za), (x1, yb, zb), (x1, ya, za))]
    # The two ends: the section as three convex parts (the base and the two walls), fans each.
    for part in ([0, 1, 4, 5], [1, 2, 3, 4], [5, 6, 7, 0]):
        for x, order in ((x0, part[::-1]), (x1, part)):
            corners = [(x,) + section[k] for k in order]
            triangles += [(corners[0], corners[j], corners[j + 1]) for j in range(1, len(corners) - 1)]
    return triangles
