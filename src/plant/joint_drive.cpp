#include "joint_drive.h"

#include <cmath>

namespace bullet_plant
{
JointDrive::JointDrive(btMultiBody* body, int link) : btMultiBodyJointMotor(body, link, 0, 0, 0)
{
  setPositionTarget(0, 0);  // no position term: only the velocity target below
}

void JointDrive::drive(double target_velocity, double gain, double max_impulse)
{
  enabled_ = max_impulse > 0 && gain > 0;
  gain_ = gain;
  side_ = 0;
  setVelocityTarget(btScalar(target_velocity), 1);
  setMaxAppliedImpulse(btScalar(max_impulse));
}

void JointDrive::bound(double target_velocity, bool lower)
{
  drive(target_velocity, std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity());
  side_ = lower ? 1 : -1;
}

double JointDrive::appliedImpulse() const
{
  if (!enabled_ || m_data.size() == 0)
    return 0.0;
  return const_cast<JointDrive*>(this)->getAppliedImpulse(0);
}

void JointDrive::createConstraintRows(btMultiBodyConstraintArray& rows, btMultiBodyJacobianData& data,
                                      const btContactSolverInfo& info)
{
  if (!enabled_)
    return;
  const int first = rows.size();
  btMultiBodyJointMotor::createConstraintRows(rows, data, info);
  for (int i = first; side_ != 0 && i < rows.size(); ++i)
  {
    rows[i].m_lowerLimit = side_ > 0 ? 0 : -SIMD_INFINITY;
    rows[i].m_upperLimit = side_ > 0 ? SIMD_INFINITY : 0;
  }
  if (std::isinf(gain_))
    return;
  // Soften the rigid row: with cfm = 1/gain the converged impulse is gain * (target - qd_end).
  // Bullet scales a row's cfm and rhs by its inverse effective mass, so rescale both.
  for (int i = first; i < rows.size(); ++i)
  {
    btMultiBodySolverConstraint& row = rows[i];
    if (row.m_jacDiagABInv <= 0)
      continue;
    const btScalar cfm = btScalar(1.0 / gain_);
    const btScalar effective_inverse_mass = btScalar(1) / row.m_jacDiagABInv;
    const btScalar soft = btScalar(1) / (effective_inverse_mass + cfm);
    row.m_rhs *= soft / row.m_jacDiagABInv;
    row.m_cfm = cfm * soft;
    row.m_jacDiagABInv = soft;
  }
}

}  // namespace bullet_plant
