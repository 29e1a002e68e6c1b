"""Ackermann geometry of the tutorial's cmdvel2gazebo.py, as pure functions.

A Twist becomes two rear wheel speeds and two front steering angles: the car turns about a point on
the rear axle line, at radius r = L / tan(delta) from the rear axle's centre for an ideal middle front
wheel angle delta; each wheel turns on its own circle around that point.
"""
import math
from collections import namedtuple

import numpy as np

from tianracer_description import bullet_plant

# rad/s for the rear wheels, rad for the steering hinges
WheelCommands = namedtuple('WheelCommands', 'rear_left rear_right steer_left steer_right')

STEERING_ANGLE = 'steering_angle'  # angular.z is the ideal front wheel's angle (the tutorial's meaning)
YAW_RATE = 'yaw_rate'              # angular.z is the yaw rate (REP 103, teleop_twist_keyboard, nav stacks)


def max_ideal_steering(wheelbase, front_track, max_inside_steer):
    """The ideal middle wheel's angle at which the inside wheel reaches its limit."""
    inside_radius = wheelbase / math.tan(max_inside_steer)
    return math.atan2(wheelbase, inside_radius + front_track / 2.0)


def ideal_steering(linear_x, angular_z, mode, wheelbase):
    """The ideal middle front wheel's angle that a Twist asks for."""
    if mode == STEERING_ANGLE:
        return angular_z
    if mode == YAW_RATE:
        if linear_x == 0.0 or angular_z == 0.0:
            return 0.0
        # A car backing up turns the other way for the same steering.
        return math.atan(wheelbase * angular_z / linear_x)
    raise ValueError("angular mode '%s' is neither '%s' nor '%s'" % (mode, STEERING_ANGLE, YAW_RATE))


def wheel_commands(speed, steering, wheelbase, rear_track, front_track, wheel_radius, max_steering):
    """Rear wheel speeds (rad/s) and steering angles (rad) for a ground speed (m/s) and an ideal
    steering angle (rad), clamped so that the inside wheel stays within its limit: wheel_command_rows'
    columns as the four fields (numbers for numbers, arrays for arrays)."""
    return WheelCommands(*np.moveaxis(wheel_command_rows(speed, steering, wheelbase, rear_track, front_track,
                                                         wheel_radius, max_steering), -1, 0))


def wheel_command_rows(speed, steering, wheelbase, rear_track, front_track, wheel_radius, max_steering):
    """The four commands as the last axis of one array, in WheelCommands' order, for each element of
    speed and steering (numbers: one row of four; the racing environments' cars: a row each). The
    geometry is the plant's (include/bullet_plant/ackermann_wheels.h: the converter script and the
    racing environments share it, in C++ for the environments' every step)."""
    rows = bullet_plant.wheel_command_rows(speed, steering, wheelbase, rear_track, front_track, wheel_radius,
                                           max_steering)
    return rows[0] if np.ndim(speed) == 0 and np.ndim(steering) == 0 and np.ndim(max_steering) == 0 else rows
