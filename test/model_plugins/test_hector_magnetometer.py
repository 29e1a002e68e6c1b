"""hector_gazebo_plugins' libhector_gazebo_ros_magnetic.so on the plant, through its Python
module, on the skid_bot: the reference field in the body frame."""
import math

import pytest

from plant_helpers import skid_bot
from tianracer_description import bullet_plant


def test_hector_magnetometer_reads_the_reference_field_in_the_body_frame():
    horizontal, vertical = 49.0 * math.cos(math.radians(65)), -49.0 * math.sin(math.radians(65))
    north = (horizontal * math.cos(math.radians(-2)), horizontal * math.sin(math.radians(-2)), vertical)
    for yaw in (0.0, math.pi / 2):
        world = bullet_plant.World()
        world.echo = False
        robot = world.spawn(skid_bot(), 'skid_bot', namespace='/', pose=(0, 0, 0, 0, 0, yaw))
        world.step(300)
        field = robot.plugin_latest('magnetic', 'magnetic')
        assert field['frame_id'] == 'base_link' and world.time - field['stamp'] <= 0.1 + 1e-9, 'updateRate 10'
        c, s = math.cos(yaw), math.sin(yaw)
        expected = [c * north[0] + s * north[1], -s * north[0] + c * north[1], north[2]]  # R^T of the world field
        assert field['vector'] == pytest.approx(expected, abs=1e-3), f'yaw {yaw}'
