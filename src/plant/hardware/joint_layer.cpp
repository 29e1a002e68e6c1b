// gazebo_ros_control's joint layer: the handles controllers write (JointHandle) and the plant side
// that carries their commands into the physics and the physics' state back (JointLayer).
#include "bullet_plant/joint_layer.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "hardware/joint_layer_sim.h"

#include <BulletDynamics/Featherstone/btMultiBody.h>

namespace bullet_plant
{
namespace
{
constexpr double kInf = std::numeric_limits<double>::infinity();

double clampAbs(double v, double limit) { return std::max(-limit, std::min(v, limit)); }

double wrapToPi(double a)
{
  a = std::fmod(a + M_PI, 2.0 * M_PI);
  return a < 0 ? a + M_PI : a - M_PI;
}

// angles::shortest_angular_distance_with_large_limits, for a revolute joint's PID: the error that
// reaches the target without leaving [lower, upper].
double revoluteError(double from, double to, double lower, double upper)
{
  double delta = wrapToPi(to - from);
  double alternative = delta > 0 ? delta - 2 * M_PI : delta + 2 * M_PI;
  auto inside = [&](double d) { return from + d >= lower - 1e-9 && from + d <= upper + 1e-9; };
  if (inside(delta))
    return delta;
  if (inside(alternative))
    return alternative;
  return to - from;  // target outside the limits (clamped by the caller): go straight
}

// Applies an effort law to a joint: implicitly through its drive when the law depends on the
// end-of-step state, else as a plain (clamped) joint torque.
void applyLaw(MovableJoint& j, const btMultiBody& mb, const EffortLaw& law, double dt)
{
  double effort_limit = j.limits.effort;
  if (!law.implicit())
  {
    j.drive->disable();
    j.explicit_effort = clampAbs(law.feedforward, effort_limit);
    return;
  }
  // The joint's own damping joins the law: effort - c*qd' folds into the same row.
  double q = mb.getJointPos(j.link);
  double gain = law.stiffness * dt + law.damping + j.damping;  // effort per unit of end-of-step velocity error
  double target = (law.feedforward + law.stiffness * (law.position_target - q) + law.damping * law.velocity_target) / gain;
  j.drive->drive(target, gain * dt, effort_limit * dt);
}

// One-sided rows keep a joint within [lower, upper], only while it is about to reach a limit; a
// joint already past one is pushed back by a fifth of the overlap per step.
void limitRows(MovableJoint& j, double q, double qd, double dt)
{
  constexpr double kMargin = 1e-3, kRecovery = 0.2;
  const double next = q + qd * dt, reach = kMargin + std::abs(qd) * dt;
  const double below = q - j.limits.lower, above = j.limits.upper - q;
  if (next - j.limits.lower < reach)
    j.lower_limit->bound((below >= 0 ? -below : -below * kRecovery) / dt, true);
  else
    j.lower_limit->disable();
  if (j.limits.upper - next < reach)
    j.upper_limit->bound((above >= 0 ? above : above * kRecovery) / dt, false);
  else
    j.upper_limit->disable();
}

void driveRigid(MovableJoint& j, double target_velocity, double dt)
{
  j.drive->drive(clampAbs(target_velocity, std::min(j.limits.velocity, kMaxJointSpeed)), kInf, j.limits.effort * dt);
}

// The joints' passive dynamics: damping (where no drive carries it), springs, dry friction, limits;
// and the explicit efforts of this step as joint torques.
void passiveDynamics(std::vector<MovableJoint>& joints, btMultiBody& mb, double dt)
{
  for (MovableJoint& j : joints)
  {
    const double q = mb.getJointPos(j.link), qd = mb.getJointVel(j.link);
    double torque = j.explicit_effort;
    if (j.damping > 0 && !j.drive->enabled())
    {
      if (j.damper)
        j.damper->drive(0.0, j.damping * dt, kInf);
      else
        torque -= j.damping * qd;
    }
    else if (j.damper)
      j.damper->disable();
    if (j.spring_stiffness > 0)
    {
      const double stretch = q - j.spring_reference;
      // The row's impulse k dt^2 (-stretch / dt - qd') is dt times -k (q + qd' dt - reference): the
      // spring at the end of the step.
      if (j.spring)
        j.spring->drive(-stretch / dt, j.spring_stiffness * dt * dt, kInf);
      else
        torque -= j.spring_stiffness * stretch;
    }
    if (j.dry_friction && j.friction > 0)
      j.dry_friction->drive(j.friction_velocity, kInf, j.friction * dt);
    else if (j.dry_friction)
      j.dry_friction->disable();
    if (j.limits.has_position)
      limitRows(j, q, qd, dt);
    if (torque != 0.0)
      mb.addJointTorque(j.link, btScalar(torque));
  }
}
}  // namespace

const char* interfaceName(JointInterface iface)
{
  switch (iface)
  {
    case JointInterface::Effort: return "hardware_interface::EffortJointInterface";
    case JointInterface::Velocity: return "hardware_interface::VelocityJointInterface";
    case JointInterface::Position: return "hardware_interface::PositionJointInterface";
  }
  return "";
}

// ------------------------------------------------------------------------------------ JointHandle

bool JointHandle::setCommand(double value)
{
  if (!std::isfinite(value))
  {
    ++rejected_;
    return false;
  }
  command_ = value;
  has_law_ = false;
  return true;
}

void JointHandle::setEffortLaw(const EffortLaw& law)
{
  for (double v : {law.feedforward, law.stiffness, law.position_target, law.damping, law.velocity_target})
    if (!std::isfinite(v))
    {
      ++rejected_;
      return;
    }
  law_ = law;
  has_law_ = true;
}

double JointHandle::positionError(double target, double position) const
{
  switch (type_)
  {
    case JointType::Revolute:
      return limits_.has_position ? revoluteError(position, target, limits_.lower, limits_.upper)
                                  : wrapToPi(target - position);
    case JointType::Continuous:
      return wrapToPi(target - position);
    case JointType::Prismatic:
      break;
  }
  return target - position;
}

// ------------------------------------------------------------------------------------- JointLayer

JointHandle& JointLayer::addHandle(const MovableJoint& joint, size_t joint_index, JointInterface iface)
{
  handles_.emplace_back(joint.name, joint.type, iface, joint.limits);
  handle_joint_.push_back(joint_index);
  said_beyond_limit_.push_back(false);
  handles_.back().position_ = joint.initial_position;
  return handles_.back();
}

bool JointLayer::drives(size_t joint_index) const
{
  return std::find(handle_joint_.begin(), handle_joint_.end(), joint_index) != handle_joint_.end();
}

JointHandle* JointLayer::handle(const std::string& joint)
{
  for (JointHandle& h : handles_)
    if (h.name() == joint)
      return &h;
  return nullptr;
}

void JointLayer::setEStop(bool on)
{
  if (on && !e_stop_)
    for (JointHandle& h : handles_)
      h.position_at_estop_ = h.position_;
  e_stop_ = on;
}

void JointLayer::sayBeyondLimit(size_t hi, double command, double limit, const char* what)
{
  if (said_beyond_limit_[hi] || !(std::abs(command) > limit))
    return;
  said_beyond_limit_[hi] = true;
  if (log_)
    log_->warn("joint '" + handles_[hi].name() + "': command " + formatNumber(command) + " is beyond its " + what + " limit " +
               formatNumber(limit) + "; held to the limit (said once per joint)");
}

void JointLayer::writeSim(std::vector<MovableJoint>& joints, btMultiBody& mb, double dt)
{
  for (MovableJoint& j : joints)
    j.explicit_effort = 0.0;
  for (size_t hi = 0; hi < handles_.size(); ++hi)
  {
    JointHandle& h = handles_[hi];
    MovableJoint& j = joints[handle_joint_[hi]];
    const double q = mb.getJointPos(j.link), qd = mb.getJointVel(j.link);
    switch (h.interface())
    {
      case JointInterface::Effort:
      {
        EffortLaw law;
        if (e_stop_)
          law = EffortLaw();
        else if (h.has_law_)
          law = h.law_;
        else
        {
          law.feedforward = h.command_;
          sayBeyondLimit(hi, h.command_, j.limits.effort, "effort");
        }
        applyLaw(j, mb, law, dt);
        break;
      }
      case JointInterface::Velocity:
      {
        const double speed_limit = std::min(j.limits.velocity, kMaxJointSpeed);
        if (!e_stop_)
          sayBeyondLimit(hi, h.command_, speed_limit, "velocity");
        double target = e_stop_ ? 0.0 : clampAbs(h.command_, speed_limit);
        h.active_target_ = target;
        if (h.pid())
          applyLaw(j, mb, h.pid()->implicitVelocityLaw(target, qd, dt), dt);
        else
          driveRigid(j, target, dt);
        break;
      }
      case JointInterface::Position:
      {
        double target = e_stop_ ? h.position_at_estop_ : h.command_;
        if (j.limits.has_position)
          target = std::max(j.limits.lower, std::min(target, j.limits.upper));
        h.active_target_ = target;
        if (h.pid())
          applyLaw(j, mb, h.pid()->implicitPositionLaw(h.positionError(target, q), q, dt), dt);
        else
          driveRigid(j, (target - q) / dt, dt);
        break;
      }
    }
  }
  passiveDynamics(joints, mb, dt);
}

void JointLayer::readSim(const std::vector<MovableJoint>& joints, const btMultiBody& mb, double dt)
{
  for (size_t hi = 0; hi < handles_.size(); ++hi)
  {
    JointHandle& h = handles_[hi];
    const MovableJoint& j = joints[handle_joint_[hi]];
    h.position_ = mb.getJointPos(j.link);
    h.velocity_ = mb.getJointVel(j.link);
    h.effort_ = actuatorEffort(j, h.velocity_, dt);
    if (!h.pid())
      continue;
    double error_after = h.interface() == JointInterface::Velocity ? h.active_target_ - h.velocity_
                                                                     : h.positionError(h.active_target_, h.position_);
    h.pid()->endImplicitStep(error_after, h.effort_, dt);
  }
}

void JointLayer::resetPids()
{
  for (JointHandle& h : handles_)
    if (h.pid())
      h.pid()->reset();
}

// The joint's own damping, folded into a soft drive, is not the actuator's.
double actuatorEffort(const MovableJoint& j, double velocity, double dt)
{
  double effort = j.explicit_effort + j.drive->appliedImpulse() / dt;
  return j.drive->soft() ? effort + j.damping * velocity : effort;
}

}  // namespace bullet_plant
