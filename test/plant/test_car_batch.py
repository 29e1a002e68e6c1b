"""bullet_plant.CarBatch and bullet_plant.Centerline (src/python/car_batch_bindings.cpp,
centerline_bindings.cpp): the centre line's nearest point against a brute-force search, its progress
and errors; a batch's state rows against what the worlds and robots say themselves, progress along
the line summed over steps, a subset of cars stepped alone, no return read as range_max, actions
driven as the converter's Ackermann commands, and errors that name the offending thing."""
import math

import numpy as np
import pytest

from tianracer_description import bullet_plant
from tianracer_description.ackermann import wheel_command_rows
from tianracer_description.racing.car import COMMAND_CONTROLLERS, CarModel, new_world
from tianracer_description.racing.track import Centerline, centerline_file
from tianracer_description.tianracer import RACE_TRACK_WORLD, STEERING_JOINTS

STATE = {name: k for k, name in enumerate(bullet_plant.CarBatch.STATE)}


def nearest_by_brute_force(points, x, y):
    """(s, distance) of the nearest point of the closed polyline, by numpy over every segment."""
    segments = np.roll(points, -1, axis=0) - points
    lengths = np.hypot(segments[:, 0], segments[:, 1])
    along = np.clip(((x - points[:, 0]) * segments[:, 0] + (y - points[:, 1]) * segments[:, 1]) / lengths ** 2, 0, 1)
    nearest = points + along[:, None] * segments
    distances = np.hypot(nearest[:, 0] - x, nearest[:, 1] - y)
    k = int(np.argmin(distances))
    return np.concatenate([[0.0], np.cumsum(lengths)])[k] + along[k] * lengths[k], distances[k]


@pytest.fixture(scope='module')
def track_line():
    return Centerline.from_file(centerline_file(RACE_TRACK_WORLD))


def test_the_nearest_point_is_the_brute_force_one_searched_everywhere_or_near_the_last(track_line):
    points = track_line.points
    rng = np.random.default_rng(3)
    segment = None
    for s in np.linspace(0.0, track_line.length, 400, endpoint=False):
        x, y, _ = track_line.pose_at(s, rng.uniform(-0.5, 0.5))
        everywhere = track_line.project(x, y)
        expected_s, expected_distance = nearest_by_brute_force(points, x, y)
        assert everywhere[0] == pytest.approx(expected_s, abs=1e-9)
        assert abs(everywhere[1]) == pytest.approx(expected_distance, abs=1e-12)
        if segment is not None:  # 5 cm on from the last: well within NEAR_SEGMENTS' reach
            assert track_line.project(x, y, segment) == everywhere
        segment = everywhere[2]


def test_the_offset_is_positive_to_the_left_and_progress_wraps_at_half_a_lap():
    square = Centerline([(0, 0), (4, 0), (4, 4), (0, 4)])  # counter-clockwise, 16 m
    assert square.length == 16.0
    assert square.project(1.0, 0.5) == (1.0, 0.5, 0)  # inside the loop: left of the direction of racing
    assert square.project(1.0, -0.5) == (1.0, -0.5, 0)
    assert square.pose_at(17.0, 0.5) == pytest.approx((1.0, 0.5, 0.0))
    assert square.pose_at(-1.0) == pytest.approx((0.0, 1.0, -math.pi / 2))
    assert square.progress(15.0, 1.0) == 2.0 and square.progress(1.0, 15.0) == -2.0
    assert square.progress(0.0, 7.9) == pytest.approx(7.9) and square.progress(0.0, 8.1) == pytest.approx(-7.9)


@pytest.mark.parametrize('points, message', [
    ([(0, 0), (1, 0)], 'three or more'),
    ([(0, 0), (1, 0), (1, 0), (0, 1)], 'repeats a point at index 1'),
    ([(0, 0), (1, 0), (0, float('nan'))], "point 2 is not finite"),
    ([0, 1, 2, 3], 'array of \\(x, y\\) rows'),
])
def test_a_bad_centre_line_is_refused_naming_its_fault(points, message):
    with pytest.raises(ValueError, match=message):
        Centerline(points)


@pytest.fixture(scope='module')
def model():
    return CarModel()


