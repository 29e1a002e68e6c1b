#include "joint_drive.h"

#include "joint_space_inertia.h"

#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>

namespace bullet_plant
{
JointDrive::JointDrive(btMultiBody* body, int link)
  : btMultiBodyConstraint(body, nullptr, link, -1, 1, true, MULTIBODY_CONSTRAINT_1DOF_JOINT_MOTOR)
{
}

void JointDrive::finalizeMultiDof()
{
  allocateJacobiansMultiDof();
  jacobianA(0)[6 + m_bodyA->getLink(m_linkA).m_dofOffset] = 1;  // the row is the joint's velocity
  m_numDofsFinalized = m_jacSizeBoth;
}

int JointDrive::getIslandIdA() const
{
  if (const btMultiBodyLinkCollider* base = m_bodyA->getBaseCollider())
    return base->getIslandTag();
  for (int i = 0; i < m_bodyA->getNumLinks(); ++i)
    if (const btMultiBodyLinkCollider* collider = m_bodyA->getLink(i).m_collider)
      return collider->getIslandTag();
  return -1;
}

void JointDrive::drive(double target_velocity, double gain, double max_impulse)
{
  set(target_velocity, gain, max_impulse, 0);
}

void JointDrive::bound(double target_velocity, bool lower)
{
  set(target_velocity, std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(), lower ? 1 : -1);
}

void JointDrive::set(double target_velocity, double gain, double max_impulse, int side)
{
  if (!enabled_ || side_ != side)
    forgetImpulse();
  enabled_ = max_impulse > 0 && gain > 0;
  target_velocity_ = target_velocity;
  gain_ = gain;
  side_ = side;
  m_maxAppliedImpulse = btScalar(max_impulse);
}

void JointDrive::disable()
{
  enabled_ = false;
  forgetImpulse();
}

void JointDrive::forgetImpulse()
{
  if (m_data.size() > 0)
    internalSetAppliedImpulse(0, 0);
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
  createRows(rows, data, info, nullptr);
}

void JointDrive::createRows(btMultiBodyConstraintArray& rows, btMultiBodyJacobianData& data,
                            const btContactSolverInfo& info, const JointSpaceInertia* inertia)
{
  if (!enabled_)
    return;
  if (m_numDofsFinalized != m_jacSizeBoth)
    finalizeMultiDof();
  btMultiBodySolverConstraint& row = rows.expandNonInitializing();
  // The other side is the fixed world: no velocity, no response.
  row.m_solverBodyIdA = data.m_fixedBodyId;
  row.m_solverBodyIdB = data.m_fixedBodyId;
  row.m_contactNormal1.setZero();
  row.m_contactNormal2.setZero();
  row.m_relpos1CrossNormal.setZero();
  row.m_relpos2CrossNormal.setZero();
  row.m_angularComponentA.setZero();
  row.m_angularComponentB.setZero();
  btScalar lower = -m_maxAppliedImpulse, upper = m_maxAppliedImpulse;
  if (side_ > 0)
  {
    lower = 0;
    upper = SIMD_INFINITY;
  }
  else if (side_ < 0)
  {
    lower = -SIMD_INFINITY;
    upper = 0;
  }
  if (inertia)
    fillRow(row, data, *inertia, lower, upper);
  else
  {
    const btVector3 unused(0, 0, 0);
    fillMultiBodyConstraint(row, data, jacobianA(0), nullptr, unused, unused, unused, unused, 0, info, lower, upper,
                            false, 1, false, btScalar(target_velocity_));
  }
  row.m_orgConstraint = this;
  row.m_orgDofIndex = 0;
  if (std::isinf(gain_) || row.m_jacDiagABInv <= 0)
    return;
  // Soften the rigid row: with cfm = 1/gain the converged impulse is gain * (target - qd_end).
  // Bullet scales a row's cfm and rhs by its inverse effective mass, so rescale both.
  const btScalar cfm = btScalar(1.0 / gain_);
  const btScalar effective_inverse_mass = btScalar(1) / row.m_jacDiagABInv;
  const btScalar soft = btScalar(1) / (effective_inverse_mass + cfm);
  row.m_rhs *= soft / row.m_jacDiagABInv;
  row.m_cfm = cfm * soft;
  row.m_jacDiagABInv = soft;
}

// What fillMultiBodyConstraint makes of this row (one multibody, the joint's velocity, no position
// error), with the response from the factored joint-space inertia instead of an articulated pass.
void JointDrive::fillRow(btMultiBodySolverConstraint& row, btMultiBodyJacobianData& data,
                         const JointSpaceInertia& inertia, btScalar lower, btScalar upper)
{
  btMultiBody* body = m_bodyA;
  const int n = body->getNumDofs() + 6;
  row.m_multiBodyA = body;
  row.m_multiBodyB = nullptr;
  row.m_linkA = m_linkA;
  row.m_linkB = -1;
  row.m_deltaVelAindex = body->getCompanionId();
  if (row.m_deltaVelAindex < 0)
  {
    row.m_deltaVelAindex = data.m_deltaVelocities.size();
    body->setCompanionId(row.m_deltaVelAindex);
    data.m_deltaVelocities.resize(data.m_deltaVelocities.size() + n);
  }
  row.m_jacAindex = data.m_jacobians.size();
  data.m_jacobians.resize(data.m_jacobians.size() + n);
  data.m_deltaVelocitiesUnitImpulse.resize(data.m_deltaVelocitiesUnitImpulse.size() + n);
  btScalar* jacobian = &data.m_jacobians[row.m_jacAindex];
  btScalar* response = &data.m_deltaVelocitiesUnitImpulse[row.m_jacAindex];
  const btScalar* source = jacobianA(0);
  for (int i = 0; i < n; ++i)
    jacobian[i] = source[i];
  inertia.solve(jacobian, response);

  const int dof = 6 + body->getLink(m_linkA).m_dofOffset;
  const btScalar denominator = response[dof];  // J is the unit vector of the joint's velocity
  row.m_jacDiagABInv = denominator > SIMD_EPSILON ? btScalar(1) / denominator : btScalar(0);
  const btScalar velocity = body->getVelocityVector()[dof];
  row.m_friction = 0;
  row.m_appliedImpulse = 0;
  row.m_appliedPushImpulse = 0;
  row.m_rhs = (btScalar(target_velocity_) - velocity) * row.m_jacDiagABInv;
  row.m_rhsPenetration = 0;
  row.m_cfm = 0;
  row.m_lowerLimit = lower;
  row.m_upperLimit = upper;
}

}  // namespace bullet_plant
