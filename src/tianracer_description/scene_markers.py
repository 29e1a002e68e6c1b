"""The world's visuals as a visualization_msgs/MarkerArray, so that rviz draws the track as well as the
robots (rviz's RobotModel draws those from robot_description; the world has no description rviz
reads). Made from what the plant publishes, latched, on /gazebo/scene (bullet_plant/scene.h): boxes,
cylinders and spheres as rviz's own shapes, planes as thin squares, meshes by file (file://, which
rviz loads with its own Collada, STL and OBJ readers; Collada and OBJ with their own materials, STL,
which has none, in the visual's colour).

The markers are in one frame, `frame_id`: the world as the robots' TF tree sees it. The plant's
ground-truth odometry (gazebo_ros_p3d's rule, the tutorial's car) puts odom at the world's origin,
so odom is the default; a robot whose drive controller publishes odom from its wheels needs a frame
tied to the world (a localiser's map) instead.
"""
import math

from geometry_msgs.msg import Pose
from std_msgs.msg import ColorRGBA
from visualization_msgs.msg import Marker, MarkerArray

PLANE_SIZE = 100.0  # m: Gazebo's ground_plane model draws its plane 100 m square
PLANE_THICKNESS = 0.001  # m: a plane as a box this thin, its top face on the plane


def quaternion_product(a, b):
    """a * b of (x, y, z, w) quaternions: b's rotation, then a's."""
    ax, ay, az, aw = a
    bx, by, bz, bw = b
    return (aw * bx + ax * bw + ay * bz - az * by,
            aw * by - ax * bz + ay * bw + az * bx,
            aw * bz + ax * by - ay * bx + az * bw,
            aw * bw - ax * bx - ay * by - az * bz)


def rotate(q, v):
    """The vector v turned by the unit quaternion q (x, y, z, w)."""
    x, y, z, _ = quaternion_product(quaternion_product(q, (v[0], v[1], v[2], 0.0)), (-q[0], -q[1], -q[2], q[3]))
    return (x, y, z)


def z_to(normal):
    """The shortest rotation (x, y, z, w) that takes +z to `normal`."""
    nx, ny, nz = normal
    length = math.sqrt(nx * nx + ny * ny + nz * nz) or 1.0
    nx, ny, nz = nx / length, ny / length, nz / length
    if nz < -1 + 1e-12:
        return (1.0, 0.0, 0.0, 0.0)  # upside down: half a turn about x
    # (z x n, 1 + z . n), normalised: half the angle between them
    x, y, z, w = -ny, nx, 0.0, 1.0 + nz
    norm = math.sqrt(x * x + y * y + w * w)
    return (x / norm, y / norm, z / norm, w / norm)


def pose_msg(xyz, quaternion):
    pose = Pose()
    pose.position.x, pose.position.y, pose.position.z = xyz
    o = pose.orientation
    o.x, o.y, o.z, o.w = quaternion
    return pose


def marker_of(visual):
    """One world visual of the scene as a Marker in its model's namespace (frame, id and stamp left to
    the caller); None for a kind rviz has no marker for. Nothing rviz would warn of: no text, a unit
    quaternion, no zero scale."""
    # A namespace per model: rviz lists them in the display, each to show or hide, as gzclient's models.
    marker = Marker(ns=visual['link'].split('::')[0], action=Marker.ADD)
    xyz, quaternion = visual['pose'][:3], visual['pose'][3:]
    r, g, b, a = visual['colour']
    marker.color = ColorRGBA(r, g, b, a)
    kind = visual['kind']
    if kind == 'box':
        marker.type = Marker.CUBE
        marker.scale.x, marker.scale.y, marker.scale.z = visual['size']
    elif kind == 'sphere':
        marker.type = Marker.SPHERE
        marker.scale.x = marker.scale.y = marker.scale.z = 2 * visual['radius']
    elif kind == 'cylinder':
        marker.type = Marker.CYLINDER  # along z, as URDF's and SDF's
        marker.scale.x = marker.scale.y = 2 * visual['radius']
        marker.scale.z = visual['length']
    elif kind == 'plane':
        marker.type = Marker.CUBE
        sx, sy = visual.get('size') or (PLANE_SIZE, PLANE_SIZE)
        marker.scale.x, marker.scale.y, marker.scale.z = sx, sy, PLANE_THICKNESS
        quaternion = quaternion_product(quaternion, z_to(visual['normal']))
        below = rotate(quaternion, (0.0, 0.0, -PLANE_THICKNESS / 2))
        xyz = [p + d for p, d in zip(xyz, below)]
    elif kind == 'mesh':
        marker.type = Marker.MESH_RESOURCE
        marker.mesh_resource = 'file://' + visual['mesh']
        marker.scale.x, marker.scale.y, marker.scale.z = visual.get('scale') or (1.0, 1.0, 1.0)
        if not visual['mesh'].lower().endswith('.stl'):
            # rviz: embedded materials as they are when the colour is all zero (any other tints them)
            marker.mesh_use_embedded_materials = True
            marker.color = ColorRGBA(0.0, 0.0, 0.0, 0.0)
    else:
        return None
    marker.pose = pose_msg(xyz, quaternion)
    return marker


def scene_markers(scene, frame_id, stamp):
    """The scene's world visuals (not the robots') as a MarkerArray in `frame_id`, after a DELETEALL
    that clears those of an earlier scene."""
    markers = MarkerArray()
    clear = Marker(action=Marker.DELETEALL)
    clear.header.frame_id = frame_id
    markers.markers.append(clear)
    for visual in scene['visuals']:
        if visual['model']:
            continue  # a robot's link: rviz's RobotModel draws it
        marker = marker_of(visual)
        if marker is None:
            continue
        marker.header.frame_id, marker.header.stamp = frame_id, stamp
        marker.id = len(markers.markers)
        markers.markers.append(marker)
    return markers
