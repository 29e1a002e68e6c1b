"""The ROS side of test_gripper_action_controller.py::test_gripper_command_with_actionlib, a rospy program the
test runs against its own master (ros.probe); it prints one JSON value on its last line."""
import json, rospy, actionlib
from control_msgs.msg import GripperCommandAction, GripperCommandGoal
rospy.init_node('probe')
client = actionlib.SimpleActionClient('/gripper/gripper_controller/gripper_cmd', GripperCommandAction)
assert client.wait_for_server(rospy.Duration(30))
goal = GripperCommandGoal()
goal.command.position, goal.command.max_effort = 0.025, 10.0
client.send_goal(goal)
assert client.wait_for_result(rospy.Duration(10))
r = client.get_result()
reached = [client.get_state(), r.position, r.reached_goal, r.stalled]
goal.command.position = 0.08
client.send_goal(goal)
assert client.wait_for_result(rospy.Duration(10))
r = client.get_result()
print(json.dumps({'reached': reached, 'stalled': [client.get_state(), r.position, r.reached_goal, r.stalled]}))
