// A joint made while the world runs (Gazebo's PhysicsEngine::CreateJoint, Joint::Load, Attach): one
// Bullet constraint that holds a body of one multibody (A, the joint's child) to a body of another,
// or of the same, or to the world (B, the parent), as the joint's type holds them, from where they
// are when it is made. Bullet's multibodies have fixed, ball and slider constraints but no hinge,
// and none of them has limits; the four types are written here once, each row on the slider's
// conventions (btMultiBodySliderConstraint), a limit as a one-sided row.
#pragma once

#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyConstraint.h>

#include "bullet_plant/run_time_joint.h"

namespace bullet_plant
{
using RunTimeJointType = RunTimeJoint::Type;

class RunTimeJointConstraint : public btMultiBodyConstraint
{
public:
  // Body `child_link` of `child` (-1: its base) held to body `parent_link` of `parent`, or to the
  // world where `parent` is null, at `anchor` with `axis` (unit; prismatic and revolute), world
  // coordinates now. Its position is 0 here.
  RunTimeJointConstraint(RunTimeJointType type, btMultiBody* child, int child_link, btMultiBody* parent,
                         int parent_link, const btVector3& anchor, const btVector3& axis);

  RunTimeJointType type() const { return type_; }
  // Prismatic and revolute: lower <= position <= upper (m or rad), each a one-sided row while the
  // joint is within a step of it; -inf / inf for none.
  void setLimits(btScalar lower, btScalar upper);
  // The child's slide along (m) or turn about (rad, unwrapped) the axis relative to the parent since
  // the joint was made, and its rate; 0 for the other types.
  btScalar position() const;
  btScalar velocity() const;
  // The anchor on the child and the axis as the parent carries it, world coordinates.
  btVector3 anchorInWorld() const;
  btVector3 axisInWorld() const;
  // An effort along (N) or about (N m) the axis for the coming step: on the child, and its
  // reaction on the parent.
  void applyEffort(btScalar effort);

  void finalizeMultiDof() override {}
  int getIslandIdA() const override;
  int getIslandIdB() const override;
  void createConstraintRows(btMultiBodyConstraintArray& rows, btMultiBodyJacobianData& data,
                            const btContactSolverInfo& info) override;
  void debugDraw(btIDebugDraw*) override {}

private:
  // Rows by slot: the three linear locks, the three angular ones, the lower and the upper limit
  // (the solver leaves each row's impulse in its slot).
  enum Slot { kLinear = 0, kAngular = 3, kLower = 6, kUpper = 7, kSlots = 8 };
  btMatrix3x3 frameInWorld(bool child) const;
  btVector3 pivotInWorld(bool child) const;
  void addRow(btMultiBodyConstraintArray& rows, btMultiBodyJacobianData& data, const btContactSolverInfo& info,
              int slot, const btVector3& angular, const btVector3& linear, btScalar error, btScalar desired_velocity,
              btScalar lowest, btScalar highest);
  // The turn about the axis, in (-pi, pi], unwrapped against the last one read.
  btScalar angle() const;

  RunTimeJointType type_;
  // The joint's frame (its z the axis) and anchor in each body's frame (B's: the world's for none).
  btMatrix3x3 frame_in_a_, frame_in_b_;
  btVector3 pivot_in_a_, pivot_in_b_;
  btScalar lower_ = -BT_INFINITY, upper_ = BT_INFINITY;
  mutable btScalar last_angle_ = 0;
};

}  // namespace bullet_plant