def batch_of(model, worlds, line=None, threads=1):
    """A CarBatch of one car per world, spawned at the origin and measured along `line`."""
    batch = bullet_plant.CarBatch(len(worlds), threads)
    for i, world in enumerate(worlds):
        model.bind(batch, i, world, model.spawn(world, 'car', (0.0, 0.0, 0.0)), line)
    return batch


def actions(count, steering=0.0, speed=0.5):
    """Every car's action: steering and speed shares of its largest (of the model's 2 m/s: 1 m/s)."""
    return np.tile([steering, speed], (count, 1))


def test_state_rows_say_what_the_world_and_robot_say_and_progress_sums_along_the_line(model, track_line):
    world = new_world(RACE_TRACK_WORLD, model.controllers)
    batch = batch_of(model, [world], track_line)
    robot = world.robot('car')
    start = robot.base_pose()  # where the batch was set: the spawn pose as the plant placed it
    gained = 0.0
    for _ in range(60):
        scans, state = batch.drive(actions(1, steering=0.2), 10)
        gained += state[0, STATE['centerline_gained']]
    row = state[0]
    pose = robot.base_pose()
    assert row[STATE['time']] == world.time == pytest.approx(0.6)
    assert (row[STATE['x']], row[STATE['y']]) == (pose[0], pose[1])
    left, right = (robot.joint_state(joint)[0] for joint in STEERING_JOINTS)
    assert (row[STATE['steer_left']], row[STATE['steer_right']], row[STATE['steering']]) == (left, right, (left + right) / 2)
    assert row[STATE['steering']] > 0.05, 'steering left'
    assert scans.shape == (1, 1081) and scans.dtype == np.float32
    s, offset, _ = track_line.project(pose[0], pose[1])
    assert (row[STATE['centerline_s']], row[STATE['centerline_offset']]) == (s, offset)
    # the start is a hair behind the start line (s near the lap's length): progress wraps
    assert gained == pytest.approx(track_line.progress(track_line.project(start[0], start[1])[0], s), abs=1e-12)
    assert gained > 0.3, 'the car drove forwards along the line (0.6 s at up to 1 m/s)'
    assert row[STATE['centerline_travelled']] == pytest.approx(gained, abs=1e-12), 'the gains since set, summed'


def test_listed_cars_step_alone_and_no_return_reads_as_range_max(model):
    worlds = [new_world(None, model.controllers) for _ in range(3)]  # empty: every ray misses
    batch = batch_of(model, worlds, threads=2)
    scans, state = batch.drive(actions(3), 30)
    assert [w.time for w in worlds] == [pytest.approx(0.03)] * 3
    range_max = model_range_max(worlds[0])
    assert np.all(scans == np.float32(range_max))
    assert np.all(np.isnan(state[:, STATE['centerline_s']])), 'no centre line given'
    scans, state = batch.drive(actions(1), 20, [2])
    assert state.shape == (1, len(STATE)) and state[0, STATE['time']] == worlds[2].time
    assert [w.time for w in worlds] == [pytest.approx(0.03), pytest.approx(0.03), pytest.approx(0.05)]


def model_range_max(world):
    robot = world.robot('car')
    return robot.scan('lidar')['range_max']


