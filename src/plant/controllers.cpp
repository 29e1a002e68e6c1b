// The ros_controllers types: joint_state_controller, forward command controllers (velocity,
// effort, position) and the effort PID controllers, on the plant's joint handles.
#include "bullet_plant/controllers.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>

#include "bullet_plant/log.h"
#include "bullet_plant/params.h"

namespace bullet_plant
{
std::vector<JointStateSample> Controller::takeJointStates()
{
  std::vector<JointStateSample> out;
  out.swap(joint_states_);
  return out;
}

std::vector<ControllerStateSample> Controller::takeControllerStates()
{
  std::vector<ControllerStateSample> out;
  out.swap(controller_states_);
  return out;
}

void Controller::emit(const JointStateSample& s)
{
  latest_joint_state_ = s;
  has_joint_state_ = true;
  ++samples_;
  if (joint_states_.size() < 1000)  // nobody draining (Python): keep the latest only
    joint_states_.push_back(s);
}

void Controller::emit(const ControllerStateSample& s)
{
  latest_state_ = s;
  has_state_ = true;
  ++samples_;
  if (controller_states_.size() < 1000)
    controller_states_.push_back(s);
}

namespace
{
const Param* param(const ControllerContext& c, const std::string& key) { return c.params.find(joinPath(c.ns, key)); }

// The named joint's handle on the interface the controller type needs (hardware_interface's
// getHandle, whose failure text this reproduces).
JointHandle* claimJoint(ControllerContext& c, JointInterface iface, std::string& joint,
                        std::vector<ClaimedResources>& claimed)
{
  const Param* p = param(c, "joint");
  if (!p || p->type() != Param::Type::String)
  {
    c.log.error("No joint given (namespace: " + c.ns + ")");
    return nullptr;
  }
  joint = p->asString();
  JointHandle* h = c.joints.handle(joint);
  if (!h || h->interface() != iface)
  {
    c.log.error("Could not find resource '" + joint + "' in '" + interfaceName(iface) + "'.");
    return nullptr;
  }
  claimed.assign(1, ClaimedResources{interfaceName(iface), {joint}});
  return h;
}

// ------------------------------------------------------------------ joint_state_controller

class JointStateController : public Controller
{
public:
  bool init(ControllerContext& c) override
  {
    const Param* rate = param(c, "publish_rate");
    if (!rate || !rate->isNumber())
    {
      c.log.error("Parameter 'publish_rate' not set");
      return false;
    }
    publish_period_ns_ = rate->asDouble() > 0 ? int64_t(std::llround(1e9 / rate->asDouble())) : -1;
    // Default: every joint with a state handle, sorted by name as the hardware interface lists them.
    std::map<std::string, JointHandle*> by_name;
    for (JointHandle& h : c.joints.handles())
      by_name[h.name()] = &h;
    if (const Param* joints = param(c, "joints"))
    {
      if (joints->type() != Param::Type::List)
      {
        c.log.error("Parameter 'joints' of " + c.ns + " is not a list of joint names");
        return false;
      }
      for (const Param& j : joints->asList())
      {
        if (j.type() != Param::Type::String || !by_name.count(j.asString()))
        {
          c.log.error("Joint " + j.describe() + " given in " + c.ns + "/joints has no state handle");
          return false;
        }
        joints_.push_back(by_name[j.asString()]);
      }
    }
    else
      for (auto& kv : by_name)
        joints_.push_back(kv.second);
    if (const Param* extra = param(c, "extra_joints"))
      for (const Param& e : extra->type() == Param::Type::List ? extra->asList() : std::vector<Param>())
      {
        const Param* name = e.find("name");
        if (!name || name->type() != Param::Type::String)
        {
          c.log.error("Extra joint specification in " + c.ns + " has no name");
          return false;
        }
        auto number = [&](const char* key) { const Param* v = e.find(key); return v && v->isNumber() ? v->asDouble() : 0.0; };
        extra_.push_back({name->asString(), number("position"), number("velocity"), number("effort")});
      }
    claimed_.assign(1, ClaimedResources{kJointStateInterface, {}});
    return true;
  }

