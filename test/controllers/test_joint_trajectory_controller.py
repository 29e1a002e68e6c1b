"""ros_controllers' joint_trajectory_controller on the plant, through its Python module: the
position, velocity and effort kinds driving test/fixtures/urdf/arm.urdf (shoulder, elbow against
gravity, continuous wrist) through gazebo_ros_control, as UR and TIAGo arms are driven. What a user
of FollowJointTrajectory relies on: the splines between waypoints, goals succeeding, rejected with
upstream's codes and texts, preempted, cancelled, aborted on path and goal tolerances, and the
trajectory merged without a jump when a new one replaces it."""
import math

import numpy as np
import pytest

from plant_helpers import ARM_JOINTS, arm, arm_controllers, logged
from tianracer_description import bullet_plant

INTERFACE = {'position_controllers': 'Position', 'velocity_controllers': 'Velocity', 'effort_controllers': 'Effort'}
SUCCESSFUL, INVALID_GOAL, INVALID_JOINTS, PATH_TOLERANCE_VIOLATED, GOAL_TOLERANCE_VIOLATED = 0, -1, -2, -4, -5


def arm_world(kind='position_controllers', **controller):
    world = bullet_plant.World()
    world.echo = False
    world.load_params(arm_controllers(kind, **controller))
    urdf = arm(INTERFACE[kind])
    world.load_params({'arm': {'robot_description': urdf}})
    robot = world.spawn(urdf, 'arm')
    manager = robot.controller_manager
    names = ['joint_state_controller', 'arm_controller']
    assert manager.spawn(names) == (names, True), world.messages()
    world.step(100)
    return world, robot, manager


def positions(robot):
    return [robot.joint_state(j)[0] for j in ARM_JOINTS]


def point(t, positions, velocities=None, accelerations=None):
    p = {'positions': positions, 'time_from_start': t}
    if velocities is not None:
        p['velocities'] = velocities
    if accelerations is not None:
        p['accelerations'] = accelerations
    return p


def goal(*points, joints=ARM_JOINTS, stamp=0.0, **tolerances):
    return dict(trajectory={'joint_names': joints, 'points': list(points), 'stamp': stamp}, **tolerances)


def run_until_done(world, manager, goal_id, seconds):
    for _ in range(int(seconds / 0.01)):
        world.step(10)
        result = manager.goal_result('arm_controller')
        if result and result['goal_id'] == goal_id:
            return result
    return manager.goal_result('arm_controller')


@pytest.mark.parametrize('kind', sorted(INTERFACE))
def test_each_kind_follows_a_goal_through_its_waypoints_and_succeeds(kind):
    world, robot, manager = arm_world(kind)
    start = world.time
    assert manager.send_goal('arm_controller', 'g1', goal(point(1.0, [0.5, 0.8, 3.0], [0.3, 0.0, 0.0]),
                                                           point(2.0, [1.0, 0.4, 6.0], [0.0, 0.0, 0.0])))
    world.step(int(round((1.0 - (world.time - start)) / world.time_step)))
    assert positions(robot) == pytest.approx([0.5, 0.8, 3.0], abs=0.02), 'at the first waypoint on time'
    feedback = manager.goal_feedback('arm_controller')
    assert feedback['goal_id'] == 'g1' and feedback['joint_names'] == ARM_JOINTS
    result = run_until_done(world, manager, 'g1', 2.0)
    assert result == {'goal_id': 'g1', 'outcome': 'succeeded', 'error_code': SUCCESSFUL, 'error_string': ''}
    assert positions(robot) == pytest.approx([1.0, 0.4, 6.0], abs=0.02)
    assert world.time - start == pytest.approx(2.0, abs=0.1), 'done when the last point is reached, at rest'
    state = manager.state('arm_controller')
    assert state['joint_names'] == ARM_JOINTS
    assert len(state['actual']['accelerations']) == 0 and len(state['desired']['accelerations']) == 3, \
        "upstream's state: actual and error without accelerations"


def hermite(t, t0, s0, t1, s1):
    """The polynomial of least order through the two ends' given derivatives, solved here as a
    linear system (not the controller's closed forms): position at t."""
    order = min(len(s0), len(s1))  # 1: position only, 2: + velocity, 3: + acceleration
    degree = 2 * order - 1
    rows, values = [], []
    for tau, s in ((0.0, s0), (t1 - t0, s1)):
        for k in range(order):
            rows.append([math.factorial(n) / math.factorial(n - k) * tau ** (n - k) if n >= k else 0.0
                         for n in range(degree + 1)])
            values.append(s[k])
    c = np.linalg.solve(np.array(rows), np.array(values))
    return sum(c[n] * (t - t0) ** n for n in range(degree + 1))


