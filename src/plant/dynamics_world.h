// Bullet's multibody world, with each multibody's forward dynamics taken from DenseRowSolver's
// joint-space inertia (DenseRowSolver::integrateVelocities) instead of Bullet's articulated-body
// pass. The step needs M and its factor for the constraint rows anyway; with them the
// unconstrained accelerations are one recursive Newton-Euler pass for the bias forces and two
// triangular solves, where the articulated-body pass cost the car a sixth of its step.
#pragma once

#include <BulletDynamics/Featherstone/btMultiBodyDynamicsWorld.h>

namespace bullet_plant
{
class DenseRowSolver;

class DynamicsWorld : public btMultiBodyDynamicsWorld
{
public:
  DynamicsWorld(btDispatcher* dispatcher, btBroadphaseInterface* broadphase, DenseRowSolver* solver,
                btCollisionConfiguration* configuration);

  void solveExternalForces(btContactSolverInfo& info) override;

private:
  DenseRowSolver* solver_;
};

}  // namespace bullet_plant
