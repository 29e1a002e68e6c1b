"""Mesh collisions through the Python module (no ROS master): a static mesh slab (links fixed to a
root link named "world") that the car lands and rests on, and a mesh wall that stops the car."""
import numpy as np
import pytest

from plant_helpers import box_stl, hold_steering, make_world
from tianracer_description.tianracer import REAR_WHEEL_JOINTS

SLAB_TOP = 0.1
WALL_X = 1.5  # the wall's near face


def scenery_urdf(tmp_path, wall):
    """A slab 4 m square with its top at SLAB_TOP and, if `wall`, a wall across +x, both meshes fixed
    to the world."""
    slab = box_stl(tmp_path / 'slab.stl', (-2, -2, SLAB_TOP - 0.1), (2, 2, SLAB_TOP))
    links = [('slab', slab)]
    if wall:
        links.append(('wall', box_stl(tmp_path / 'wall.stl', (WALL_X, -2, SLAB_TOP), (WALL_X + 0.2, 2, 0.6))))
    body = ''.join(f"""<link name="{name}"><collision><geometry><mesh filename="file://{path}"/></geometry></collision></link>
  <joint name="{name}_joint" type="fixed"><parent link="world"/><child link="{name}"/></joint>"""
                   for name, path in links)
    return f'<robot name="scenery"><link name="world"/>{body}</robot>'


def rest_height(world, robot):
    world.step(1500)
    return robot.base_pose()[2]


def test_the_car_dropped_on_a_static_mesh_slab_rests_on_its_top(tmp_path, urdf_xml, control_config):
    on_ground = make_world(control_config)
    ground_height = rest_height(on_ground, on_ground.spawn(urdf_xml, 'tianracer', pose=(0, 0, 0.3, 0, 0, 0)))

    world = make_world(control_config)
    world.spawn(scenery_urdf(tmp_path, wall=False), 'scenery')
    car = world.spawn(urdf_xml, 'tianracer', pose=(0, 0, SLAB_TOP + 0.3, 0, 0, 0))
    assert rest_height(world, car) - SLAB_TOP == pytest.approx(ground_height, abs=1e-3)
    world.step(2000)
    assert car.base_pose()[2] - SLAB_TOP == pytest.approx(ground_height, abs=1e-3), 'stays on the slab'


def test_a_mesh_wall_stops_the_car(tmp_path, urdf_xml, control_config):
    world = make_world(control_config)
    world.spawn(scenery_urdf(tmp_path, wall=True), 'scenery')
    car = world.spawn(urdf_xml, 'tianracer', pose=(0, 0, SLAB_TOP + 0.05, 0, 0, 0))
    world.step(500)
    hold_steering(car)
    for joint in REAR_WHEEL_JOINTS:
        car.set_command(joint, 31.25)  # 1 m/s
    furthest = 0.0
    for _ in range(400):  # 4 s: 4 m of driving with nothing in the way
        world.step(10)
        furthest = max(furthest, car.base_pose()[0])
    assert 0.5 < furthest < WALL_X, 'the car reached the wall and did not pass into it'
    linear, _ = car.base_twist()
    assert np.hypot(linear[0], linear[1]) < 0.1, 'held by the wall'
    assert abs(car.base_pose()[2] - SLAB_TOP) < 0.05, 'still on the slab'
