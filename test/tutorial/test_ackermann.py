"""cmdvel2gazebo.py's geometry as pure functions, against values worked out by hand for the
Tianracer (L = 0.261 m, tracks 0.1632 m, wheel radius 0.032 m, inside wheel limit 0.6 rad)."""
import math

import pytest

from tianracer_description.ackermann import (STEERING_ANGLE, YAW_RATE, ideal_steering, max_ideal_steering,
                                             wheel_commands)

L, TRACK, RADIUS = 0.261, 0.1632, 0.032
MAX = 0.513217  # atan2(0.261, 0.261 / tan(0.6) + 0.0816)


def commands(speed, steering):
    return wheel_commands(speed, steering, L, TRACK, TRACK, RADIUS, MAX)


def test_max_ideal_steering_puts_the_inside_wheel_at_its_limit():
    assert max_ideal_steering(L, TRACK, 0.6) == pytest.approx(MAX, abs=1e-6)
    assert commands(1.0, MAX).steer_left == pytest.approx(0.6, abs=1e-5)


def test_left_turn_at_0_3_rad_and_1_m_s():
    # r = 0.261 / tan(0.3) = 0.843742 m; inside 0.762142 m, outside 0.925342 m
    c = commands(1.0, 0.3)
    assert c.rear_left == pytest.approx(28.22775, abs=1e-4)   # 31.25 * 0.762142 / 0.843742
    assert c.rear_right == pytest.approx(34.27225, abs=1e-4)
    assert c.steer_left == pytest.approx(0.329938, abs=1e-6)  # atan2(0.261, 0.762142)
    assert c.steer_right == pytest.approx(0.274916, abs=1e-6)  # atan2(0.261, 0.925342)


def test_right_turn_mirrors_the_left_turn():
    left, right = commands(1.0, 0.3), commands(1.0, -0.3)
    assert (right.rear_left, right.rear_right) == pytest.approx((left.rear_right, left.rear_left))
    assert (right.steer_left, right.steer_right) == pytest.approx((-left.steer_right, -left.steer_left))


def test_straight_reverse_and_standstill():
    assert commands(1.0, 0.0) == (31.25, 31.25, 0.0, 0.0)
    assert commands(-0.5, 0.0) == (-15.625, -15.625, 0.0, 0.0)
    reverse = commands(-1.0, 0.3)
    assert (reverse.rear_left, reverse.rear_right) == pytest.approx((-28.22775, -34.27225), abs=1e-4)
    assert reverse.steer_left == pytest.approx(0.329938, abs=1e-6), 'steering does not depend on direction'
    assert commands(0.0, 0.3).rear_left == 0.0


def test_steering_is_clamped_so_the_inside_wheel_stays_within_its_limit():
    assert commands(1.0, 1.0) == commands(1.0, MAX)
    assert commands(1.0, -5.0) == commands(1.0, -MAX)


def test_angular_z_as_a_steering_angle_or_a_yaw_rate():
    assert ideal_steering(1.0, 0.3, STEERING_ANGLE, L) == 0.3
    assert ideal_steering(1.0, 1.0, YAW_RATE, L) == pytest.approx(0.255305, abs=1e-6)  # atan(0.261 * 1 / 1)
    assert ideal_steering(-1.0, 1.0, YAW_RATE, L) == pytest.approx(-0.255305, abs=1e-6)
    assert ideal_steering(0.0, 1.0, YAW_RATE, L) == 0.0
    assert ideal_steering(1.0, 0.0, YAW_RATE, L) == 0.0
    with pytest.raises(ValueError, match='twist_mode'):
        ideal_steering(1.0, 1.0, 'twist_mode', L)


def test_yaw_rate_mode_turns_at_the_asked_rate():
    steering = ideal_steering(0.5, 0.4, YAW_RATE, L)
    assert 0.5 * math.tan(steering) / L == pytest.approx(0.4)


def test_circle_radius_of_points_on_a_known_circle():
    from tianracer_description.path_metrics import circle_radius
    angles = [0.1 * i for i in range(40)]
    points = [(2.0 + 0.7 * math.cos(a), -1.0 + 0.7 * math.sin(a)) for a in angles]
    assert circle_radius(points) == pytest.approx(0.7, abs=1e-9)


def test_arrays_of_commands_are_each_element_as_a_number_gives_it():
    import numpy as np
    speeds, steerings = np.array([1.0, -0.5, 0.7, 0.0]), np.array([0.3, 0.0, -0.45, 2.0])
    many = commands(speeds, steerings)
    for k in range(4):
        assert [field[k] for field in many] == list(commands(float(speeds[k]), float(steerings[k])))
