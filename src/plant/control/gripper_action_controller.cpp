// gripper_action_controller (ros_controllers, ROS 1 Noetic): {position,effort}_controllers/
// GripperActionController. One joint driven to a control_msgs/GripperCommand goal on
// <ctrl>/gripper_cmd: the position kind commands the goal's position, the effort kind a PID
// (gains/<joint>) on the position error held to +-max_effort (0 is no effort at all, as upstream).
// The goal succeeds within goal_tolerance and aborts as stalled when the joint has moved slower than
// stall_velocity_threshold for stall_timeout short of it; either way the joint keeps being driven
// to the goal. Parameters, texts and what differs: docs/interfaces.md section 12.
#include <cmath>

#include "bullet_plant/action_messages.h"
#include "control/controller_support.h"

namespace bullet_plant
{
namespace
{
class GripperActionController : public Controller
{
public:
  explicit GripperActionController(JointInterface iface) : interface_(iface)
  {
    subscribe<ActionGoal<GripperCommandGoal>>("gripper_cmd/goal",
                                              [this](const ActionGoal<GripperCommandGoal>& g) { return onGoal(g); });
    subscribe<ActionCancel>("gripper_cmd/cancel", [this](const ActionCancel& c) { return onCancel(c); });
    result_port_ = &advertise<ActionResult<GripperCommandResult>>("gripper_cmd/result");
    // upstream never publishes feedback; the port exists because the action has the topic
    advertise<ActionFeedback<GripperCommandResult>>("gripper_cmd/feedback");
  }

  bool init(ControllerContext& c) override
  {
    log_ = &c.log;
    const std::string joint = paramText(c, "joint", "");
    if (joint.empty())
    {
      c.log.error("Could not find joint name on param server (set " + c.ns + "/joint to the gripper's joint)");
      return false;
    }
    handle_ = c.joints.handle(joint);
    if (!handle_ || handle_->interface() != interface_)
    {
      c.log.error("Could not find joint '" + joint + "' in '" + interfaceName(interface_) + "'.");
      return false;
    }
    claimed_.assign(1, ClaimedResources{interfaceName(interface_), {joint}});
    goal_tolerance_ = std::fabs(paramNumber(c, "goal_tolerance", 0.01));
    default_max_effort_ = std::fabs(paramNumber(c, "max_effort", 0.0));
    stall_velocity_threshold_ = paramNumber(c, "stall_velocity_threshold", 0.001);
    stall_timeout_ = paramNumber(c, "stall_timeout", 1.0);
    if (interface_ == JointInterface::Effort)
    {
      const std::string gains = joinPath(c.ns, "gains/" + joint);
      try
      {
        pid_ = Pid(readPidGains(c.params, gains));
      }
      catch (const std::exception& e)
      {
        // upstream loads anyway and then runs on a null PID: the plant refuses the controller instead
        c.log.error(std::string(e.what()) + "\nFailed to initialize PID gains from ROS parameter server. Set " + gains +
                    "/p (and i, d).");
        return false;
      }
    }
    return true;
  }

  void starting(int64_t time_ns) override
  {
    running_ = true;
    command_ = GripperCommandGoal{handle_->position(), default_max_effort_};
    pid_.reset();
    if (interface_ == JointInterface::Effort)
      handle_->setCommand(0.0);
    last_movement_ns_ = time_ns;
  }

  void stopping(int64_t) override
  {
    running_ = false;
    preemptActiveGoal();
  }

  void update(int64_t time_ns, double period) override
  {
    last_update_ns_ = time_ns;
    const double position = handle_->position(), velocity = handle_->velocity();
    const double position_error = command_.position - position;
    checkForSuccess(time_ns, position_error, position, velocity);
    if (interface_ == JointInterface::Position)
    {
      handle_->setCommand(command_.position);
      computed_command_ = command_.max_effort;  // what upstream reports as the effort
    }
    else
    {
      const double limit = std::fabs(command_.max_effort);
      computed_command_ = std::fmax(-limit, std::fmin(limit, pid_.computeCommand(position_error, -velocity, period)));
      handle_->setCommand(computed_command_);
    }
  }

private:
  bool onGoal(const ActionGoal<GripperCommandGoal>& g)
  {
    if (!running_)
    {
      const std::string text = "Can't accept new action goals. Controller is not running.";
      log_->error(text);
      result_port_->publish(ActionResult<GripperCommandResult>{g.id, GoalOutcome::Rejected, GripperCommandResult(), text});
      return false;
    }
    if (!std::isfinite(g.goal.position) || !std::isfinite(g.goal.max_effort))
    {
      const std::string text = "GripperCommand goal with a non-finite position or max_effort: refused";
      log_->error(text);
      result_port_->publish(ActionResult<GripperCommandResult>{g.id, GoalOutcome::Rejected, GripperCommandResult(), text});
      return false;
    }
    preemptActiveGoal();
    command_ = g.goal;
    last_movement_ns_ = last_update_ns_;
    active_goal_ = g.id;
    return true;
  }

  bool onCancel(const ActionCancel& c)
  {
    if (c.id.empty() || c.id != active_goal_)
      return true;
    command_ = GripperCommandGoal{handle_->position(), default_max_effort_};  // hold where it is
    finish(GoalOutcome::Canceled, GripperCommandResult());
    return true;
  }

  void preemptActiveGoal()
  {
    if (!active_goal_.empty())
      finish(GoalOutcome::Canceled, GripperCommandResult());
  }

  void finish(GoalOutcome outcome, const GripperCommandResult& result)
  {
    result_port_->publish(ActionResult<GripperCommandResult>{active_goal_, outcome, result, ""});
    active_goal_.clear();
  }

  void checkForSuccess(int64_t time_ns, double position_error, double position, double velocity)
  {
    if (active_goal_.empty())
      return;
    if (std::fabs(position_error) < goal_tolerance_)
      return finish(GoalOutcome::Succeeded, GripperCommandResult{position, computed_command_, false, true});
    if (std::fabs(velocity) > stall_velocity_threshold_)
      last_movement_ns_ = time_ns;
    else if ((time_ns - last_movement_ns_) * 1e-9 > stall_timeout_)
      finish(GoalOutcome::Aborted, GripperCommandResult{position, computed_command_, true, false});
  }

  JointInterface interface_;
  Log* log_ = nullptr;
  JointHandle* handle_ = nullptr;
  Pid pid_;
  double goal_tolerance_ = 0.01, default_max_effort_ = 0.0, stall_velocity_threshold_ = 0.001, stall_timeout_ = 1.0;
  bool running_ = false;
  GripperCommandGoal command_;
  double computed_command_ = 0.0;  // the last effort computed (the position kind: max_effort)
  int64_t last_movement_ns_ = 0, last_update_ns_ = 0;
  std::string active_goal_;
  OutputPort<ActionResult<GripperCommandResult>>* result_port_ = nullptr;
};
}  // namespace

ROS_CONTROLLER_TYPE(effort_gripper, "effort_controllers/GripperActionController",
                    controllerFactory<GripperActionController>(JointInterface::Effort));
ROS_CONTROLLER_TYPE(position_gripper, "position_controllers/GripperActionController",
                    controllerFactory<GripperActionController>(JointInterface::Position));

}  // namespace bullet_plant
