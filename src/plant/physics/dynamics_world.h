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
  // Objects asleep (ISLAND_SLEEPING) are left out too: they do not move until something wakes them.
  void updateAabbs() override;
  // Bullet's deactivation, and then what Bullet does for a sleeping rigid body: its velocities are
  // zeroed, so that it wakes from rest rather than from the sub-threshold drift it fell asleep with.
  void updateActivationState(btScalar timeStep) override;

  // Each multibody is numbered by its place in the world (MultibodyStates::numberOf), kept in its
  // user index: the step's and the solver's tables are indexed by it rather than searched.
  void addMultiBody(btMultiBody* body, int group = btBroadphaseProxy::DefaultFilter,
                    int mask = btBroadphaseProxy::AllFilter) override;
  void removeMultiBody(btMultiBody* body) override;

  const MultibodyState* stateOf(btMultiBody& body) override;
  void needArticulatedPass(btMultiBody& body) override;
  void needArticulatedPasses() override;
  int multibodyCount() const override { return m_multiBodies.size(); }

private:
  // A multibody's state in this step.
  struct StepState
  {
    std::unique_ptr<MultibodyState> state;  // kept from step to step for its storage
    bool current = false;                   // built this step
    bool valid = false;                     // false: M is not positive definite, Bullet's passes answer
    bool articulated_pass_pending = false;  // its velocities came from integrateVelocities
  };
  StepState& stepState(btMultiBody& body);  // built when first asked for in the step
  void runArticulatedPass(btMultiBody& body, StepState& step);
  // qd += dt * M^-1 (tau - C). Returns false where Bullet's pass must run instead (see the cases
  // in the function).
  bool integrateVelocities(btMultiBody& body, btScalar dt);

  std::vector<StepState> states_;  // by multibody number
  std::vector<int> built_;         // the numbers of this step's current states, in the order built
  std::vector<btScalar> accelerations_;
};

// Wakes a multibody that sleeps or is about to (and with it, at the next step, every body asleep
// in its island). Contacts with a moving body wake a sleeping one from inside the step; what moves
// it from outside (a wrench, a joint effort, a new state or gravity) must call this.
void wakeUp(btMultiBody& body);

}  // namespace bullet_plant
