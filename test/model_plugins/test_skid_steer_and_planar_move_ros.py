"""libgazebo_ros_skid_steer_drive.so and libgazebo_ros_planar_move.so through the node: a skid-steer
robot (with hector's GPS and IMU) and a holonomic base in one world, each in its spawn namespace."""
import pytest

from plant_helpers import planar_bot, skid_bot
from ros_harness import spawn_urdf, start_plant

pytestmark = pytest.mark.ros


@pytest.mark.slow
def test_skid_steer_and_planar_move_robots_in_their_spawn_namespaces(ros, tmp_path):
    (tmp_path / 'skid_bot.urdf').write_text(skid_bot())
    (tmp_path / 'planar_bot.urdf').write_text(planar_bot(robotBaseFrame='planar_base'))
    plant = start_plant(ros)
    ros.set_param('/skid_bot/robot_description', textfile=str(tmp_path / 'skid_bot.urdf'))
    ros.set_param('/planar_bot/robot_description', textfile=str(tmp_path / 'planar_bot.urdf'))
    spawn_urdf(ros, plant, '/skid_bot/robot_description', 'skid_bot', robot_namespace='/skid_bot')
    spawn_urdf(ros, plant, '/planar_bot/robot_description', 'planar_bot', robot_namespace='/planar_bot', xyz=(0, 2, 0))
    seen = ros.probe('model_plugins/probes/skid_steer_and_planar_move_robots_in_their_spawn_namespaces.py', timeout=90)
    frame, child, speed, x, yaw_covariance = seen['skid']
    assert (frame, child) == ('odom', 'base_footprint'), 'skid_steer_drive prefixes no frame'
    assert speed == pytest.approx(0.3, rel=0.05) and x > 0.2 and yaw_covariance == 0.01
    child, sideways, y = seen['planar']
    assert child == 'planar_base' and sideways == pytest.approx(0.2, rel=0.1) and y > 2.2, 'it moved sideways from y 2'
    assert seen['tf_y'] == pytest.approx(y, abs=0.1)
    assert seen['joints'][0] == 'front_left_wheel_joint' and seen['wheel_speeds'] == pytest.approx([7.5] * 4, rel=0.05)
    frame, latitude, covariance_type, covariance = seen['fix']
    assert frame == 'base_link' and covariance_type == 2 and covariance == pytest.approx(1e-8), \
        "hector's GPS in its own <robotNamespace> '/': /navsat/fix, drift^2 on the diagonal"
    assert seen['imu'][0] == 'base_link' and seen['imu'][1] == pytest.approx(9.8, abs=0.3), "hector's IMU on /imu/data"
    assert seen['imu'][2] == pytest.approx(0.005 ** 2)
    assert seen['accel_bias'] == pytest.approx(0.4, abs=0.02), 'set through /imu/data/set_accel_bias'
    assert (latitude - 49.9) * 111_260 == pytest.approx(seen['x_at_fix'], abs=0.02), 'about 111.26 km a degree of latitude at 49.9'
