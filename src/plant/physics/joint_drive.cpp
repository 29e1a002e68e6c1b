#include "physics/joint_drive.h"

#include <algorithm>

#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyDynamicsWorld.h>
#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>

namespace bullet_plant
{
JointDrive::JointDrive(btMultiBodyDynamicsWorld* world, btMultiBody* body, int link)
  : btMultiBodyConstraint(body, nullptr, link, -1, 1, true, MULTIBODY_CONSTRAINT_1DOF_JOINT_MOTOR), world_(world)
{
}

JointDrive::JointDrive(btMultiBodyDynamicsWorld* world, btMultiBody* body, int link, int coupled_link, double ratio)
  : JointDrive(world, body, link)
{
  coupled_link_ = coupled_link;
  coupled_ratio_ = ratio;
}

JointDrive::~JointDrive() { setEnabled(false); }

void JointDrive::setEnabled(bool enabled)
{
  if (enabled == enabled_)
    return;
  enabled_ = enabled;
  if (enabled)
    world_->addMultiBodyConstraint(this);
  else
    world_->removeMultiBodyConstraint(this);
}

void JointDrive::finalizeMultiDof()
{
  allocateJacobiansMultiDof();
  jacobianA(0)[6 + m_bodyA->getLink(m_linkA).m_dofOffset] = 1;  // the row is the joint's velocity
  if (coupled_link_ >= 0)
    jacobianA(0)[6 + m_bodyA->getLink(coupled_link_).m_dofOffset] = btScalar(-coupled_ratio_);
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
  setEnabled(max_impulse > 0 && gain > 0);
  target_velocity_ = target_velocity;
  gain_ = gain;
  side_ = side;
  m_maxAppliedImpulse = btScalar(max_impulse);
}

void JointDrive::disable()
{
  setEnabled(false);
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
  if (!enabled_)
    return;
  btMultiBodySolverConstraint& row = startRow(rows, data);
  const btVector3 unused(0, 0, 0);
  fillMultiBodyConstraint(row, data, jacobianA(0), nullptr, unused, unused, unused, unused, 0, info, row.m_lowerLimit,
                          row.m_upperLimit, false, 1, false, btScalar(target_velocity_));
  if (std::isinf(gain_) || row.m_jacDiagABInv <= 0)
    return;
  // Soften the rigid row: with cfm = 1/gain the converged impulse is gain * (target - qd_end).
  // Bullet scales a row's cfm and rhs by its inverse effective mass, so rescale both.
  const btScalar cfm = btScalar(1.0 / gain_);
  const btScalar soft = btScalar(1) / (btScalar(1) / row.m_jacDiagABInv + cfm);
  row.m_rhs *= soft / row.m_jacDiagABInv;
  row.m_cfm = cfm * soft;
  row.m_jacDiagABInv = soft;
}

btMultiBodySolverConstraint& JointDrive::startRow(btMultiBodyConstraintArray& rows, btMultiBodyJacobianData& data)
{
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
  row.m_lowerLimit = side_ > 0 ? btScalar(0) : side_ < 0 ? -SIMD_INFINITY : -m_maxAppliedImpulse;
  row.m_upperLimit = side_ < 0 ? btScalar(0) : side_ > 0 ? SIMD_INFINITY : m_maxAppliedImpulse;
  row.m_orgConstraint = this;
  row.m_orgDofIndex = 0;
  return row;
}

// What fillMultiBodyConstraint makes of this row (one multibody, the joint's velocity or a coupled
// pair's, no position error) up to the response.
int JointDrive::createRowWithoutResponse(btMultiBodyConstraintArray& rows, btMultiBodyJacobianData& data,
                                         btScalar& velocity_error, btScalar& cfm)
{
  if (!enabled_)
    return -1;
  btMultiBodySolverConstraint& row = startRow(rows, data);
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
  std::copy(jacobianA(0), jacobianA(0) + n, &data.m_jacobians[row.m_jacAindex]);
  row.m_friction = 0;
  row.m_appliedImpulse = 0;
  row.m_appliedPushImpulse = 0;
  row.m_rhsPenetration = 0;

  const btScalar* qd = body->getVelocityVector();
  velocity_error = btScalar(target_velocity_) - qd[6 + body->getLink(m_linkA).m_dofOffset];
  if (coupled_link_ >= 0)
    velocity_error += btScalar(coupled_ratio_) * qd[6 + body->getLink(coupled_link_).m_dofOffset];
  // A soft drive: with cfm = 1/gain the converged impulse is gain * (target - qd_end).
  cfm = std::isinf(gain_) ? btScalar(0) : btScalar(1.0 / gain_);
  return rows.size() - 1;
}

}  // namespace bullet_plant
