"""joint_trajectory_controller through the node, as MoveIt and rqt_joint_trajectory_controller use
it: the arm (test/fixtures/urdf/arm.urdf) spawned by spawn_model, its controllers loaded from YAML and
started by controller_manager's spawner, a goal sent with actionlib's own SimpleActionClient to
/arm/arm_controller/follow_joint_trajectory (succeeded, preempted, cancelled, rejected, as actionlib
reports them), feedback, the state topic, and a trajectory on the command topic."""
import pytest

from plant_helpers import start_arm

pytestmark = pytest.mark.ros


PROBE_SETUP = """
import json, rospy, actionlib
from actionlib_msgs.msg import GoalStatus
from control_msgs.msg import (FollowJointTrajectoryAction, FollowJointTrajectoryFeedback, FollowJointTrajectoryGoal,
                              JointTrajectoryControllerState)
from sensor_msgs.msg import JointState
from trajectory_msgs.msg import JointTrajectory, JointTrajectoryPoint
rospy.init_node('probe')
JOINTS = ['shoulder', 'elbow', 'wrist']
def goal(*points, joints=JOINTS):
    g = FollowJointTrajectoryGoal()
    g.trajectory.joint_names = joints
    for t, positions in points:
        g.trajectory.points.append(JointTrajectoryPoint(positions=positions, time_from_start=rospy.Duration(t)))
    return g
client = actionlib.SimpleActionClient('/arm/arm_controller/follow_joint_trajectory', FollowJointTrajectoryAction)
assert client.wait_for_server(rospy.Duration(30))
rospy.sleep(1.0)  # the elbow swung until the spawner started the controller: let the hold settle it
"""


@pytest.mark.parametrize('kind', ['position_controllers', 'effort_controllers'])
@pytest.mark.slow
def test_follow_joint_trajectory_with_actionlib(ros, tmp_path, kind):
    start_arm(ros, tmp_path, kind)
    seen = ros.python(PROBE_SETUP + """
feedback = []
client.send_goal(goal((1.0, [0.6, 0.5, 1.0]), (2.0, [1.0, 0.3, 2.0])), feedback_cb=feedback.append)
assert client.wait_for_result(rospy.Duration(20))
done = {'state': client.get_state(), 'result': [client.get_result().error_code, client.get_result().error_string],
        'feedback': len(feedback), 'feedback_joints': list(feedback[-1].joint_names)}
joints = rospy.wait_for_message('/arm/joint_states', JointState, 10)
done['positions'] = [joints.position[joints.name.index(j)] for j in JOINTS]
state = rospy.wait_for_message('/arm/arm_controller/state', JointTrajectoryControllerState, 10)
done['state_desired'] = list(state.desired.positions)

client.send_goal(goal((3.0, [-1.0, 0.0, 0.0])))
rospy.sleep(0.5)
client.send_goal(goal((1.0, [0.0, 0.2, 0.0])))  # the first is preempted
assert client.wait_for_result(rospy.Duration(20))
done['after_preempt'] = client.get_state()

client.send_goal(goal((3.0, [1.5, 0.2, 0.0])))
rospy.sleep(0.5)
client.cancel_goal()
assert client.wait_for_result(rospy.Duration(10))
done['cancelled'] = client.get_state()

client.send_goal(goal((1.0, [0.0, 0.0]), joints=['shoulder', 'elbow']))
assert client.wait_for_result(rospy.Duration(10))
done['rejected'] = [client.get_state(), client.get_result().error_code, client.get_goal_status_text()]
print(json.dumps(done))
""", timeout=120)
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
    seen = ros.python("""
import json, rospy
from control_msgs.msg import JointTrajectoryControllerState
from trajectory_msgs.msg import JointTrajectory, JointTrajectoryPoint
from ros_harness import connected_publisher
rospy.init_node('probe')
states = []
rospy.Subscriber('/arm/arm_controller/state', JointTrajectoryControllerState, states.append)
pub = connected_publisher('/arm/arm_controller/command', JointTrajectory, queue_size=1, latch=True)
rospy.sleep(1.0)
t = JointTrajectory(joint_names=['elbow', 'shoulder', 'wrist'])
t.points.append(JointTrajectoryPoint(positions=[0.4, -0.6, 0.0], time_from_start=rospy.Duration(1.0)))
pub.publish(t)
rospy.sleep(2.5)
last = states[-1]
stamps = [s.header.stamp.to_sec() for s in states[-20:]]
from control_msgs.srv import QueryTrajectoryState
query = rospy.ServiceProxy('/arm/arm_controller/query_state', QueryTrajectoryState)
queried = query(rospy.Time.now())
try:
    query(rospy.Time(0.001))
    early = 'answered'
except rospy.ServiceException as e:
    early = 'failed'
print(json.dumps({'names': list(last.joint_names), 'actual': list(last.actual.positions),
                  'error': list(last.error.positions), 'period': (stamps[-1] - stamps[0]) / (len(stamps) - 1),
                  'queried': [list(queried.name), list(queried.position), list(queried.velocity)], 'early': early}))
""", timeout=60)
    assert seen['queried'] == [['shoulder', 'elbow', 'wrist'], pytest.approx([-0.6, 0.4, 0.0], abs=1e-9), [0, 0, 0]], \
        'query_state: the trajectory held at its last point'
    assert seen['early'] == 'failed', 'a time before the trajectory fails the call, as upstream returns false'
    assert seen['names'] == ['shoulder', 'elbow', 'wrist']
    assert seen['actual'] == pytest.approx([-0.6, 0.4, 0.0], abs=0.02), 'reordered by name'
    assert max(abs(e) for e in seen['error']) < 0.02
    assert seen['period'] == pytest.approx(1 / 25, rel=0.05), 'state_publish_rate 25'
