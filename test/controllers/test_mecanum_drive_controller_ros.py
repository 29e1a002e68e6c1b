"""A Ridgeback-like mecanum base through the node (test/fixtures/urdf/mecanum_bot.urdf): its
controllers started by the spawner, one Twist sent to the controller and to the force-based move
plugin as Ridgeback's relay does; the controller's wheel odometry and odom -> base_footprint on /tf
follow the command sideways and turning, the body moves with it, the wheels' joint_states carry the
inverse kinematics."""
import pytest
import yaml

from plant_helpers import MECANUM_CONTROLLERS, mecanum_bot
from ros_harness import spawn_with_controllers, start_plant
from test_mecanum_drive_controller import WHEELS, inverse_kinematics

pytestmark = pytest.mark.ros


@pytest.mark.slow
def test_mecanum_controller_through_the_spawner_with_the_body_moved_by_force_based_move(ros, tmp_path):
    (tmp_path / 'mecanum_bot.urdf').write_text(mecanum_bot())
    (tmp_path / 'controllers.yaml').write_text(yaml.safe_dump(MECANUM_CONTROLLERS))
    spawner = spawn_with_controllers(ros, start_plant(ros), str(tmp_path / 'mecanum_bot.urdf'),
                                     str(tmp_path / 'controllers.yaml'), '/mecanum_bot', 'mecanum_bot',
                                     ['joint_state_controller', 'mecanum_controller'])
    seen = ros.probe('controllers/probes/mecanum_controller_through_the_spawner_with_the_body_moved_by_force_based_move.py',
                     timeout=90)
    spawner.stop()
    assert seen['frames'] == ['odom', 'base_footprint']
    assert seen['twist'] == pytest.approx([0.0, 0.3, 0.2], abs=0.02)
    assert seen['odom_y'] > 0.5 and seen['tf_y'] == pytest.approx(seen['odom_y'], abs=0.1)
    assert seen['moved_y'] > 0.5, 'force_based_move moved the body sideways'
    assert [seen['speeds'][w] for w in WHEELS] == pytest.approx(inverse_kinematics(0.0, 0.3, 0.2), abs=0.05)
