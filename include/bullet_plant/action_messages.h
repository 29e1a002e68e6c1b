// The controllers' actions as the plant's ports carry them: the shape of an action an owner serves
// (actionlib's server side) and the messages of FollowJointTrajectory (trajectory_msgs,
// control_msgs) and GripperCommand.
// The node carries an action with actionlib itself (src/node/port_topics.cpp); here an action is
// four ports on actionlib's own topic names under the action's name:
//   <action>/goal      in   ActionGoal<Goal>: delivered true = accepted, false = rejected (the owner
//                           then publishes the Rejected result with its reason)
//   <action>/cancel    in   ActionCancel: cancel that goal if it is still active
//   <action>/result    out  ActionResult<Result>: how each goal ended
//   <action>/feedback  out  ActionFeedback<Feedback>
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace bullet_plant
{
// trajectory_msgs/JointTrajectoryPoint; a vector left empty was not given.
struct TrajectoryPointSample
{
  std::vector<double> positions, velocities, accelerations, effort;
  int64_t time_from_start_ns = 0;
};

// trajectory_msgs/JointTrajectory; stamp 0 means "start now".
struct JointTrajectoryCommand
{
  int64_t stamp_ns = 0;
  std::string frame_id;  // the header's (gazebo_ros_joint_pose_trajectory's reference link)
  std::vector<std::string> joint_names;
  std::vector<TrajectoryPointSample> points;
};

// control_msgs/JointTolerance: 0 keeps the controller's default, -1 removes the bound.
struct JointToleranceSpec
{
  std::string name;
  double position = 0, velocity = 0, acceleration = 0;
};

// control_msgs/FollowJointTrajectoryGoal.
struct FollowJointTrajectoryGoal
{
  JointTrajectoryCommand trajectory;
  std::vector<JointToleranceSpec> path_tolerance, goal_tolerance;
  int64_t goal_time_tolerance_ns = 0;
};

// control_msgs/FollowJointTrajectoryResult.
struct FollowJointTrajectoryResult
{
  enum : int32_t
  {
    SUCCESSFUL = 0,
    INVALID_GOAL = -1,
    INVALID_JOINTS = -2,
    OLD_HEADER_TIMESTAMP = -3,
    PATH_TOLERANCE_VIOLATED = -4,
    GOAL_TOLERANCE_VIOLATED = -5
  };
  int32_t error_code = SUCCESSFUL;
  std::string error_string;
};

// control_msgs/JointTrajectoryControllerState, and FollowJointTrajectoryFeedback (the same fields).
struct TrajectoryStateSample
{
  int64_t stamp_ns = 0;
  std::vector<std::string> joint_names;
  TrajectoryPointSample desired, actual, error;  // error = desired - actual
};

// control_msgs/QueryTrajectoryState: the controller's trajectory sampled at a time (ROS time, ns).
struct QueryTrajectoryStateRequest
{
  int64_t time_ns = 0;
};

struct QueryTrajectoryStateResponse
{
  std::vector<std::string> name;
  std::vector<double> position, velocity, acceleration;
};

// control_msgs/GripperCommand: the goal of GripperCommand.action.
struct GripperCommandGoal
{
  double position = 0, max_effort = 0;
};

// control_msgs/GripperCommandResult (and its Feedback, the same fields).
struct GripperCommandResult
{
  double position = 0, effort = 0;
  bool stalled = false, reached_goal = false;
};

// A goal as actionlib's server hands it over: its id (unique per goal) and the goal.
template <class Goal>
struct ActionGoal
{
  std::string id;
  Goal goal;
};

struct ActionCancel
{
  std::string id;
};

// How a goal ended: actionlib's setRejected, setSucceeded, setAborted and setCanceled (an active
// goal's cancel is reported PREEMPTED, a pending one's RECALLED, as actionlib does).
enum class GoalOutcome { Rejected, Succeeded, Aborted, Canceled };

template <class Result>
struct ActionResult
{
  std::string id;
  GoalOutcome outcome = GoalOutcome::Succeeded;
  Result result;
  std::string text;
};

template <class Feedback>
struct ActionFeedback
{
  std::string id;
  Feedback feedback;
};

}  // namespace bullet_plant
