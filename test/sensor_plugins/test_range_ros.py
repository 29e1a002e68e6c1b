"""gazebo_ros_range through the node: the skid_bot's sensor_msgs/Range against a wall at a known
distance."""
import pytest

from plant_helpers import box_model, sdf_world, skid_bot
from ros_harness import spawn_urdf, start_plant

pytestmark = pytest.mark.ros


def test_range_sensor_reports_the_nearest_ray_to_a_wall(ros, tmp_path):
    # The wall's face at x = 0.7; the skid_bot's range sensor 0.15 m ahead of its origin.
    (tmp_path / 'wall.world').write_text(sdf_world(box_model('wall', (0.1, 2.0, 0.5), (0.75, 0.0, 0.25))))
    (tmp_path / 'skid_bot.urdf').write_text(skid_bot())
    plant = start_plant(ros, str(tmp_path / 'wall.world'))
    ros.set_param('/robot_description', textfile=str(tmp_path / 'skid_bot.urdf'))
    spawn_urdf(ros, plant, '/robot_description', 'skid_bot')
    seen = ros.probe('sensor_plugins/probes/range_sensor_reports_the_nearest_ray_to_a_wall.py', timeout=60)
    assert seen['frame'] == 'range_front' and seen['radiation'] == 1, 'infrared'
    assert seen['fov'] == pytest.approx(0.26) and seen['limits'] == pytest.approx([0.02, 0.9])
    assert seen['before'] == pytest.approx(0.55, abs=0.005), 'the straight-ahead ray: 0.7 - 0.15 m'
    assert seen['after'] == pytest.approx(0.55 - seen['x'], abs=0.01) and seen['x'] > 0.1, 'it drove toward the wall'