def test_bad_calls_name_the_car_and_what_to_give(model):
    world = new_world(None, model.controllers)
    batch = bullet_plant.CarBatch(2, 1)
    with pytest.raises(ValueError, match='car 0 of the batch was never set'):
        batch.step(np.zeros((2, 4)), 1)
    with pytest.raises(ValueError, match='car 0 of the batch was never set'):
        batch.set_drive(0, 0.26, 0.16, 0.16, 0.03, 0.5, 2.0)
    model.bind(batch, 0, world, model.spawn(world, 'car', (0.0, 0.0, 0.0)))
    with pytest.raises(IndexError, match='car 5 of a batch of 2'):
        batch.step(np.zeros((1, 4)), 1, [5])
    with pytest.raises(ValueError, match='commands are 1 x 4 numbers'):
        batch.step(np.zeros((2, 4)), 1, [0])
    with pytest.raises(ValueError, match='actions are 1 x 2 numbers'):
        batch.drive(np.zeros((1, 4)), 1, [0])
    with pytest.raises(ValueError, match='no car to step'):
        batch.step(np.zeros((0, 4)), 1, [])
    with pytest.raises(ValueError, match='steps must be at least 1'):
        batch.drive(actions(1), 0, [0])
    with pytest.raises(ValueError, match='above 0'):
        batch.set_drive(0, 0.26, 0.16, 0.16, 0.03, -0.5, 2.0)
    other = new_world(None, model.controllers)
    batch.set(1, other, model.spawn(other, 'car', (0.0, 0.0, 0.0)), list(COMMAND_CONTROLLERS[:2]), model.lidar, '',
              list(STEERING_JOINTS))
    with pytest.raises(ValueError, match='car 1 has no drive'):
        batch.drive(actions(1), 1, [1])
    with pytest.raises(ValueError, match='car 1 has 2 controllers; a drive commands four'):
        batch.set_drive(1, 0.26, 0.16, 0.16, 0.03, 0.5, 2.0)


def test_an_action_drives_the_car_as_the_converters_commands_of_its_shares_do(model):
    """drive's (steering, speed) shares of max_steering and max_speed are wheel_command_rows' commands
    for them, the speed held within max_speed: the same trajectory, bit for bit, as step with those."""
    g = model.geometry
    max_steering, max_speed = 0.3, 1.5  # within the car's: as car_params set them
    driven, stepped = (new_world(RACE_TRACK_WORLD, model.controllers) for _ in range(2))
    by_action, by_commands = bullet_plant.CarBatch(1, 1), bullet_plant.CarBatch(1, 1)
    for batch, world in ((by_action, driven), (by_commands, stepped)):
        model.bind(batch, 0, world, model.spawn(world, 'car', (0.0, 0.0, 0.0)),
                   params={'max_steering': max_steering, 'max_speed': max_speed})
    for k in range(40):
        steering, speed = 1.4 * math.sin(0.3 * k), (1.7 if k < 20 else -0.6)  # beyond +-1 too: held
        a = by_action.drive(np.array([[steering, speed]]), 10)
        commands = wheel_command_rows(np.clip(speed * max_speed, -max_speed, max_speed), steering * max_steering,
                                      g.wheelbase, g.rear_track, g.front_track, g.wheel_radius, max_steering)
        b = by_commands.step(commands.reshape(1, 4), 10)
        assert all(np.array_equal(x, y, equal_nan=True) for x, y in zip(a, b)), k  # (NaN: no centre line)
    pose = driven.robot('car').base_pose()
    assert np.array_equal(pose, stepped.robot('car').base_pose())
    assert pose[0] > 0.1, 'it drove: 0.2 s forwards at 1.5 m/s, 0.2 s back at 0.9 (the car accelerating)'


def test_helper_threads_spin_only_between_close_steps_and_never_change_results(model):
    # (nor does the order the threads take the worlds in: those whose lidar scans within the step first)
    import time
    traces, cpu_after = [], {}
    for threads, gap in ((1, 0.0), (2, 0.0003), (2, 0.02)):
        worlds = [new_world(RACE_TRACK_WORLD, model.controllers) for _ in range(3)]
        batch = batch_of(model, worlds, threads=threads)
        batch.drive(actions(1), 13, [1])  # its lidar scans in other steps than the others'
        trace = []
        for k in range(15):
            time.sleep(gap)
            trace.append(batch.drive(actions(3, steering=0.1 * math.sin(k)), 10))
        start = time.process_time()
        time.sleep(0.2)
        cpu_after[(threads, gap)] = time.process_time() - start
        del batch  # returns while helpers may be spinning
        traces.append(trace)
    for trace in traces[1:]:  # (the centre line's columns are NaN: no line given)
        assert all(np.array_equal(a, b, equal_nan=True) for x, y in zip(traces[0], trace) for a, b in zip(x, y))
    # after the last step: at most kMaxLinger (1 ms) of spinning after close steps, none after far ones
    assert cpu_after[(2, 0.0003)] < 0.02 and cpu_after[(2, 0.02)] < 0.02, cpu_after