  void starting(int64_t time_ns) override { last_publish_ns_ = time_ns; }

  void update(int64_t time_ns, double) override
  {
    if (publish_period_ns_ <= 0 || last_publish_ns_ + publish_period_ns_ >= time_ns)
      return;
    last_publish_ns_ += publish_period_ns_;
    JointStateSample s;
    s.stamp_ns = time_ns;
    for (JointHandle* h : joints_)
    {
      s.name.push_back(h->name());
      s.position.push_back(h->position());
      s.velocity.push_back(h->velocity());
      s.effort.push_back(h->effort());
    }
    for (const Extra& e : extra_)
    {
      s.name.push_back(e.name);
      s.position.push_back(e.position);
      s.velocity.push_back(e.velocity);
      s.effort.push_back(e.effort);
    }
    emit(s);
  }

private:
  struct Extra { std::string name; double position, velocity, effort; };
  std::vector<JointHandle*> joints_;
  std::vector<Extra> extra_;
  int64_t publish_period_ns_ = 0, last_publish_ns_ = 0;
};

// A controller with a <controller>/command topic (std_msgs/Float64).
class CommandedController : public Controller
{
public:
  CommandTopic commandTopic() const override { return CommandTopic::Float64; }
  bool setCommand(double value) override
  {
    if (!std::isfinite(value))
      return false;
    command_ = value;
    return true;
  }

protected:
  double command_ = 0.0;
};

// ------------------------------------------------------------------ forward command controllers

class ForwardCommandController : public CommandedController
{
public:
  explicit ForwardCommandController(JointInterface iface) : interface_(iface) {}

  bool init(ControllerContext& c) override
  {
    std::string joint;
    handle_ = claimJoint(c, interface_, joint, claimed_);
    return handle_ != nullptr;
  }

  void starting(int64_t) override
  {
    // position_controllers start where the joint is; the others from 0
    command_ = interface_ == JointInterface::Position ? handle_->position() : 0.0;
  }

  void update(int64_t, double) override { handle_->setCommand(command_); }


private:
  JointInterface interface_;
  JointHandle* handle_ = nullptr;
};

// ------------------------------------------------------------------ effort PID controllers

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

  bool hasState() const override { return true; }

  bool init(ControllerContext& c) override
  {
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
      emit(s);
    }
    ++loop_count_;
  }

private:
  bool position_;
  std::unique_ptr<EffortLoop> loop_;
  uint64_t loop_count_ = 0;
};

// ------------------------------------------------------------------ joint group controllers

// A controller of several joints commanded together by a Float64MultiArray on <controller>/command
// (forward_command_controller's ForwardJointGroupCommandController and
// effort_controllers/JointGroupPositionController, docs/interfaces.md section 12).
class JointGroupController : public Controller
{
public:
  CommandTopic commandTopic() const override { return CommandTopic::Float64MultiArray; }

  bool setCommands(const std::vector<double>& values) override
  {
    if (values.size() != commands_.size())
    {
      log_->error("Dimension of command (" + std::to_string(values.size()) + ") does not match number of joints (" +
                  std::to_string(commands_.size()) + ")! Not executing!");
      return false;
    }
    for (double v : values)
      if (!std::isfinite(v))
      {
        log_->error("Rejected a command with a non-finite value for " + ns_ + " (the joints keep the last one)");
        return false;
      }
    commands_ = values;
    return true;
  }

protected:
  // The joints of the `joints` parameter on `iface`; false with upstream's error texts.
  bool claimJoints(ControllerContext& c, JointInterface iface)
  {
    log_ = &c.log;
    ns_ = c.ns;
    const Param* names = param(c, "joints");
    if (!names || names->type() != Param::Type::List)
    {
      c.log.error("Failed to getParam 'joints' (namespace: " + c.ns + ").");
      return false;
    }
    if (names->asList().empty())
    {
      c.log.error("List of joint names is empty.");
      return false;
    }
    ClaimedResources claimed{interfaceName(iface), {}};
    for (const Param& name : names->asList())
    {
      JointHandle* h = name.type() == Param::Type::String ? c.joints.handle(name.asString()) : nullptr;
      if (!h || h->interface() != iface)
      {
        c.log.error("Exception thrown: Could not find resource '" +
                    (name.type() == Param::Type::String ? name.asString() : name.describe()) + "' in '" +
                    interfaceName(iface) + "'.");
        return false;
      }
      handles_.push_back(h);
      claimed.resources.push_back(h->name());
    }
    claimed_.assign(1, claimed);
    commands_.assign(handles_.size(), 0.0);
    return true;
  }