@pytest.mark.parametrize('given', ['positions', 'velocities', 'accelerations'])
def test_waypoints_are_joined_by_the_spline_their_fields_allow(given):
    world, robot, manager = arm_world(state_publish_rate=1000)
    first = (0.4, 0.5, -0.2)
    second = (0.9, 0.1, 0.3)
    with_velocity, with_acceleration = given != 'positions', given == 'accelerations'
    stamp = world.time + 0.5
    points = [point(1.0, [first[0], 0.3, 0.5], [first[1], 0.0, 0.0] if with_velocity else None,
                    [first[2], 0.0, 0.0] if with_acceleration else None),
              point(2.0, [second[0], 0.3, 0.5], [second[1], 0.0, 0.0] if with_velocity else None,
                    [second[2], 0.0, 0.0] if with_acceleration else None)]
    assert manager.command('arm_controller', {'joint_names': ARM_JOINTS, 'points': points, 'stamp': stamp})
    order = 3 if with_acceleration else 2 if with_velocity else 1
    while world.time < stamp + 1.9:
        world.step(1)
        state = manager.state('arm_controller')
        t = state['stamp']
        if t > stamp + 1.0:
            expected = hermite(t, stamp + 1.0, first[:order], stamp + 2.0, second[:order])
            assert state['desired']['positions'][0] == pytest.approx(expected, abs=1e-9), (given, t)
    world.step(300)
    assert manager.state('arm_controller')['desired']['positions'][0] == pytest.approx(0.9, abs=1e-12), \
        'the last point is held'


def test_query_state_samples_the_trajectory_at_any_time_of_it():
    world, robot, manager = arm_world()
    started = world.time - 0.1  # the hold trajectory begins when the controller starts
    held = manager.query_state('arm_controller', world.time)
    assert held['name'] == ARM_JOINTS and held['velocity'] == [0, 0, 0]
    assert held['position'] == pytest.approx(positions(robot), abs=0.02)
    stamp = world.time + 0.5
    first, second = (0.4, 0.5, -0.2), (0.9, 0.1, 0.3)
    points = [point(1.0, [first[0], 0.3, 0.5], [first[1], 0.0, 0.0], [first[2], 0.0, 0.0]),
              point(2.0, [second[0], 0.3, 0.5], [second[1], 0.0, 0.0], [second[2], 0.0, 0.0])]
    assert manager.command('arm_controller', {'joint_names': ARM_JOINTS, 'points': points, 'stamp': stamp})
    world.step(1)
    # ahead of time and in the past of the new trajectory alike: the quintic between the waypoints
    for t in (stamp + 1.25, stamp + 1.5, stamp + 1.75):
        sampled = manager.query_state('arm_controller', t)
        assert sampled['position'][0] == pytest.approx(hermite(t, stamp + 1.0, first, stamp + 2.0, second), abs=1e-9)
        assert sampled['position'][1:] == pytest.approx([0.3, 0.5], abs=1e-9)
    world.step(3000)
    assert manager.query_state('arm_controller', world.time + 10)['position'][0] == pytest.approx(0.9, abs=1e-12)
    assert manager.query_state('arm_controller', started - 1.0) is None
    assert any('Requested sample time precedes trajectory start time.' in m for m in logged(world, 'ERROR'))
    manager.switch([], ['arm_controller'])
    world.step(10)  # the switch happens at the next update, as ros_control's
    assert manager.query_state('arm_controller', world.time) is None
    assert any("Can't sample trajectory. Controller is not running." in m for m in logged(world, 'ERROR'))


