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
  bool hasCommand() const override { return true; }
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

// effort_controllers/JointPositionController and JointVelocityController. The PID is control_toolbox's,
// applied through the joint's implicit effort law (see Pid::implicitPositionLaw), which keeps the
// tutorial's gains stable at the steering hinges' tiny inertia.
class EffortPidController : public CommandedController
{
public:
  explicit EffortPidController(bool position) : position_(position) {}

  bool hasState() const override { return true; }

  bool init(ControllerContext& c) override
  {
    std::string joint;
    handle_ = claimJoint(c, JointInterface::Effort, joint, claimed_);
    if (!handle_)
      return false;
    try
    {
      pid_.setGains(readPidGains(c.params, joinPath(c.ns, "pid")));
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
    command_ = position_ ? limited(handle_->position()) : 0.0;
    pid_.reset();
    loop_count_ = 0;
    law_applied_ = false;
  }

  void stopping(int64_t) override
  {
    // As with the real controller, the joint keeps the last effort once nobody updates it.
    handle_->setCommand(handle_->effort());
  }

  void update(int64_t time_ns, double period) override
  {
    const double q = handle_->position(), qd = handle_->velocity();
    const double target = position_ ? limited(command_) : command_;
    if (law_applied_)
      pid_.endImplicitStep(error(last_target_, q, qd), handle_->effort(), period);
    double e = error(target, q, qd);
    EffortLaw law = position_ ? pid_.implicitPositionLaw(e, q, period) : pid_.implicitVelocityLaw(target, qd, period);
    handle_->setEffortLaw(law);
    law_applied_ = true;
    last_target_ = target;

    if (loop_count_ % 10 == 0)
    {
      ControllerStateSample s;
      s.stamp_ns = time_ns;
      s.set_point = target;
      s.process_value = position_ ? q : qd;
      s.process_value_dot = position_ ? qd : 0.0;
      s.error = e;
      s.time_step = period;
      s.command = handle_->effort();
      const PidGains& g = pid_.gains();
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
  double limited(double target) const
  {
    const JointLimits& l = handle_->limits();
    return l.has_position ? std::max(l.lower, std::min(target, l.upper)) : target;
  }
  double error(double target, double q, double qd) const
  {
    return position_ ? handle_->positionError(target, q) : target - qd;
  }

  bool position_;
  JointHandle* handle_ = nullptr;
  Pid pid_;
  double last_target_ = 0.0;
  bool law_applied_ = false;
  uint64_t loop_count_ = 0;
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
      {"effort_controllers/JointPositionController",
       [] { return std::unique_ptr<Controller>(new EffortPidController(true)); }},
      {"effort_controllers/JointVelocityController",
       [] { return std::unique_ptr<Controller>(new EffortPidController(false)); }},
      {"joint_state_controller/JointStateController",
       [] { return std::unique_ptr<Controller>(new JointStateController()); }},
      {"position_controllers/JointPositionController",
       [] { return std::unique_ptr<Controller>(new ForwardCommandController(JointInterface::Position)); }},
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
