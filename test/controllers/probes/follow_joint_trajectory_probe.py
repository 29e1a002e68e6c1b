"""The start the arm's FollowJointTrajectory probes share (`from follow_joint_trajectory_probe import *`): a
rospy node, actionlib's SimpleActionClient of /arm/arm_controller connected, goal() of (time, positions)
points, JOINTS."""
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
