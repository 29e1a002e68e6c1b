// The joint-space inertia matrix M of a btMultiBody, in Bullet's generalized velocities (base
// angular and linear velocity in the world frame, then the joint rates), and its Cholesky factor.
//
// Bullet answers "how does the multibody respond to this generalized impulse" (M^-1 f) with one
// articulated-body pass per question; a constraint row asks once to set up and the car's sixteen
// rows asked sixteen times per step, after one more pass for the forward dynamics. Building M from
// the links' kinematics by composite rigid bodies and factoring it once per step answers all of a
// step's rows with two triangular solves over all of them at once (giving their Delassus block
// too), and the forward dynamics with one recursive Newton-Euler pass and one solve.
#pragma once

#include <vector>

#include <LinearMath/btScalar.h>
#include <LinearMath/btVector3.h>

class btMultiBody;

namespace bullet_plant
{
class JointSpaceInertia
{
public:
  // Rebuilds M from the multibody's cached link transforms (valid from Bullet's forward dynamics
  // of this step on). Returns false if M is not positive definite (then use Bullet's own passes).
  bool update(const btMultiBody& body);
  int size() const { return n_; }

  // Bullet's forward dynamics without its articulated-body pass: the accelerations
  // qdd = M^-1 (tau - C) for the multibody's joint torques and applied forces and torques, with C
  // the velocity-product (centripetal, Coriolis, gyroscopic) and damping forces as Bullet's
  // computeAccelerationsArticulatedBodyAlgorithmMultiDof has them (recursive Newton-Euler). Laid
  // out as Bullet's result: world-frame base angular and centre-of-mass acceleration, then the
  // joints. Valid after update() for the same configuration.
  void accelerations(const btMultiBody& body, btScalar* qdd);

  // The row of a contact Jacobian: d/dq of the velocity, along `direction`, of the world point
  // `point` moving with `link` (-1: the base); what btMultiBody::fillContactJacobianMultiDof gives.
  void contactJacobian(int link, const btVector3& point, const btVector3& direction, btScalar* row) const;

  // For `count` right-hand sides at once (a multiple of kSides: pad with zeros), stored degree
  // of freedom by degree of freedom (x[i * count + r] is entry i of side r): x <- M^-1 x, and
  // gram (count x count, row-major) <- x^T M^-1 x of the sides as given.
  static constexpr int kSides = 4;
  void solveColumns(btScalar* x, int count, btScalar* gram) const;

private:
  // A spatial motion vector (angular; linear at a body's centre of mass), in the body's frame.
  struct Motion
  {
    double w[3], v[3];
  };
  // Where a body is: the world-to-body rotation (row-major) and its centre of mass; for a link,
  // also Bullet's parent-to-link rotation and the vector from the parent's centre of mass to the
  // link's, in the link's frame; its parent body and its joint's generalized velocities.
  struct Frame
  {
    double rotation[9];
    double com[3];
    double from_parent[9];
    double offset[3];
    int parent, first_dof, dof_count;
  };
  // A joint's unit motion in world axes: angular, and linear at its link's centre of mass.
  struct Dof
  {
    double angular[3], linear[3];
    int body;
  };
  // A body with everything beyond it: mass, first moment and rotational inertia about the body's
  // centre of mass, in world axes.
  struct Composite
  {
    double mass;
    double moment[3];
    double inertia[9];
  };

  void solve(double* x) const;  // x <- M^-1 x

  int n_ = 0;
  int first_ = 0;  // 6 with a fixed base: its six velocities do not move
  std::vector<Frame> frames_;          // per body, 0 is the base
  std::vector<Composite> composites_;  // per body
  std::vector<Dof> dofs_;              // per generalized velocity (the joints' entries)
  std::vector<double> inertia_;  // M, lower triangle, n x n row-major
  std::vector<double> lower_;    // its Cholesky factor L (M = L L^T), n x n row-major
  std::vector<double> inverse_diagonal_;
  std::vector<btScalar> lower_scalar_, inverse_diagonal_scalar_;  // the factor for solveColumns
  std::vector<Motion> velocity_, acceleration_, force_;  // per body, scratch of accelerations()
  std::vector<double> generalized_;
};

}  // namespace bullet_plant
