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
  setVelocityTarget(btScalar(target_velocity), 1);
  setMaxAppliedImpulse(btScalar(max_impulse));
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