  std::vector<JointHandle*> handles_;
  std::vector<double> commands_;

private:
  Log* log_ = nullptr;
  std::string ns_;
};

// position_controllers/, velocity_controllers/ and effort_controllers/JointGroup*Controller that
// forward each value to its joint: they start from the joints' positions (position) or from 0.
class ForwardGroupController : public JointGroupController
{
public:
  explicit ForwardGroupController(JointInterface iface) : interface_(iface) {}

  bool init(ControllerContext& c) override { return claimJoints(c, interface_); }

  void starting(int64_t) override
  {
    for (size_t k = 0; k < handles_.size(); ++k)
      commands_[k] = interface_ == JointInterface::Position ? handles_[k]->position() : 0.0;
  }

  void update(int64_t, double) override
  {
    for (size_t k = 0; k < handles_.size(); ++k)
      handles_[k]->setCommand(commands_[k]);
  }

private:
  JointInterface interface_;
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

struct ControllerType
{
  const char* name;
  std::function<std::unique_ptr<Controller>()> make;
};

const std::vector<ControllerType>& registry()
{
  static const std::vector<ControllerType> types = {
      {"effort_controllers/JointEffortController",
       [] { return std::unique_ptr<Controller>(new ForwardCommandController(JointInterface::Effort)); }},
      {"effort_controllers/JointGroupEffortController",
       [] { return std::unique_ptr<Controller>(new ForwardGroupController(JointInterface::Effort)); }},
      {"effort_controllers/JointGroupPositionController",
       [] { return std::unique_ptr<Controller>(new EffortGroupPositionController()); }},
      {"effort_controllers/JointPositionController",
       [] { return std::unique_ptr<Controller>(new EffortPidController(true)); }},
      {"effort_controllers/JointVelocityController",
       [] { return std::unique_ptr<Controller>(new EffortPidController(false)); }},
      {"joint_state_controller/JointStateController",
       [] { return std::unique_ptr<Controller>(new JointStateController()); }},
      {"position_controllers/JointGroupPositionController",
       [] { return std::unique_ptr<Controller>(new ForwardGroupController(JointInterface::Position)); }},
      {"position_controllers/JointPositionController",
       [] { return std::unique_ptr<Controller>(new ForwardCommandController(JointInterface::Position)); }},
      {"velocity_controllers/JointGroupVelocityController",
       [] { return std::unique_ptr<Controller>(new ForwardGroupController(JointInterface::Velocity)); }},
      {"velocity_controllers/JointVelocityController",
       [] { return std::unique_ptr<Controller>(new ForwardCommandController(JointInterface::Velocity)); }},
  };
  return types;
}
}  // namespace

const std::vector<std::string>& controllerTypes()
{
  static const std::vector<std::string> names = [] {
    std::vector<std::string> out;
    for (const ControllerType& t : registry())
      out.push_back(t.name);
    return out;
  }();
  return names;
}

std::unique_ptr<Controller> createController(const std::string& type)
{
  for (const ControllerType& t : registry())
    if (type == t.name)
      return t.make();
  return nullptr;
}

}  // namespace bullet_plant
