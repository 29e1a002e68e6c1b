// Bullet's multibody world whose step owns each multibody's joint-space state (MultibodyState):
// built once per step, it gives the forward dynamics qd += dt M^-1 (tau - C) in place of Bullet's
// articulated-body pass, and the constraint solver (DenseRowSolver) builds its rows from it. The
// step needs M and its factor for the rows anyway; with them the unconstrained accelerations are
// one recursive Newton-Euler pass and two triangular solves, where the articulated-body pass cost
// the car a sixth of its step. The world also decides when that pass must run all the same: Bullet's
// own constraint rows read its caches.
#pragma once

#include <memory>
#include <vector>

#include <BulletDynamics/Featherstone/btMultiBodyDynamicsWorld.h>

#include "physics/dense_row_solver.h"
#include "physics/multibody_dynamics.h"

namespace bullet_plant
{
class DynamicsWorld : public btMultiBodyDynamicsWorld, public MultibodyStates
{
public:
  // The solver gets its multibodies' states from this world.
  DynamicsWorld(btDispatcher* dispatcher, btBroadphaseInterface* broadphase, DenseRowSolver* solver,
                btCollisionConfiguration* configuration);

  void solveExternalForces(btContactSolverInfo& info) override;
  // Bullet's box update of every object at every step (m_forceUpdateAllAabbs), less the plain static
  // objects: a world's static shapes never move, so their boxes are made once, as they are added
  // (with the contact breaking threshold around them, as Bullet's update makes them). Recomputing
  // the race circuit's 258 walls cost the car's step 7 us of 16.
  void addCollisionObject(btCollisionObject* object, int group = btBroadphaseProxy::DefaultFilter,
                          int mask = btBroadphaseProxy::AllFilter) override;
  void updateAabbs() override;

  const MultibodyState* stateOf(btMultiBody& body) override;
  void needArticulatedPass(btMultiBody& body) override;
  void needArticulatedPasses() override;

private:
  // A multibody's state in this step.
  struct StepState
  {
    btMultiBody* body = nullptr;
    std::unique_ptr<MultibodyState> state;  // null: M is not positive definite, Bullet's passes answer
    bool articulated_pass_pending = false;  // its velocities came from integrateVelocities
  };
  StepState& stepState(btMultiBody& body);  // built when first asked for in the step
  void runArticulatedPass(StepState& step);
  // qd += dt * M^-1 (tau - C). Returns false where Bullet's pass must run instead (see the cases
  // in the function).
  bool integrateVelocities(btMultiBody& body, btScalar dt);

  std::vector<StepState> states_;  // this step's first states_used_ are current
  size_t states_used_ = 0;
  std::vector<btScalar> accelerations_;
};

}  // namespace bullet_plant
