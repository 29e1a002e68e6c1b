"""The figures the plant's acceptance tests check, printed with their values (`make figures`).

The tests assert bounds; this prints what the plant actually does, for notes and regressions:
the car at rest, driving straight at 1 m/s, the rear wheels' pid_gains loop (on the ground and on
a stand), the steering controllers' step response (standing and at 1 m/s), and the turning radius
for the tutorial's Ackermann commands at an ideal steering angle of 0.3 rad.
"""
import math

import numpy as np

from tianracer_description import bullet_plant
from tianracer_description.path_metrics import circle_radius
from tianracer_description.tianracer import (CONFIG_YAML, REAR_WHEEL_CONTROLLERS, STEERING_CONTROLLERS,
                                            TUTORIAL_CONTROLLERS, tianracer_urdf)
from tianracer_description.urdf_geometry import ackermann_geometry

STAND = """<?xml version="1.0"?><sdf version="1.6"><world name="stand">
  <include><uri>model://ground_plane</uri></include>
  <model name="stand"><static>true</static><pose>0.13 0 0.02 0 0 0</pose><link name="link">
    <collision name="collision"><geometry><box><size>0.2 0.08 0.04</size></box></geometry></collision>
  </link></model></world></sdf>"""


def car(urdf, sdf=None, z=0.0):
    world = bullet_plant.World.from_sdf(sdf) if sdf else bullet_plant.World()
    world.echo = False
    world.load_params(CONFIG_YAML)
    robot = world.spawn(urdf, 'tianracer', pose=(0, 0, z, 0, 0, 0))
    manager = robot.controller_manager
    manager.spawn(list(TUTORIAL_CONTROLLERS))
    world.step(2)
    return world, robot, manager


def command(manager, names, value):
    for name in names:
        manager.command(name, value)


def record(world, robot, joint, index, steps):
    """One entry of a joint's state (0 position, 1 velocity) after each of `steps` steps."""
    values = []
    for _ in range(steps):
        world.step()
        values.append(robot.joint_state(joint)[index])
    return np.array(values)


def settle_time(values, target, tolerance, dt):
    within = np.abs(np.asarray(values) - target) <= tolerance
    return 0.0 if within.all() else (len(within) - np.argmin(within[::-1])) * dt


def at_rest(urdf):
    world, robot, _ = car(urdf)
    world.step(1000)
    start = robot.base_pose()
    heights = []
    for _ in range(100):
        world.step(100)
        heights.append(robot.base_pose()[2])
    end = robot.base_pose()
    print('at rest, 10 s: height drift %.2e m, creep %.2e m' %
          (max(abs(h - start[2]) for h in heights), np.hypot(*(end[:2] - start[:2]))))


def straight(urdf):
    world, robot, manager = car(urdf)
    command(manager, REAR_WHEEL_CONTROLLERS, 31.25)
    world.step(3000)
    speed = np.hypot(*robot.base_twist()[0][:2])
    start = robot.base_pose()
    while np.hypot(*(robot.base_pose()[:2] - start[:2])) < 5.0:
        world.step(10)
    offset = robot.base_pose()[:2] - start[:2]
    print('31.25 rad/s on both rear wheels: %.4f m/s after 3 s, lateral drift %.4f m over 5 m' % (speed, offset[1]))


def wheel_loop(urdf, lifted):
    world, robot, manager = car(urdf, STAND, 0.025) if lifted else car(urdf)
    world.step(500)
    command(manager, REAR_WHEEL_CONTROLLERS, 31.25)
    velocities = record(world, robot, 'left_rear_wheel_joint', 1, 1000)
    print('rear wheel loop (pid_gains p 100), %s: within 2 %% after %.3f s, steady std %.3f %%' %
          ('lifted' if lifted else 'on the ground', settle_time(velocities, 31.25, 0.625, world.time_step),
           100 * np.std(velocities[500:]) / 31.25))


def steering(urdf, speed):
    world, robot, manager = car(urdf)
    command(manager, REAR_WHEEL_CONTROLLERS, speed / 0.032)
    world.step(1500)
    command(manager, STEERING_CONTROLLERS, 0.3)
    angles = record(world, robot, 'left_steering_hinge_joint', 0, 2000)
    print('steering step 0 -> 0.3 rad at %.1f m/s: 63 %% at %.3f s, within 0.01 rad after %.3f s, overshoot %.1f %%, '
          'final %.4f rad' % (speed, np.argmax(angles >= 0.189) * 0.001, settle_time(angles, 0.3, 0.01, 0.001),
                              100 * max(0.0, angles.max() - 0.3) / 0.3, angles[-1]))


def circle(urdf):
    world, robot, manager = car(urdf)
    g = ackermann_geometry(urdf)
    radius = g.wheelbase / math.tan(0.3)
    rate = 0.5 / g.wheel_radius
    manager.command('rear_left_velocity_controller', rate * (radius - g.rear_track / 2) / radius)
    manager.command('rear_right_velocity_controller', rate * (radius + g.rear_track / 2) / radius)
    manager.command('front_left_steering_position_controller', math.atan2(g.wheelbase, radius - g.front_track / 2))
    manager.command('front_right_steering_position_controller', math.atan2(g.wheelbase, radius + g.front_track / 2))
    world.step(3000)
    points = []
    for _ in range(600):
        world.step(10)
        points.append(robot.base_pose()[:2])
    measured = circle_radius(points)
    print('Ackermann at 0.3 rad, 0.5 m/s: radius %.4f m, geometry L/tan(0.3) %.4f m (%+.2f %%)' %
          (measured, radius, 100 * (measured / radius - 1)))


def main():
    urdf = tianracer_urdf()
    at_rest(urdf)
    straight(urdf)
    wheel_loop(urdf, lifted=False)
    wheel_loop(urdf, lifted=True)
    steering(urdf, 0.0)
    steering(urdf, 1.0)
    circle(urdf)


if __name__ == '__main__':
    main()
