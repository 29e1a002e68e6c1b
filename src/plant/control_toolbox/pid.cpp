#include "bullet_plant/pid.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "bullet_plant/log.h"
#include "bullet_plant/params.h"

namespace bullet_plant
{
namespace
{
bool finite(double v) { return std::isfinite(v); }

double number(const Param& root, const std::string& path, double fallback)
{
  const Param* p = root.find(path);
  return p && p->isNumber() ? p->asDouble() : fallback;
}
}  // namespace

PidGains readPidGains(const Param& root, const std::string& ns)
{
  const Param* p = root.find(joinPath(ns, "p"));
  if (!p || !p->isNumber())
    throw std::runtime_error("No p gain specified for pid.  Namespace: " + normaliseNamespace(ns));
  const Param* antiwindup = root.find(joinPath(ns, "antiwindup"));
  PidGains g = PidGains::withIClamp(p->asDouble(), number(root, joinPath(ns, "i"), 0.0),
                                    number(root, joinPath(ns, "d"), 0.0), number(root, joinPath(ns, "i_clamp"), 0.0),
                                    antiwindup && antiwindup->type() == Param::Type::Bool && antiwindup->asBool());
  g.i_max = number(root, joinPath(ns, "i_clamp_max"), g.i_max);
  g.i_min = number(root, joinPath(ns, "i_clamp_min"), g.i_min);
  // A NaN or infinite gain would make the controller run and do nothing (or blow up): refuse it.
  const std::pair<const char*, double> gains[] = {{"p", g.p}, {"i", g.i}, {"d", g.d}, {"i_clamp", g.i_max},
                                                  {"i_clamp_min", g.i_min}};
  for (const auto& gain : gains)
    if (!std::isfinite(gain.second))
      throw std::runtime_error("PID gain '" + std::string(gain.first) + "' of " + normaliseNamespace(ns) + " is " +
                               formatNumber(gain.second) + "; gains must be finite numbers");
  return g;
}

PidGains PidGains::withIClamp(double p, double i, double d, double i_clamp, bool antiwindup)
{
  PidGains g;
  g.p = p;
  g.i = i;
  g.d = d;
  g.i_max = std::abs(i_clamp);
  g.i_min = -std::abs(i_clamp);
  g.antiwindup = antiwindup;
  return g;
}

void Pid::reset()
{
  p_error_last_ = p_error_ = i_error_ = d_error_ = cmd_ = 0.0;
}

double Pid::computeCommand(double error, double dt)
{
  if (dt == 0.0 || !finite(error))
    return 0.0;
  double error_dot = d_error_;
  if (dt > 0.0)
  {
    error_dot = (error - p_error_last_) / dt;
    p_error_last_ = error;
  }
  return computeCommand(error, error_dot, dt);
}

double Pid::integralTerm(double error, double dt)
{
  i_error_ += dt * error;
  if (gains_.antiwindup && gains_.i != 0.0)
    i_error_ = std::max(gains_.i_min / std::abs(gains_.i), std::min(i_error_, gains_.i_max / std::abs(gains_.i)));
  double i_term = gains_.i * i_error_;
  if (!gains_.antiwindup)
    i_term = std::max(gains_.i_min, std::min(i_term, gains_.i_max));
  return i_term;
}

double Pid::computeCommand(double error, double error_dot, double dt)
{
  p_error_ = error;
  d_error_ = error_dot;
  if (dt == 0.0 || !finite(error) || !finite(error_dot))
    return 0.0;
  double p_term = gains_.p * p_error_;
  double i_term = integralTerm(p_error_, dt);
  double d_term = gains_.d * d_error_;
  cmd_ = p_term + i_term + d_term;
  return cmd_;
}

// Both laws below are computeCommand(error, dt) with error and error_dot evaluated at the end of
// the step, written as EffortLaw's feedforward + stiffness*(q* - q') + damping*(v* - qd').

EffortLaw Pid::implicitVelocityLaw(double velocity_command, double velocity, double dt)
{
  EffortLaw law;
  double error = velocity_command - velocity;
  p_error_ = error;
  if (dt <= 0.0 || !finite(error))
    return law;
  // p*(v - qd') + d*((v - qd') - e_last)/dt
  law.damping = gains_.p + gains_.d / dt;
  law.velocity_target = velocity_command;
  law.feedforward = integralTerm(error, dt) - gains_.d / dt * p_error_last_;
  return law;
}

EffortLaw Pid::implicitPositionLaw(double position_error, double position, double dt)
{
  EffortLaw law;
  p_error_ = position_error;
  if (dt <= 0.0 || !finite(position_error))
    return law;
  // p*(q* - q') + d*((q* - q') - e_last)/dt, with q* - q' = e - dt*qd'
  law.stiffness = gains_.p;
  law.position_target = position + position_error;
  law.damping = gains_.d;
  law.velocity_target = 0.0;
  law.feedforward = integralTerm(position_error, dt) + gains_.d / dt * (position_error - p_error_last_);
  return law;
}

void Pid::endImplicitStep(double error_after, double applied_command, double dt)
{
  if (!finite(error_after))
    return;
  d_error_ = dt > 0.0 ? (error_after - p_error_last_) / dt : 0.0;
  p_error_ = error_after;
  p_error_last_ = error_after;
  cmd_ = applied_command;
}

}  // namespace bullet_plant
