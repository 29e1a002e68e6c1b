// The joint-space inertia matrix M of a btMultiBody, in Bullet's generalized velocities (base
// angular and linear velocity in the world frame, then the joint rates), and its Cholesky factor.
//
// Bullet answers "how does the multibody respond to this generalized impulse" (M^-1 f) with one
// articulated-body pass per question; a constraint row asks once to set up and the car's sixteen
// rows asked sixteen times per step. Building M from the links' kinematics (each body's 6 x n
// Jacobian, M = sum J^T diag(I, m) J) and factoring it once per step answers each row with two
// triangular solves.
#pragma once

#include <vector>

#include <LinearMath/btScalar.h>

class btMultiBody;

namespace bullet_plant
{
class JointSpaceInertia
{
public:
  // A spatial motion vector (angular; linear at a body's centre of mass, in its frame).
  struct Motion
  {
    double w[3], v[3];
  };

  // Rebuilds M from the multibody's cached link transforms (valid from Bullet's forward dynamics
  // of this step on). Returns false if M is not positive definite (then use Bullet's own passes).
  bool update(const btMultiBody& body);
  int size() const { return n_; }

  // out = M^-1 f.
  void solve(const btScalar* f, btScalar* out) const;

private:
  // The two halves of solve: half = L^-1 f, then out = L^-T half (M = L L^T).
  void halfSolve(const btScalar* f, double* half) const;
  void finishSolve(const double* half, btScalar* out) const;

  int n_ = 0;
  bool fixed_base_ = false;
  // The bodies' Jacobians by non-zero column: body b's columns are motions_[first_column_[b] ..
  // first_column_[b + 1]), for the generalized velocities columns_[...].
  std::vector<Motion> motions_;
  std::vector<int> columns_;
  std::vector<int> first_column_;
  std::vector<double> lower_;      // Cholesky factor L of M, n x n row-major
  std::vector<double> upper_;      // L^T, row-major
  std::vector<double> inverse_diagonal_;
  std::vector<double> inertia_;     // M, lower triangle
  mutable std::vector<double> scratch_, half_;
};

}  // namespace bullet_plant
