"""The mimic joint plugin through the node: a gripper whose second finger follows the first by the
plugin's PID, its gains from the parameter server."""
import pytest

from plant_helpers import gripper
from ros_harness import drive_mimic_gripper, start_plant

pytestmark = pytest.mark.ros


@pytest.mark.slow
def test_the_mimic_joint_plugin_reads_its_pid_gains_from_the_parameter_server(ros, tmp_path):
    (tmp_path / 'gripper.urdf').write_text(gripper(hasPID='mimic_gains'))
    plant = start_plant(ros)
    seen = drive_mimic_gripper(ros, plant, tmp_path / 'gripper.urdf')
    assert seen['finger_left'] == pytest.approx(0.01 + 0.03, abs=1e-3), 'the controller moved the first finger'
    assert seen['finger_right'] == pytest.approx(-0.01 - 0.03, abs=1e-3), 'the PID (gains at /mimic_gains) the second'
    assert 'not loaded' not in plant.log()
