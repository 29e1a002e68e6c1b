"""The mimic joint plugin through the node: a gripper whose second finger follows the first by the
plugin's PID, its gains from the parameter server."""
import pytest

from plant_helpers import gripper
from ros_harness import spawn_urdf, start_plant

pytestmark = pytest.mark.ros


@pytest.mark.slow
def test_the_mimic_joint_plugin_reads_its_pid_gains_from_the_parameter_server(ros, tmp_path):
    (tmp_path / 'gripper.urdf').write_text(gripper(hasPID='mimic_gains'))
    plant = start_plant(ros)
    ros.set_param('/gripper/robot_description', textfile=str(tmp_path / 'gripper.urdf'))
    ros.set_param('/mimic_gains', {'p': 100.0, 'i': 0.0, 'd': 4.0})
    ros.set_param('/gripper/finger_controller', {'type': 'position_controllers/JointPositionController',
                                                 'joint': 'finger_joint'})
    spawn_urdf(ros, plant, '/gripper/robot_description', 'gripper')
    spawner = ros.start(['rosrun', 'controller_manager', 'spawner', '__ns:=/gripper', 'finger_controller'], 'spawner')
    ros.wait_for_controllers(1, namespace='/gripper')
    seen = ros.probe('model_plugins/probes/the_mimic_joint_plugin_reads_its_pid_gains_from_the_parameter_server.py',
                     timeout=60)
    spawner.stop()
    assert seen['finger_left'] == pytest.approx(0.01 + 0.03, abs=1e-3), 'the controller moved the first finger'
    assert seen['finger_right'] == pytest.approx(-0.01 - 0.03, abs=1e-3), 'the PID (gains at /mimic_gains) the second'
    assert 'not loaded' not in plant.log()
