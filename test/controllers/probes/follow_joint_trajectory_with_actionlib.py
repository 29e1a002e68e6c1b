"""The ROS side of test_joint_trajectory_controller_ros.py::test_follow_joint_trajectory_with_actionlib, a
rospy program the test runs against its own master (ros.probe); it prints one JSON value on its last line."""
from follow_joint_trajectory_probe import *  # noqa: F401,F403  (the node, client, goal, JOINTS)
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