def test_goals_are_rejected_with_upstreams_codes_and_reasons():
    world, robot, manager = arm_world()
    reach = point(1.0, [0.2, 0.2, 0.2])

    def rejected(goal_id, g):
        assert not manager.send_goal('arm_controller', goal_id, g)
        result = manager.goal_result('arm_controller')
        assert result['goal_id'] == goal_id and result['outcome'] == 'rejected'
        return result['error_code'], result['error_string']

    assert rejected('swapped', goal(reach, joints=['shoulder', 'elbow', 'hip'])) == \
        (INVALID_JOINTS, "Joints on incoming goal don't match the controller joints.")
    assert rejected('two', goal(point(1.0, [0.2, 0.2]), joints=['shoulder', 'elbow']))[0] == INVALID_JOINTS, \
        'all joints unless allow_partial_joints_goal'
    assert rejected('back', goal(point(2.0, [0.1] * 3), point(1.0, [0.2] * 3))) == \
        (INVALID_GOAL, 'Trajectory message contains waypoints that are not strictly increasing in time.')
    code, text = rejected('late', goal(reach, stamp=world.time - 5.0))
    assert code == INVALID_GOAL and text.startswith('Dropping all 1 trajectory point(s), as they occur before the current time.')
    assert rejected('short', goal(point(1.0, [0.2, 0.2])))[0] == INVALID_GOAL, 'two positions for three joints'
    assert rejected('nan', goal(point(1.0, [0.2, float('nan'), 0.2])))[0] == INVALID_GOAL, 'the plant refuses NaN'
    assert manager.switch([], ['arm_controller'], 2)
    world.step(1)  # controller_manager switches in its next update
    assert rejected('stopped', goal(reach)) == (INVALID_GOAL, "Can't accept new action goals. Controller is not running.")
    world.step(100)
    assert positions(robot) == pytest.approx([0.0, 0.0, 0.0], abs=0.01), 'nothing moved'


def test_reordered_and_partial_goals():
    world, robot, manager = arm_world(allow_partial_joints_goal=True)
    assert manager.send_goal('arm_controller', 'reordered',
                             goal(point(0.5, [0.3, 0.2, 0.1]), joints=['wrist', 'elbow', 'shoulder']))
    assert run_until_done(world, manager, 'reordered', 2.0)['outcome'] == 'succeeded'
    assert positions(robot) == pytest.approx([0.1, 0.2, 0.3], abs=0.01)
    assert manager.send_goal('arm_controller', 'elbow only', goal(point(0.5, [-0.3]), joints=['elbow']))
    assert run_until_done(world, manager, 'elbow only', 2.0)['outcome'] == 'succeeded'
    assert positions(robot) == pytest.approx([0.1, -0.3, 0.3], abs=0.01), 'the other joints keep their trajectories'


def test_a_new_goal_preempts_the_one_in_force_and_continues_without_a_jump():
    world, robot, manager = arm_world(state_publish_rate=1000)
    assert manager.send_goal('arm_controller', 'first', goal(point(2.0, [1.5, 0.0, 0.0])))
    world.step(700)
    desired = []
    assert manager.send_goal('arm_controller', 'second', goal(point(1.0, [-0.5, 0.0, 0.0])))
    assert manager.goal_result('arm_controller') == {'goal_id': 'first', 'outcome': 'canceled', 'error_code': 0,
                                                     'error_string': ''}, 'PREEMPTED, as upstream reports it'
    for _ in range(1500):
        world.step(1)
        desired.append(manager.state('arm_controller')['desired']['positions'][0])
    assert max(abs(b - a) for a, b in zip(desired, desired[1:])) < 0.01, 'no jump where the trajectories meet'
    assert manager.goal_result('arm_controller')['goal_id'] == 'second'
    assert manager.goal_result('arm_controller')['outcome'] == 'succeeded'
    assert positions(robot)[0] == pytest.approx(-0.5, abs=0.01)


def test_a_trajectory_on_the_command_topic_preempts_a_goal():
    world, robot, manager = arm_world()
    assert manager.send_goal('arm_controller', 'slow', goal(point(3.0, [1.0, 0.0, 0.0])))
    world.step(500)
    assert manager.command('arm_controller', {'joint_names': ARM_JOINTS, 'points': [point(0.5, [0.0, 0.5, 0.0])]})
    assert manager.goal_result('arm_controller')['outcome'] == 'canceled'
    world.step(1000)
    assert positions(robot) == pytest.approx([0.0, 0.5, 0.0], abs=0.01)


@pytest.mark.parametrize('stop_duration', [0.0, 0.3])
def test_cancel_holds_where_the_arm_is_or_ramps_to_rest(stop_duration):
    world, robot, manager = arm_world(stop_trajectory_duration=stop_duration, state_publish_rate=1000)
    assert manager.send_goal('arm_controller', 'g', goal(point(2.0, [2.0, 0.0, 0.0])))
    world.step(1000)
    speed = manager.state('arm_controller')['desired']['velocities'][0]
    assert speed > 0.5
    at_cancel = positions(robot)[0]
    assert manager.cancel_goal('arm_controller', 'g')
    assert manager.goal_result('arm_controller')['outcome'] == 'canceled'
    world.step(1)
    after = manager.state('arm_controller')['desired']
    if stop_duration == 0:
        assert after['positions'][0] == pytest.approx(at_cancel, abs=1e-9) and after['velocities'][0] == 0.0
    else:
        assert after['velocities'][0] == pytest.approx(speed, rel=0.02), 'the ramp starts at the desired speed'
    world.step(int(stop_duration * 1000) + 10)
    held = positions(robot)[0]
    world.step(500)
    assert positions(robot)[0] == pytest.approx(held, abs=1e-3) and held < 1.5, 'at rest, short of the goal'
    if stop_duration:
        assert held - at_cancel == pytest.approx(0.5 * speed * stop_duration, rel=0.25), 'braked over the duration'


