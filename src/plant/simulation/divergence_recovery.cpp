#include "simulation/divergence_recovery.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "simulation/internals.h"
#include "simulation/robot_builder.h"

namespace bullet_plant
{
void LastGoodState::save(const RobotMultibody& robot)
{
  const btMultiBody* mb = robot.bullet.get();
  q.resize(robot.joints.size());
  qd.resize(robot.joints.size());
  for (size_t i = 0; i < robot.joints.size(); ++i)
  {
    q[i] = mb->getJointPos(robot.joints[i].link);
    qd[i] = mb->getJointVel(robot.joints[i].link);
  }
  ball_q.resize(4 * robot.balls.size());
  for (size_t i = 0; i < robot.balls.size(); ++i)
    std::copy(mb->getJointPosMultiDof(robot.balls[i].link), mb->getJointPosMultiDof(robot.balls[i].link) + 4,
              &ball_q[4 * i]);
  base = mb->getBaseWorldTransform();
  base_velocity = mb->getBaseVel();
  base_omega = mb->getBaseOmega();
}

void LastGoodState::restore(RobotMultibody& robot) const
{
  btMultiBody* mb = robot.bullet.get();
  mb->setBaseWorldTransform(base);
  mb->setBaseVel(btVector3(0, 0, 0));
  mb->setBaseOmega(btVector3(0, 0, 0));
  for (size_t i = 0; i < robot.joints.size(); ++i)
  {
    mb->setJointPos(robot.joints[i].link, q[i]);
    mb->setJointVel(robot.joints[i].link, 0);
  }
  const btScalar at_rest[3] = {0, 0, 0};
  for (size_t i = 0; i < robot.balls.size(); ++i)
  {
    mb->setJointPosMultiDof(robot.balls[i].link, &ball_q[4 * i]);
    mb->setJointVelMultiDof(robot.balls[i].link, at_rest);
  }
  robot.updateKinematics();
}

namespace
{
bool stateFinite(const RobotMultibody& robot)
{
  const btMultiBody* mb = robot.bullet.get();
  auto finite3 = [](const btVector3& v) { return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z()); };
  if (!finite3(mb->getBasePos()) || !finite3(mb->getBaseVel()) || !finite3(mb->getBaseOmega()))
    return false;
  btQuaternion q = mb->getWorldToBaseRot();
  if (!std::isfinite(q.x()) || !std::isfinite(q.y()) || !std::isfinite(q.z()) || !std::isfinite(q.w()))
    return false;
  for (const MovableJoint& j : robot.joints)
    if (!std::isfinite(mb->getJointPos(j.link)) || !std::isfinite(mb->getJointVel(j.link)))
      return false;
  for (const BallJoint& b : robot.balls)
  {
    const btScalar* q = mb->getJointPosMultiDof(b.link);
    const btScalar* qd = mb->getJointVelMultiDof(b.link);
    if (!std::isfinite(q[0] + q[1] + q[2] + q[3]) || !std::isfinite(qd[0] + qd[1] + qd[2]))
      return false;
  }
  return true;
}
}  // namespace

// The error is said at the first recovery of each simulated second with the count so far (a robot
// that diverges every step would otherwise log a line per step).
void recoverIfDiverged(Robot::Internals& r)
{
  DivergenceRecovery& recovery = r.recovery;
  if (stateFinite(r.multibody))
  {
    recovery.last_good.save(r.multibody);
    return;
  }
  ++recovery.recoveries;
  recovery.last_good.restore(r.multibody);
  r.joint_layer.resetPids();
  r.forgetSolverHistory();  // the diverged step's impulses would seed the next one (and read as NaN efforts)
  const int64_t now = r.world->time_ns;
  if (recovery.window_start_ns < 0 || now - recovery.window_start_ns >= 1000000000 || now < recovery.window_start_ns)
  {
    recovery.window_start_ns = now;
    recovery.recoveries_in_window = 0;
    r.world->log.error("robot '" + r.name + "': the physics produced a non-finite state; restored the last good state "
                       "with zero velocity (" + std::to_string(recovery.recoveries) + " recoveries so far; further "
                       "ones in this simulated second are counted, not logged)");
  }
  if (++recovery.recoveries_in_window < Robot::kRecoveriesBeforeDisabling)
    return;
  r.disabled = true;
  detachFromPhysics(r);
  r.world->log.error("robot '" + r.name + "' is disabled: its physics diverged on " +
                     std::to_string(recovery.recoveries_in_window) + " steps within one simulated second (" +
                     std::to_string(recovery.recoveries) + " recoveries in all). Check its URDF's masses, inertias "
                     "and limits and its gains; remove it (delete_model) and spawn it again once fixed");
}

}  // namespace bullet_plant
