// control_toolbox's PID (docs/interfaces.md section 4), plus the implicit form the plant uses to
// apply it stably to joints whose inertia is tiny compared to the gains.
#pragma once

#include <string>

namespace bullet_plant
{
class Param;

struct PidGains
{
  double p = 0.0, i = 0.0, d = 0.0;
  double i_max = 0.0, i_min = 0.0;  // bounds of the integral term
  bool antiwindup = false;          // clamp the integral itself instead of the term

  // control_toolbox's i_clamp: the integral term is bounded to [-|i_clamp|, |i_clamp|].
  static PidGains withIClamp(double p, double i, double d, double i_clamp, bool antiwindup = false);
};

// Reads p (required), i, d, i_clamp, i_clamp_min, i_clamp_max, antiwindup under ns in the tree.
// Throws std::runtime_error("No p gain specified for pid.  Namespace: <ns>") without p.
PidGains readPidGains(const Param& root, const std::string& ns);

// An effort as a function of the joint's state at the END of the coming step:
//   effort = feedforward + stiffness * (position_target - q') + damping * (velocity_target - qd')
// with q' = q + dt * qd' (the integrator's). The joint layer turns it into a soft constraint, which
// is unconditionally stable where the same law applied explicitly would blow up.
struct EffortLaw
{
  double feedforward = 0.0;
  double stiffness = 0.0, position_target = 0.0;
  double damping = 0.0, velocity_target = 0.0;
  bool implicit() const { return stiffness != 0.0 || damping != 0.0; }
};

class Pid
{
public:
  explicit Pid(const PidGains& gains = PidGains()) : gains_(gains) {}

  void setGains(const PidGains& gains) { gains_ = gains; }
  const PidGains& gains() const { return gains_; }
  void reset();

  // control_toolbox::Pid::computeCommand(error, dt): derivative from the previous error.
  double computeCommand(double error, double dt);
  // control_toolbox::Pid::computeCommand(error, error_dot, dt).
  double computeCommand(double error, double error_dot, double dt);

  // The same controller with the proportional and derivative terms taken at the END of the coming
  // step (backward Euler) instead of its start; the integral stays explicit, as in computeCommand.
  // Velocity loop (gazebo_ros_control pid_gains): error = velocity_command - velocity.
  EffortLaw implicitVelocityLaw(double velocity_command, double velocity, double dt);
  // Position loop (effort_controllers/JointPositionController): error = position_error, already
  // wrapped or limited by the caller; the target is position + position_error.
  EffortLaw implicitPositionLaw(double position_error, double position, double dt);
  // After the step: the error it ended with and the effort actually applied (for state reports and
  // the next derivative).
  void endImplicitStep(double error_after, double applied_command, double dt);

  double pError() const { return p_error_; }
  double iError() const { return i_error_; }
  double dError() const { return d_error_; }
  double command() const { return cmd_; }

private:
  double integralTerm(double error, double dt);

  PidGains gains_;
  double p_error_last_ = 0.0, p_error_ = 0.0, i_error_ = 0.0, d_error_ = 0.0, cmd_ = 0.0;
};

}  // namespace bullet_plant
