"""The car's Ackermann geometry, measured from its URDF.

The URDF is the one place where the car's dimensions are written down. Nodes that need them
(cmdvel2gazebo.py) and the tests measure them here instead of repeating numbers: joint origins
are chained from the root link to get each wheel's centre, and the wheel radius is read from the
wheel's collision cylinder.
"""
import math
import xml.etree.ElementTree as ET
from dataclasses import dataclass

import numpy as np

# Joint names of the tutorial's model (and of the official Tianracer).
DEFAULT_JOINTS = {
    'left_rear_wheel': 'left_rear_wheel_joint',
    'right_rear_wheel': 'right_rear_wheel_joint',
    'left_steering_hinge': 'left_steering_hinge_joint',
    'right_steering_hinge': 'right_steering_hinge_joint',
    'left_front_wheel': 'left_front_wheel_joint',
    'right_front_wheel': 'right_front_wheel_joint',
}


@dataclass(frozen=True)
class AckermannGeometry:
    wheelbase: float        # rear axle to front axle (steering hinges), m
    rear_track: float       # between the rear wheel centres, m
    front_track: float      # between the steering hinge axes, m
    wheel_radius: float     # rear wheel radius, m
    max_steer: float        # smallest steering hinge limit, rad (the inside wheel's maximum)


def _rpy_matrix(roll, pitch, yaw):
    """URDF's fixed-axis roll, pitch, yaw: R = Rz(yaw) Ry(pitch) Rx(roll)."""
    cr, sr = math.cos(roll), math.sin(roll)
    cp, sp = math.cos(pitch), math.sin(pitch)
    cy, sy = math.cos(yaw), math.sin(yaw)
    return np.array([
        [cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr],
        [sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr],
        [-sp, cp * sr, cp * cr],
    ])


def _origin_transform(element):
    """4x4 transform of an element's <origin> (identity when absent)."""
    transform = np.eye(4)
    origin = element.find('origin')
    if origin is not None:
        xyz = [float(v) for v in origin.get('xyz', '0 0 0').split()]
        rpy = [float(v) for v in origin.get('rpy', '0 0 0').split()]
        transform[:3, :3] = _rpy_matrix(*rpy)
        transform[:3, 3] = xyz
    return transform


class UrdfModel:
    """Joint tree of a URDF document, enough to place joint frames in the root link's frame."""

    def __init__(self, urdf_xml):
        try:
            self.root = ET.fromstring(urdf_xml)
        except ET.ParseError as e:
            raise ValueError('robot_description is not valid XML: %s' % e) from None
        if self.root.tag != 'robot':
            raise ValueError("robot_description has root element <%s>, expected <robot>" % self.root.tag)
        self.joints = {j.get('name'): j for j in self.root.findall('joint')}
        self.links = {l.get('name'): l for l in self.root.findall('link')}
        self._joint_of_child = {j.find('child').get('link'): j for j in self.joints.values()}

    def root_link(self):
        """The root link: the one no joint has as its child; ValueError unless there is one."""
        roots = [name for name in self.links if name not in self._joint_of_child]
        if len(roots) != 1:
            raise ValueError('a robot has one root link; this URDF has %s' % (roots or 'none'))
        return roots[0]

    def joint(self, name):
        try:
            return self.joints[name]
        except KeyError:
            raise ValueError("joint '%s' is not in the URDF (it has: %s); pass the right joint "
                             "name as a parameter" % (name, ', '.join(sorted(self.joints)))) from None

    def joint_frame(self, name):
        """Transform of a joint's frame (= its child link's frame at joint position 0) in the root link."""
        transform = _origin_transform(self.joint(name))
        parent = self.joint(name).find('parent').get('link')
        while parent in self._joint_of_child:
            joint = self._joint_of_child[parent]
            transform = _origin_transform(joint) @ transform
            parent = joint.find('parent').get('link')
        return transform

    def joint_position(self, name):
        return self.joint_frame(name)[:3, 3]

    def joint_limits(self, name):
        limit = self.joint(name).find('limit')
        if limit is None:
            raise ValueError("joint '%s' has no <limit> in the URDF" % name)
        return float(limit.get('lower', 0.0)), float(limit.get('upper', 0.0))

    def wheel_radius(self, joint_name):
        """Radius of the cylinder (or sphere) collision of a joint's child link."""
        link_name = self.joint(joint_name).find('child').get('link')
        for collision in self.links[link_name].findall('collision'):
            for shape in ('cylinder', 'sphere'):
                geometry = collision.find('geometry/' + shape)
                if geometry is not None:
                    return float(geometry.get('radius'))
        raise ValueError("link '%s' of joint '%s' has no cylinder or sphere collision to take "
                         "the wheel radius from" % (link_name, joint_name))


def ackermann_geometry(urdf_xml, joints=None):
    """Measure wheelbase, tracks, wheel radius and steering limit from URDF text.

    joints maps the roles in DEFAULT_JOINTS to joint names, for models that name them otherwise.
    """
    names = dict(DEFAULT_JOINTS, **(joints or {}))
    model = UrdfModel(urdf_xml)
    pos = {role: model.joint_position(joint) for role, joint in names.items()}
    rear_axle_x = (pos['left_rear_wheel'][0] + pos['right_rear_wheel'][0]) / 2.0
    front_axle_x = (pos['left_steering_hinge'][0] + pos['right_steering_hinge'][0]) / 2.0
    steer_limits = [abs(v) for side in ('left', 'right')
                    for v in model.joint_limits(names[side + '_steering_hinge'])]
    return AckermannGeometry(
        wheelbase=float(front_axle_x - rear_axle_x),
        rear_track=float(abs(pos['left_rear_wheel'][1] - pos['right_rear_wheel'][1])),
        front_track=float(abs(pos['left_steering_hinge'][1] - pos['right_steering_hinge'][1])),
        wheel_radius=model.wheel_radius(names['left_rear_wheel']),
        max_steer=min(steer_limits),
    )
