"""joint_trajectory_controller through the node, as MoveIt and rqt_joint_trajectory_controller use
it: the arm (test/fixtures/urdf/arm.urdf) spawned by spawn_model, its controllers loaded from YAML and
started by controller_manager's spawner, a goal sent with actionlib's own SimpleActionClient to
/arm/arm_controller/follow_joint_trajectory (succeeded, preempted, cancelled, rejected, as actionlib
reports them), feedback, the state topic, and a trajectory on the command topic."""
import pytest

from plant_helpers import start_arm

pytestmark = pytest.mark.ros


@pytest.mark.parametrize('kind', ['position_controllers', 'effort_controllers'])
@pytest.mark.slow
def test_follow_joint_trajectory_with_actionlib(ros, tmp_path, kind):
    start_arm(ros, tmp_path, kind)
    seen = ros.probe('controllers/probes/follow_joint_trajectory_with_actionlib.py', timeout=120)
    SUCCEEDED, PREEMPTED, REJECTED = 3, 2, 5
    assert (seen['state'], seen['result']) == (SUCCEEDED, [0, ''])
    assert seen['positions'] == pytest.approx([1.0, 0.3, 2.0], abs=0.02)
    assert seen['state_desired'] == pytest.approx([1.0, 0.3, 2.0], abs=1e-6)
    assert seen['feedback'] >= 10 and seen['feedback_joints'] == ['shoulder', 'elbow', 'wrist'], \
        'feedback at action_monitor_rate (10 Hz) over 2 s'
    assert seen['after_preempt'] == SUCCEEDED
    assert seen['cancelled'] == PREEMPTED, "actionlib's state for an active goal cancelled"
    assert seen['rejected'] == [REJECTED, -2, "Joints on incoming goal don't match the controller joints."]


@pytest.mark.slow
def test_a_trajectory_on_the_command_topic_the_state_topic_and_query_state(ros, tmp_path):
    start_arm(ros, tmp_path)
    seen = ros.probe('controllers/probes/a_trajectory_on_the_command_topic_the_state_topic_and_query_state.py',
                     timeout=60)
    assert seen['queried'] == [['shoulder', 'elbow', 'wrist'], pytest.approx([-0.6, 0.4, 0.0], abs=1e-9), [0, 0, 0]], \
        'query_state: the trajectory held at its last point'
    assert seen['early'] == 'failed', 'a time before the trajectory fails the call, as upstream returns false'
    assert seen['names'] == ['shoulder', 'elbow', 'wrist']
    assert seen['actual'] == pytest.approx([-0.6, 0.4, 0.0], abs=0.02), 'reordered by name'
    assert max(abs(e) for e in seen['error']) < 0.02
    assert seen['period'] == pytest.approx(1 / 25, rel=0.05), 'state_publish_rate 25'
