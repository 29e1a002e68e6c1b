#include "physics/movable_joint.h"

#include <algorithm>
#include <limits>

#include <BulletDynamics/Featherstone/btMultiBody.h>

namespace bullet_plant
{
double positionWithinLimits(const MovableJoint& j, double q, Log& log, const std::string& robot, const std::string& what)
{
  if (!j.limits.has_position || (q >= j.limits.lower && q <= j.limits.upper))
    return q;
  // Outside its limits, the limit rows would push the joint back at overlap / 5 dt per step.
  const double within = std::max(j.limits.lower, std::min(q, j.limits.upper));
  log.warn(what + " " + formatNumber(q) + " of joint '" + j.name + "' of '" + robot + "' is outside its URDF limits [" +
           formatNumber(j.limits.lower) + ", " + formatNumber(j.limits.upper) + "]; it starts at " + formatNumber(within));
  return within;
}

void holdCoupling(JointCoupling& c, const std::vector<MovableJoint>& joints, const btMultiBody& body, double dt)
{
  const double mismatch = body.getJointPos(joints[c.follower].link) - c.multiplier * body.getJointPos(joints[c.leader].link);
  const double inf = std::numeric_limits<double>::infinity();
  c.row->drive(-kCouplingRecovery * mismatch / dt, inf, inf);
}

}  // namespace bullet_plant
