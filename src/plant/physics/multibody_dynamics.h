// One multibody's dynamics in joint space, in MuJoCo's manner: a state struct built once per step
// (what mjData is to one model) and one named function per algorithm acting on it.
//
// Bullet answers "how does the multibody respond to this generalized impulse" (M^-1 f) with one
// articulated-body pass per question; a constraint row asks once to set up and the car's sixteen
// rows asked sixteen times per step, after one more pass for the forward dynamics. Building the
// joint-space inertia M by composite rigid bodies and factoring it once per step answers all of a
// step's rows with two triangular solves over all of them at once (giving their Delassus block
// too), and the forward dynamics with one recursive Newton-Euler pass and one solve.
//
// Generalized velocities are Bullet's: base angular and linear velocity in the world frame, then
// the joint rates (n = dofs + 6). With a fixed base the first six do not move: every function
// works on entries first..n-1 and leaves the others zero.
#pragma once

#include <vector>

#include <LinearMath/btScalar.h>
#include <LinearMath/btVector3.h>

#include "physics/spatial.h"

class btMultiBody;

namespace bullet_plant
{
struct MultibodyState
{
  // Where a body is: the world-to-body rotation (row-major) and its centre of mass; for a link,
  // also Bullet's parent-to-link rotation and the vector from the parent's centre of mass to the
  // link's, in the link's frame; its parent body and its joint's generalized velocities.
  struct BodyKinematics
  {
    double rotation[9];
    double com[3];
    double from_parent[9];
    double offset[3];
    int parent, first_dof, dof_count;
  };
  // A joint's unit motion in world axes: angular, and linear at its link's centre of mass.
  struct DofMotion
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

  int n = 0;      // generalized velocities
  int first = 0;  // 6 with a fixed base, else 0
  std::vector<BodyKinematics> bodies;  // per body, 0 is the base (linkKinematics)
  std::vector<DofMotion> dofs;         // per generalized velocity, the joints' entries (linkKinematics)
  std::vector<Composite> composites;   // per body (compositeRigidBodyInertia)
  std::vector<double> inertia;         // M, n x n row-major, lower triangle (compositeRigidBodyInertia)
  // A free body (no links, a floating base, M = diag(I, m) about its centre of mass): M^-1 in closed
  // form, and no factor (factorInertia).
  bool free = false;
  double inverse_inertia[9];  // I^-1, world axes, row-major
  double inverse_mass = 0;
  std::vector<double> lower;           // its Cholesky factor L, M = L L^T (factorInertia)
  std::vector<double> inverse_diagonal;
  std::vector<btScalar> lower_scalar, inverse_diagonal_scalar;  // the factor in float, for solveInertiaColumns
  std::vector<double> bias;            // C (biasForces)
  std::vector<SpatialVector> velocity, acceleration, force;  // per body, scratch of biasForces
  std::vector<double> generalized;     // scratch of forwardDynamics
};

// The bodies' rotations and centres of mass and the joints' unit motions, from the multibody's
// cached link transforms (valid from Bullet's forward kinematics of this step on).
void linkKinematics(const btMultiBody& body, MultibodyState& state);

// The composite rigid bodies, and from them M (after linkKinematics).
void compositeRigidBodyInertia(const btMultiBody& body, MultibodyState& state);

// M = L L^T, or for a free body I^-1 and 1 / m. False if M is not positive definite (then Bullet's
// own passes must answer).
bool factorInertia(MultibodyState& state);

// linkKinematics, compositeRigidBodyInertia and factorInertia: the state of one step.
bool buildMultibodyState(const btMultiBody& body, MultibodyState& state);

// state.bias = C, the generalized force the joint torques must overcome for zero accelerations:
// velocity products (centripetal, Coriolis, gyroscopic as Bullet's getUseGyroTerm says), Bullet's
// damping, minus the applied forces and torques; as Bullet's
// computeAccelerationsArticulatedBodyAlgorithmMultiDof has them (recursive Newton-Euler).
void biasForces(const btMultiBody& body, MultibodyState& state);

// x <- M^-1 x (after factorInertia).
void solveInertia(const MultibodyState& state, double* x);

// Bullet's forward dynamics without its articulated-body pass: qdd = M^-1 (tau - C) for the
// multibody's joint torques, laid out as Bullet's result.
void forwardDynamics(const btMultiBody& body, MultibodyState& state, btScalar* qdd);

// For `count` right-hand sides at once (a multiple of kInertiaSides: pad with zeros), stored degree
// of freedom by degree of freedom (x[i * count + r] is entry i of side r): x <- M^-1 x, and
// gram (count x count, row-major) <- x^T M^-1 x of the sides as given (unless gram is null). In float.
constexpr int kInertiaSides = 4;
void solveInertiaColumns(const MultibodyState& state, btScalar* x, int count, btScalar* gram);

// The row of a contact Jacobian: d/dq of the velocity, along `direction`, of the world point
// `point` moving with `link` (-1: the base); what btMultiBody::fillContactJacobianMultiDof gives.
void contactJacobianRow(const MultibodyState& state, int link, const btVector3& point, const btVector3& direction,
                        btScalar* row);

}  // namespace bullet_plant
