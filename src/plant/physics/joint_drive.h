// One constraint row on a joint's velocity, solved together with the contacts:
//   impulse = gain * (target_velocity - qd_end), clamped to [-max_impulse, max_impulse].
// A coupled row (a screw's slide to its turn, a gearbox's gears) is on qd - ratio * qd_other of
// another joint of the same multibody instead.
// gain = infinity gives a rigid velocity motor; a finite gain is a soft (implicit) drive, i.e. a
// spring-damper evaluated at the end of the step, stable for any gain and inertia.
// The row acts on the joint's own multibody only (Bullet's joint motor also carries an all-zero
// Jacobian for the same body as its second body, which doubles the work of every solver pass).
#pragma once

#include <cmath>
#include <limits>

#include <BulletDynamics/Featherstone/btMultiBodyConstraint.h>

class btMultiBodyDynamicsWorld;

namespace bullet_plant
{
class JointDrive : public btMultiBodyConstraint
{
public:
  // The drive is in the world's constraints only while enabled: an idle drive costs the world's
  // per-step sorting and island bookkeeping nothing.
  JointDrive(btMultiBodyDynamicsWorld* world, btMultiBody* body, int link);
  // The row on qd(link) - ratio * qd(coupled_link), both single-dof links of `body`.
  JointDrive(btMultiBodyDynamicsWorld* world, btMultiBody* body, int link, int coupled_link, double ratio);
  ~JointDrive() override;

  void drive(double target_velocity, double gain, double max_impulse);
  // A one-sided rigid row: the joint velocity may not fall below (lower bound) or rise above
  // (upper bound) target_velocity. Used for position limits.
  void bound(double target_velocity, bool lower);
  void disable();
  bool enabled() const { return enabled_; }
  bool soft() const { return enabled_ && !std::isinf(gain_); }
  // Impulse the last solve applied (0 when disabled).
  double appliedImpulse() const;

  void finalizeMultiDof() override;
  int getIslandIdA() const override;
  int getIslandIdB() const override { return getIslandIdA(); }
  void createConstraintRows(btMultiBodyConstraintArray& rows, btMultiBodyJacobianData& data,
                            const btContactSolverInfo& info) override;
  // The row without what depends on its response J M^-1 J^T (m_jacDiagABInv, m_rhs, m_cfm and
  // the response vector), for a solver that computes the responses of all of a multibody's rows
  // at once (DenseRowSolver): returns the row's index in `rows` (-1 when the drive is off), the
  // velocity error the row removes and its constraint force mixing, both before Bullet's scaling
  // by the row's inverse effective mass.
  int createRowWithoutResponse(btMultiBodyConstraintArray& rows, btMultiBodyJacobianData& data,
                               btScalar& velocity_error, btScalar& cfm);
  void debugDraw(class btIDebugDraw*) override {}

private:
  // A new row with this drive's bounds and bookkeeping, acting against the fixed world.
  btMultiBodySolverConstraint& startRow(btMultiBodyConstraintArray& rows, btMultiBodyJacobianData& data);
  void setEnabled(bool enabled);
  void set(double target_velocity, double gain, double max_impulse, int side);
  // The solver starts the row from its last impulse: only from one of the same kind of row.
  void forgetImpulse();

  btMultiBodyDynamicsWorld* world_;
  bool enabled_ = false;
  int side_ = 0;  // 0: two-sided drive; +1: velocity >= target; -1: velocity <= target
  double target_velocity_ = 0.0;
  double gain_ = std::numeric_limits<double>::infinity();
  int coupled_link_ = -1;  // -1: a row on the joint's own velocity alone
  double coupled_ratio_ = 0.0;
};

}  // namespace bullet_plant
