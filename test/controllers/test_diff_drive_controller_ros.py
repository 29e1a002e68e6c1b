"""ros_controllers' diff_drive_controller through the node: the diff_bot with gazebo_ros_control,
its controllers started by the spawner, driven on the controller's cmd_vel."""
import pytest
import yaml

from plant_helpers import DIFF_DRIVE_CONTROLLERS, diff_bot_with_gazebo_ros_control
from ros_harness import spawn_with_controllers, start_plant

pytestmark = pytest.mark.ros


@pytest.mark.slow
def test_diff_drive_controller_through_gazebo_ros_control_and_the_spawner(ros, tmp_path):
    (tmp_path / 'diff_bot.urdf').write_text(diff_bot_with_gazebo_ros_control())
    (tmp_path / 'controllers.yaml').write_text(yaml.safe_dump(DIFF_DRIVE_CONTROLLERS))
    spawner = spawn_with_controllers(ros, start_plant(ros), str(tmp_path / 'diff_bot.urdf'),
                                     str(tmp_path / 'controllers.yaml'), '/diff_bot', 'diff_bot',
                                     ['joint_state_controller', 'mobile_base_controller'])
    seen = ros.probe('controllers/probes/diff_drive_controller_through_gazebo_ros_control_and_the_spawner.py',
                     timeout=90)
    spawner.stop()
    assert seen['frames'] == ['odom', 'base_footprint']
    assert seen['linear'] == pytest.approx(0.2, rel=0.1) and seen['angular'] == pytest.approx(0.5, rel=0.1)
    assert seen['x'] > 0.1, 'it drove'
