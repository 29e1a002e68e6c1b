// gazebo_ros_control's DefaultRobotHWSim semantics (docs/interfaces.md section 5): one handle per
// transmitted joint, with the URDF limits, optional pid_gains, e-stop, and commands checked before
// they reach the physics.
#pragma once

#include <memory>
#include <string>

#include "bullet_plant/joint_limits.h"
#include "bullet_plant/pid.h"

namespace bullet_plant
{
class JointLayer;  // the plant side of the handles (joint_layer.cpp)

enum class JointInterface { Effort, Velocity, Position };

const char* interfaceName(JointInterface iface);  // "hardware_interface::EffortJointInterface", ...

// What a controller (or Python) writes into a joint, and what the joint reports back.
class JointHandle
{
public:
  JointHandle(std::string name, JointType type, JointInterface iface, const JointLimits& limits)
    : name_(std::move(name)), type_(type), interface_(iface), limits_(limits) {}

  const std::string& name() const { return name_; }
  JointType type() const { return type_; }
  JointInterface interface() const { return interface_; }
  const JointLimits& limits() const { return limits_; }

  // The command in the interface's unit (N m or N, rad/s or m/s, rad or m). A non-finite value is
  // rejected (counted, the previous command stays) and false is returned.
  bool setCommand(double value);
  double command() const { return command_; }
  // For controllers that compute an effort from the state (PID): the law replaces the command for
  // the next step and is applied implicitly. Effort joints only.
  void setEffortLaw(const EffortLaw& law);
  long rejectedCommands() const { return rejected_; }
  // The error a position loop on this joint sees: shortest way within the limits for revolute
  // joints, wrapped for continuous ones, plain for prismatic ones.
  double positionError(double target, double position) const;

  // The pid_gains/<joint> loop of a velocity or position joint; null when the joint has none.
  Pid* pid() { return pid_.get(); }
  void setPid(const PidGains& gains) { pid_.reset(new Pid(gains)); }

  // State after the last step.
  double position() const { return position_; }
  double velocity() const { return velocity_; }
  double effort() const { return effort_; }

private:
  friend class JointLayer;
  std::string name_;
  JointType type_;
  JointInterface interface_;
  JointLimits limits_;
  double command_ = 0.0;
  bool has_law_ = false;
  EffortLaw law_;
  long rejected_ = 0;
  std::unique_ptr<Pid> pid_;
  double position_ = 0.0, velocity_ = 0.0, effort_ = 0.0;
  double position_at_estop_ = 0.0;
  double active_target_ = 0.0;  // the (clamped) target the joint was driven to in the last step
};

}  // namespace bullet_plant
