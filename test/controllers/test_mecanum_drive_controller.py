"""mecanum_drive_controller/MecanumDriveController (Ridgeback's, the one ROS 1 robots load under
that type) on the plant through its Python module, driving test/fixtures/urdf/mecanum_bot.urdf as
Ridgeback is simulated: the wheels (frictionless) turned by the controller for its wheel odometry,
the body moved by the force-based move plugin on the same Twist. The wheel speeds against the
mecanum inverse kinematics with the geometry read from the URDF, the odometry's twist and pose
against the command integrated here, the timeout, the limits, the geometry parameters and the
errors that name what to set."""
import copy
import math

import pytest

from plant_helpers import MECANUM_CONTROLLERS, logged, mecanum_bot
from tianracer_description import bullet_plant

WHEELS = ['front_left_wheel', 'rear_left_wheel', 'rear_right_wheel', 'front_right_wheel']  # FL, BL, BR, FR
K, RADIUS = 0.2 + 0.15, 0.05  # half separations (x + y) and the wheels' radius, from the URDF


def mecanum_world(**controller):
    params = copy.deepcopy(MECANUM_CONTROLLERS)
    params['mecanum_bot']['mecanum_controller'].update(controller)
    world = bullet_plant.World()
    world.echo = False
    world.load_params(params)
    urdf = mecanum_bot()
    world.load_params({'mecanum_bot': {'robot_description': urdf}})
    robot = world.spawn(urdf, 'mecanum_bot')
    manager = robot.controller_manager
    return world, robot, manager


def started(**controller):
    world, robot, manager = mecanum_world(**controller)
    names = ['joint_state_controller', 'mecanum_controller']
    assert manager.spawn(names) == (names, True), world.messages()
    world.step(100)
    return world, robot, manager


def inverse_kinematics(vx, vy, wz):
    return [(vx - vy - K * wz) / RADIUS, (vx + vy - K * wz) / RADIUS,
            (vx - vy + K * wz) / RADIUS, (vx + vy + K * wz) / RADIUS]


def test_wheels_turn_by_the_mecanum_kinematics_and_odometry_follows_the_command():
    world, robot, manager = started()
    vx, vy, wz = 0.3, 0.2, 0.5
    assert manager.command('mecanum_controller', (vx, vy, wz)), '(linear.x, linear.y, angular.z)'
    t0 = world.time
    x = y = heading = 0.0
    for _ in range(100):  # 0.2 s at a time: resent within cmd_vel_timeout
        world.step(200)
        manager.command('mecanum_controller', (vx, vy, wz))
    speeds = [robot.joint_state(w)[1] for w in WHEELS]
    assert speeds == pytest.approx(inverse_kinematics(vx, vy, wz), abs=0.02)
    odom = manager.odometry('mecanum_controller')
    assert odom['frame_id'] == 'odom' and odom['child_frame_id'] == 'base_footprint'
    assert odom['twist'][:2] + odom['twist'][5:] == pytest.approx([vx, vy, wz], abs=0.01)
    # the command's pose after t: the twist in the body frame turned with the heading
    t = odom['stamp'] - t0
    heading = wz * t
    x = (vx * math.sin(heading) + vy * (math.cos(heading) - 1)) / wz
    y = (vx * (1 - math.cos(heading)) + vy * math.sin(heading)) / wz
    assert [odom['x'], odom['y']] == pytest.approx([x, y], abs=0.03)
    assert math.remainder(odom['heading'] - heading, 2 * math.pi) == pytest.approx(0, abs=0.03)
    assert odom['pose_covariance'] == [0.001, 0.001, 1e6, 1e6, 1e6, 0.03]


def test_a_stale_command_brakes_within_the_acceleration_limit():
    world, robot, manager = started(linear={'y': {'has_acceleration_limits': True, 'max_acceleration': 1.0},
                                            'x': {'has_velocity_limits': True, 'max_velocity': 0.2}})
    assert manager.command('mecanum_controller', (0.5, 0.4, 0.0))
    world.step(200)
    speeds = [robot.joint_state(w)[1] for w in WHEELS]
    # x held to 0.2 m/s at once; y ramps at 1 m/s^2: 0.2 m/s after 0.2 s
    assert speeds == pytest.approx(inverse_kinematics(0.2, 0.2, 0.0), abs=0.05)
    world.step(300)  # past the 0.25 s timeout: x stops at once, y ramps down at 1 m/s^2
    odom = manager.odometry('mecanum_controller')
    assert odom['twist'][0] == pytest.approx(0.0, abs=0.02)
    assert 0.0 < odom['twist'][1] < 0.25
    world.step(500)
    assert manager.odometry('mecanum_controller')['twist'][:2] == pytest.approx([0, 0], abs=0.01)


def test_geometry_parameters_override_the_urdf():
    world, robot, manager = started(wheel_separation_x=1.0, wheel_separation_y=0.6, wheel_radius=0.1)
    assert manager.command('mecanum_controller', (0.0, 0.0, 0.4))
    world.step(200)
    k, r = (1.0 + 0.6) / 2, 0.1
    assert robot.joint_state('front_left_wheel')[1] == pytest.approx(-k * 0.4 / r, abs=0.02)


@pytest.mark.parametrize('params, says', [
    ({'wheel_separation_x': 0.5}, 'Only one wheel separation overrided'),
    ({'front_left_wheel_joint': 'nowhere'}, "Could not find resource 'nowhere' (front_left_wheel_joint)"),
    ({'pose_covariance_diagonal': [1, 2]}, "'pose_covariance_diagonal'"),
])
def test_configuration_errors_say_what_to_set(params, says):
    world, robot, manager = mecanum_world(**params)
    assert manager.spawn(['mecanum_controller'])[0] == [], 'not loaded'
    assert any(says in m for m in logged(world, 'ERROR')), logged(world, 'ERROR')
