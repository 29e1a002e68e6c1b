// effort_controllers' PID types: JointPositionController and JointVelocityController (one joint,
// control_toolbox's PID toward a Float64 target) and JointGroupPositionController (one PID per joint).
#include "control/controller_support.h"

#include <algorithm>

namespace bullet_plant
{
namespace
{
// One effort joint driven by control_toolbox's PID toward a position or velocity target, applied
// through the joint's implicit effort law (see Pid::implicitPositionLaw), which keeps the tutorial's
// gains stable at the steering hinges' tiny inertia. Shared by the single and the group controllers.
class EffortLoop
{
public:
  EffortLoop(JointHandle* handle, bool position) : handle_(handle), position_(position) {}

  JointHandle& handle() { return *handle_; }
  Pid& pid() { return pid_; }
  void reset()
  {
    pid_.reset();
    law_applied_ = false;
  }
  // A position target within the joint's URDF limits (revolute and prismatic joints).
  double limited(double target) const
  {
    const JointLimits& l = handle_->limits();
    return position_ && l.has_position ? std::max(l.lower, std::min(target, l.upper)) : target;
  }
  // Closes the previous step's loop and sets the law for the coming one; returns the error it acts on.
  double drive(double target, double period)
  {
    const double q = handle_->position(), qd = handle_->velocity();
    if (law_applied_)
      pid_.endImplicitStep(error(last_target_, q, qd), handle_->effort(), period);
    const double e = error(target, q, qd);
    handle_->setEffortLaw(position_ ? pid_.implicitPositionLaw(e, q, period)
                                    : pid_.implicitVelocityLaw(target, qd, period));
    law_applied_ = true;
    last_target_ = target;
    return e;
  }

private:
  double error(double target, double q, double qd) const
  {
    return position_ ? handle_->positionError(target, q) : target - qd;
  }

  JointHandle* handle_;
  bool position_;
  Pid pid_;
  double last_target_ = 0.0;
  bool law_applied_ = false;
};

// effort_controllers/JointPositionController and JointVelocityController.
class EffortPidController : public CommandedController
{
public:
  explicit EffortPidController(bool position) : position_(position) {}

  bool init(ControllerContext& c) override
  {
    state_ = &advertise<ControllerStateSample>("state");
    std::string joint;
    JointHandle* handle = claimJoint(c, JointInterface::Effort, joint, claimed_);
    if (!handle)
      return false;
    loop_.reset(new EffortLoop(handle, position_));
    try
    {
      loop_->pid().setGains(readPidGains(c.params, joinPath(c.ns, "pid")));
    }
    catch (const std::exception& e)
    {
      c.log.error(e.what());
      return false;
    }
    return true;
  }

  void starting(int64_t) override
  {
    command_ = position_ ? loop_->limited(loop_->handle().position()) : 0.0;
    loop_->reset();
    loop_count_ = 0;
  }

  void stopping(int64_t) override
  {
    // As with the real controller, the joint keeps the last effort once nobody updates it.
    loop_->handle().setCommand(loop_->handle().effort());
  }

  void update(int64_t time_ns, double period) override
  {
    const JointHandle& h = loop_->handle();
    const double q = h.position(), qd = h.velocity();
    const double target = loop_->limited(command_);
    const double e = loop_->drive(target, period);

    if (loop_count_ % 10 == 0)
    {
      ControllerStateSample s;
      s.stamp_ns = time_ns;
      s.set_point = target;
      s.process_value = position_ ? q : qd;
      s.process_value_dot = position_ ? qd : 0.0;
      s.error = e;
      s.time_step = period;
      s.command = h.effort();
      const PidGains& g = loop_->pid().gains();
      s.p = g.p;
      s.i = g.i;
      s.d = g.d;
      s.i_clamp = g.i_max;
      s.antiwindup = g.antiwindup;
      state_->publish(s);
    }
    ++loop_count_;
  }

private:
  bool position_;
  OutputPort<ControllerStateSample>* state_ = nullptr;
  std::unique_ptr<EffortLoop> loop_;
  uint64_t loop_count_ = 0;
};

// effort_controllers/JointGroupPositionController: one PID per joint, gains in <controller>/<joint>/pid.
class EffortGroupPositionController : public JointGroupController
{
public:
  bool init(ControllerContext& c) override
  {
    if (!claimJoints(c, JointInterface::Effort))
      return false;
    for (JointHandle* h : handles_)
    {
      loops_.emplace_back(h, true);
      try
      {
        loops_.back().pid().setGains(readPidGains(c.params, joinPath(c.ns, h->name() + "/pid")));
      }
      catch (const std::exception& e)
      {
        c.log.error(e.what());
        c.log.error("Failed to load PID parameters from " + h->name() + "/pid");
        return false;
      }
    }
    return true;
  }

  void starting(int64_t) override
  {
    for (size_t k = 0; k < loops_.size(); ++k)
    {
      commands_[k] = loops_[k].limited(handles_[k]->position());
      loops_[k].reset();
    }
  }

  void update(int64_t, double period) override
  {
    for (size_t k = 0; k < loops_.size(); ++k)
      loops_[k].drive(loops_[k].limited(commands_[k]), period);
  }

private:
  std::vector<EffortLoop> loops_;
};
}  // namespace

ROS_CONTROLLER_TYPE(effort_position, "effort_controllers/JointPositionController",
                    controllerFactory<EffortPidController>(true));
ROS_CONTROLLER_TYPE(effort_velocity, "effort_controllers/JointVelocityController",
                    controllerFactory<EffortPidController>(false));
ROS_CONTROLLER_TYPE(effort_group_position, "effort_controllers/JointGroupPositionController",
                    controllerFactory<EffortGroupPositionController>());

}  // namespace bullet_plant