def test_tolerance_violations_abort_the_goal():
    weak = {'shoulder': {'p': 0.2, 'd': 0.1, 'i': 0.0, 'i_clamp': 0.0},
            'elbow': {'p': 400.0, 'd': 20.0, 'i': 0.0, 'i_clamp': 0.0},
            'wrist': {'p': 2.0, 'd': 0.05, 'i': 0.0, 'i_clamp': 0.0}}
    world, robot, manager = arm_world('effort_controllers', gains=weak)
    assert manager.send_goal('arm_controller', 'fast', goal(point(0.5, [1.0, 0.0, 0.0])))
    result = run_until_done(world, manager, 'fast', 1.0)
    assert (result['outcome'], result['error_code']) == ('aborted', PATH_TOLERANCE_VIOLATED)
    assert "joint 'shoulder'" in result['error_string'], 'constraints/shoulder/trajectory 0.2'

    world, robot, manager = arm_world('effort_controllers', gains=weak)
    started = world.time
    loose = goal(point(0.5, [1.0, 0.0, 0.0]), path_tolerance=[{'name': 'shoulder', 'position': -1}],
                 goal_time_tolerance=0.3)
    assert manager.send_goal('arm_controller', 'unreachable in time', loose)
    result = run_until_done(world, manager, 'unreachable in time', 2.0)
    assert (result['outcome'], result['error_code']) == ('aborted', GOAL_TOLERANCE_VIOLATED), \
        'path tolerance -1 erased, the goal tolerance 0.02 not met'
    assert world.time - started == pytest.approx(0.5 + 0.3, abs=0.03), 'when the goal time tolerance ran out'


def test_an_empty_goal_holds_and_succeeds():
    world, robot, manager = arm_world()
    assert manager.send_goal('arm_controller', 'moving', goal(point(2.0, [1.0, 0.0, 0.0])))
    world.step(500)
    assert manager.send_goal('arm_controller', 'stop', goal())
    result = run_until_done(world, manager, 'stop', 0.5)
    assert (result['goal_id'], result['outcome']) == ('stop', 'succeeded')
    held = positions(robot)[0]
    world.step(500)
    assert positions(robot)[0] == pytest.approx(held, abs=1e-3) and 0.0 < held < 0.5


def test_a_continuous_joint_takes_the_short_way_round():
    world, robot, manager = arm_world()
    assert manager.send_goal('arm_controller', 'round', goal(point(1.0, [0.0, 0.0, 6.0])))
    assert run_until_done(world, manager, 'round', 2.0)['outcome'] == 'succeeded'
    assert positions(robot)[2] == pytest.approx(6.0 - 2 * math.pi, abs=0.01), '-0.28 rad rather than +6'


def refused_arm_controller(kind, remove):
    """The messages of loading arm_controller with `remove` (a function of its parameters) applied."""
    world = bullet_plant.World()
    world.echo = False
    params = arm_controllers(kind)
    remove(params['arm']['arm_controller'])
    world.load_params(params)
    robot = world.spawn(arm(INTERFACE[kind]), 'arm')
    assert not robot.controller_manager.load('arm_controller')
    return logged(world, 'ERROR')


def test_configuration_errors_say_what_to_set():
    errors = refused_arm_controller('effort_controllers', lambda c: c['gains'].pop('elbow'))
    assert any('No p gain specified for pid.  Namespace: /arm/arm_controller/gains/elbow' in m and
               'Failed to initialize PID gains' in m for m in errors)
    errors = refused_arm_controller('position_controllers', lambda c: c.pop('joints'))
    assert any("Could not find 'joints' parameter (namespace: /arm/arm_controller)." in m for m in errors)
    errors = refused_arm_controller('position_controllers', lambda c: c.update(joints=['shoulder', 'knee']))
    assert any("Could not find joint 'knee' in 'hardware_interface::PositionJointInterface'." in m for m in errors)
