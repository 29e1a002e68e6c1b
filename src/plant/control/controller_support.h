// What the controller families share (private to control/): parameter lookup, claiming a joint
// the way hardware_interface's getHandle does, and the bases of the controllers with a command
// topic: one joint and a std_msgs/Float64, or a joint group and a std_msgs/Float64MultiArray.
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "bullet_plant/controllers.h"
#include "bullet_plant/log.h"
#include "bullet_plant/params.h"
#include "bullet_plant/rate_gate.h"

namespace bullet_plant
{
inline const Param* param(const ControllerContext& c, const std::string& key) { return c.params.find(joinPath(c.ns, key)); }

// A parameter of the controller's namespace, or `fallback` when absent or of another type (as
// NodeHandle::param does).
inline std::string paramText(const ControllerContext& c, const std::string& key, const std::string& fallback)
{
  const Param* p = param(c, key);
  return p && p->type() == Param::Type::String ? p->asString() : fallback;
}
inline double paramNumber(const ControllerContext& c, const std::string& key, double fallback)
{
  const Param* p = param(c, key);
  return p && p->isNumber() ? p->asDouble() : fallback;
}
inline bool paramFlag(const ControllerContext& c, const std::string& key, bool fallback)
{
  const Param* p = param(c, key);
  return p && p->type() == Param::Type::Bool ? p->asBool() : fallback;
}

// The named joint's handle on the interface the controller type needs (hardware_interface's
// getHandle, whose failure text this reproduces).
inline JointHandle* claimJoint(ControllerContext& c, JointInterface iface, std::string& joint,
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

// A controller with a <controller>/command topic (std_msgs/Float64); a non-finite value is rejected.
class CommandedController : public Controller
{
public:
  CommandedController()
  {
    subscribe<double>("command", [this](const double& value) {
      if (!std::isfinite(value))
        return false;
      command_ = value;
      return true;
    });
  }

protected:
  double command_ = 0.0;
};

// A controller of several joints commanded together by a Float64MultiArray on <controller>/command
// (forward_command_controller's ForwardJointGroupCommandController and
// effort_controllers/JointGroupPositionController, docs/interfaces.md section 12).
class JointGroupController : public Controller
{
public:
  JointGroupController()
  {
    subscribe<std::vector<double>>("command", [this](const std::vector<double>& values) { return setCommands(values); });
  }

protected:
  bool setCommands(const std::vector<double>& values)
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

}  // namespace bullet_plant
