#include "physics/run_time_joint.h"

#include <cmath>

#include <BulletDynamics/ConstraintSolver/btGeneric6DofSpring2Constraint.h>
#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>

namespace bullet_plant
{
namespace
{
// A frame whose z is `axis` (unit), its x and y any two directions across it.
btMatrix3x3 frameAbout(const btVector3& axis)
{
  btVector3 x, y;
  btPlaneSpace1(axis, x, y);
  return btMatrix3x3(x.x(), y.x(), axis.x(), x.y(), y.y(), axis.y(), x.z(), y.z(), axis.z());
}

// The island of a multibody's first collider; -1 for the world or a body without one.
int islandOf(const btMultiBody* body)
{
  if (!body)
    return -1;
  if (const btMultiBodyLinkCollider* base = body->getBaseCollider())
    return base->getIslandTag();
  for (int i = 0; i < body->getNumLinks(); ++i)
    if (const btMultiBodyLinkCollider* link = body->getLink(i).m_collider)
      return link->getIslandTag();
  return -1;
}

// The angular and linear velocity (world) of body `link` (-1: the base) of `body` at `point`
// (world); zero for the world. Bullet keeps the links' at their centres of mass in their own frames.
void motionAt(const btMultiBody* body, int link, const btVector3& point, btVector3& omega, btVector3& velocity)
{
  omega.setZero();
  velocity.setZero();
  if (!body)
    return;
  btVector3 v_com, com;
  if (link < 0)
  {
    omega = body->getBaseOmega();
    v_com = body->getBaseVel();
    com = body->getBasePos();
  }
  else
  {
    btAlignedObjectArray<btVector3> omegas, velocities;
    omegas.resize(body->getNumLinks() + 1);
    velocities.resize(body->getNumLinks() + 1);
    body->compTreeLinkVelocities(&omegas[0], &velocities[0]);
    omega = body->localDirToWorld(link, omegas[link + 1]);
    v_com = body->localDirToWorld(link, velocities[link + 1]);
    com = body->localPosToWorld(link, btVector3(0, 0, 0));
  }
  velocity = v_com + omega.cross(point - com);
}
}  // namespace

RunTimeJointConstraint::RunTimeJointConstraint(RunTimeJointType type, btMultiBody* child, int child_link,
                                               btMultiBody* parent, int parent_link, const btVector3& anchor,
                                               const btVector3& axis)
  : btMultiBodyConstraint(child, parent, child_link, parent ? parent_link : -1, kSlots, false, MAX_MULTIBODY_CONSTRAINT_TYPE),
    type_(type)
{
  const btMatrix3x3 frame = frameAbout(axis.fuzzyZero() ? btVector3(0, 0, 1) : axis.normalized());
  // The body frames' world rotations now, and the anchor in each body's frame.
  const btMatrix3x3 a_in_world = child->localFrameToWorld(child_link, btMatrix3x3::getIdentity());
  frame_in_a_ = a_in_world.transpose() * frame;
  pivot_in_a_ = child->worldPosToLocal(child_link, anchor);
  if (parent)
  {
    const btMatrix3x3 b_in_world = parent->localFrameToWorld(parent_link, btMatrix3x3::getIdentity());
    frame_in_b_ = b_in_world.transpose() * frame;
    pivot_in_b_ = parent->worldPosToLocal(parent_link, anchor);
  }
  else
  {
    frame_in_b_ = frame;
    pivot_in_b_ = anchor;
  }
  m_data.resize(kSlots);  // the impulses the solver leaves each slot
}

void RunTimeJointConstraint::setLimits(btScalar lower, btScalar upper)
{
  lower_ = lower;
  upper_ = upper;
}

btMatrix3x3 RunTimeJointConstraint::frameInWorld(bool child) const
{
  if (child)
    return m_bodyA->localFrameToWorld(m_linkA, frame_in_a_);
  return m_bodyB ? m_bodyB->localFrameToWorld(m_linkB, frame_in_b_) : frame_in_b_;
}

btVector3 RunTimeJointConstraint::pivotInWorld(bool child) const
{
  if (child)
    return m_bodyA->localPosToWorld(m_linkA, pivot_in_a_);
  return m_bodyB ? m_bodyB->localPosToWorld(m_linkB, pivot_in_b_) : pivot_in_b_;
}

btVector3 RunTimeJointConstraint::anchorInWorld() const { return pivotInWorld(true); }

btVector3 RunTimeJointConstraint::axisInWorld() const { return frameInWorld(false).getColumn(2); }

btScalar RunTimeJointConstraint::angle() const
{
  // The child's x in the parent's joint frame, turned about z.
  const btVector3 x = frameInWorld(false).transpose() * frameInWorld(true).getColumn(0);
  const btScalar turn = std::atan2(x.y(), x.x());
  last_angle_ += std::remainder(turn - last_angle_, btScalar(2 * SIMD_PI));
  return last_angle_;
}

btScalar RunTimeJointConstraint::position() const
{
  if (type_ == RunTimeJointType::Prismatic)
    return (pivotInWorld(true) - pivotInWorld(false)).dot(axisInWorld());
  if (type_ == RunTimeJointType::Revolute)
    return angle();
  return 0;
}

btScalar RunTimeJointConstraint::velocity() const
{
  if (type_ != RunTimeJointType::Prismatic && type_ != RunTimeJointType::Revolute)
    return 0;
  const btVector3 anchor = pivotInWorld(true), axis = axisInWorld();
  btVector3 omega_a, v_a, omega_b, v_b;
  motionAt(m_bodyA, m_linkA, anchor, omega_a, v_a);
  motionAt(m_bodyB, m_linkB, anchor, omega_b, v_b);
  return type_ == RunTimeJointType::Prismatic ? (v_a - v_b).dot(axis) : (omega_a - omega_b).dot(axis);
}

void RunTimeJointConstraint::applyEffort(btScalar effort)
{
  if (effort == 0 || (type_ != RunTimeJointType::Prismatic && type_ != RunTimeJointType::Revolute))
    return;
  const btVector3 axis = axisInWorld() * effort;
  // A force at the anchor is the force and its moment about the body's centre of mass.
  auto apply = [&](btMultiBody* body, int link, const btVector3& point, btScalar sign) {
    if (!body)
      return;
    if (type_ == RunTimeJointType::Revolute)
    {
      link < 0 ? body->addBaseTorque(sign * axis) : body->addLinkTorque(link, sign * axis);
      return;
    }
    const btVector3 com = link < 0 ? body->getBasePos() : body->localPosToWorld(link, btVector3(0, 0, 0));
    const btVector3 torque = (point - com).cross(sign * axis);
    if (link < 0)
    {
      body->addBaseForce(sign * axis);
      body->addBaseTorque(torque);
    }
    else
    {
      body->addLinkForce(link, sign * axis);
      body->addLinkTorque(link, torque);
    }
  };
  apply(m_bodyA, m_linkA, pivotInWorld(true), 1);
  apply(m_bodyB, m_linkB, pivotInWorld(false), -1);
}

int RunTimeJointConstraint::getIslandIdA() const { return islandOf(m_bodyA); }

int RunTimeJointConstraint::getIslandIdB() const { return islandOf(m_bodyB); }

void RunTimeJointConstraint::addRow(btMultiBodyConstraintArray& rows, btMultiBodyJacobianData& data,
                                    const btContactSolverInfo& info, int slot, const btVector3& angular,
                                    const btVector3& linear, btScalar error, btScalar desired_velocity,
                                    btScalar lowest, btScalar highest)
{
  btMultiBodySolverConstraint& row = rows.expandNonInitializing();
  row.m_orgConstraint = this;
  row.m_orgDofIndex = slot;
  row.m_relpos1CrossNormal.setValue(0, 0, 0);
  row.m_contactNormal1.setValue(0, 0, 0);
  row.m_relpos2CrossNormal.setValue(0, 0, 0);
  row.m_contactNormal2.setValue(0, 0, 0);
  row.m_angularComponentA.setValue(0, 0, 0);
  row.m_angularComponentB.setValue(0, 0, 0);
  row.m_solverBodyIdA = data.m_fixedBodyId;
  row.m_solverBodyIdB = data.m_fixedBodyId;
  const bool is_angular = !angular.isZero();
  fillMultiBodyConstraint(row, data, nullptr, nullptr, angular, linear, pivotInWorld(true), pivotInWorld(false), error,
                          info, lowest, highest, is_angular, 1, false, desired_velocity);
}

void RunTimeJointConstraint::createConstraintRows(btMultiBodyConstraintArray& rows, btMultiBodyJacobianData& data,
                                                  const btContactSolverInfo& info)
{
  // Every row starts cold, as Bullet's own multibody constraints do: the solver would otherwise
  // start a row from its impulse of the step before (DenseRowSolver's warm start), and a limit's
  // row that had just stopped the joint (an impact's impulse) carried that into the steps at rest,
  // where it came back out as the same speed the other way (a pendulum stopped at 3 rad/s
  // rebounded at 3 rad/s 16 steps later).
  for (int i = 0; i < kSlots; ++i)
    m_data[i] = 0;
  const btMatrix3x3 frame_a = frameInWorld(true), frame_b = frameInWorld(false);
  const btVector3 pivot_a = pivotInWorld(true), pivot_b = pivotInWorld(false);
  const btScalar most = m_maxAppliedImpulse;
  const btVector3 none(0, 0, 0);
  // Linear locks: all three, less the axis for a slide. The error is A's offset from B along each
  // direction, as the slider's.
  for (int i = 0; i < 3; ++i)
    if (!(type_ == RunTimeJointType::Prismatic && i == 2))
    {
      const btVector3 n = frame_a.getColumn(i);
      addRow(rows, data, info, kLinear + i, none, n, (pivot_a - pivot_b).dot(n), 0, -most, most);
    }
  // Angular locks: all three for fixed and prismatic joints, the two across the axis for a hinge,
  // none for a ball; the error, as Bullet's fixed and slider constraints take it, from the XYZ
  // Euler angles of B's joint frame in A's.
  if (type_ != RunTimeJointType::Ball)
  {
    btVector3 angles;
    btGeneric6DofSpring2Constraint::matrixToEulerXYZ(frame_a.transpose() * frame_b, angles);
    for (int i = 0; i < 3; ++i)
      if (!(type_ == RunTimeJointType::Revolute && i == 2))
        addRow(rows, data, info, kAngular + i, frame_a.getColumn(i), none, angles[i], 0, -most, most);
  }
  if (type_ != RunTimeJointType::Prismatic && type_ != RunTimeJointType::Revolute)
    return;
  // A limit as a contact: a row that only pushes the joint back, made while the joint is past the
  // limit (its error corrected as the locks') or could reach it within the step (then it may close
  // the gap but not cross it).
  const btScalar q = position(), rate = velocity(), dt = info.m_timeStep;
  const btVector3 axis = frame_b.getColumn(2);
  const bool turn = type_ == RunTimeJointType::Revolute;
  auto limit = [&](int slot, btScalar gap, btScalar sign) {
    if (gap + std::min(btScalar(0), sign * rate) * dt * 2 > 0)
      return;  // out of reach this step
    const btVector3 n = sign * axis;
    if (gap >= 0)
      addRow(rows, data, info, slot, turn ? n : none, turn ? none : n, 0, -gap / dt, 0, most);
    else
      addRow(rows, data, info, slot, turn ? n : none, turn ? none : n, gap, 0, 0, most);
  };
  if (std::isfinite(lower_))
    limit(kLower, q - lower_, 1);
  if (std::isfinite(upper_))
    limit(kUpper, upper_ - q, -1);
}

}  // namespace bullet_plant
