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
// Gravity on a multibody whose links do not all feel it (SDF's <link><gravity>false</gravity>): per
// body (the base first, then Bullet's links), the mass gravity pulls and where, from the body's
// centre of mass in its own frame. The multibody's user pointer points to it; a multibody without
// one feels gravity on all of its mass, as Bullet applies it.
struct PartialGravity
{
  std::vector<btScalar> mass;
  std::vector<btVector3> offset;
  static const PartialGravity* of(const btMultiBody& body)
  {
    return static_cast<const PartialGravity*>(body.getUserPointer());
  }
};

// The force gravity `g` puts on body `body` of the multibody (0 the base) and its torque about the
// body's centre of mass, world frame.
void gravityOn(const btMultiBody& multibody, int body, const btVector3& g, btVector3& force, btVector3& torque);

class DynamicsWorld : public btMultiBodyDynamicsWorld, public MultibodyStates
{
public:
  // The solver gets its multibodies' states from this world.
  DynamicsWorld(btDispatcher* dispatcher, btBroadphaseInterface* broadphase, DenseRowSolver* solver,
                btCollisionConfiguration* configuration);

  void solveExternalForces(btContactSolverInfo& info) override;
  // Bullet's gravity on each awake multibody (m g on every body), or a PartialGravity's where the
  // multibody has one.
  void applyGravity() override;
  // Bullet's box update of every object at every step (m_forceUpdateAllAabbs), less the plain static
  // objects: a world's static shapes never move, so their boxes are made once, as they are added
  // (with the contact breaking threshold around them, as Bullet's update makes them). Recomputing
  // the race circuit's 258 walls cost the car's step 7 us of 16.
  void addCollisionObject(btCollisionObject* object, int group = btBroadphaseProxy::DefaultFilter,
                          int mask = btBroadphaseProxy::AllFilter) override;
  // Speculative contacts for bodies that arrive faster than the contact breaking threshold per
  // step (gContactBreakingThreshold, 1 mm: a body dropped from 1 m moves 4.4 mm a step at 1 ms).
  // Bullet's narrow phase reports points up to the manifold's threshold apart and the solver lets
  // such a point close only by its distance in the step (DenseRowSolver, Bullet's own rows alike);
  // with the 1 mm threshold a falling body was found 4 mm deep instead, and the penetration's
  // correction (erp * depth / dt) threw it back up. So each moving link's box is grown by twice its
  // reach (how far any of its points can move in a step), which makes the pair a step before the
  // bodies can touch, and a manifold without points looks as far as its two bodies' reach. A
  // manifold with points keeps the threshold Bullet's dispatcher gives the pair, relative to the
  // smaller shape's size (0.05 mm for a wheel): a rolling wheel's points go stale as it turns. With
  // 1 mm a wheel on a mesh kept several (10 points under the car's four wheels, each with its
  // friction rows) and the car kept the yaw it landed with on test_track_world's Collada floor
  // (4.1 deg for 14 s: into the side wall at 6.8 m, 9.09 m of the 10); with the pair's own threshold
  // it straightens out (4.3 -> 2.5 deg in its first 2 m) and drives the 10 m.
  // What this does not reach: a convex shape against a triangle mesh. Bullet's convex-concave
  // algorithm collects the triangles within the mesh's margin of the shape's box, whatever the
  // manifold's threshold, so on a mesh a falling body is still found inside it.
  // Objects asleep (ISLAND_SLEEPING) are left out too: they do not move until something wakes them.
  // It walks the objects that can move (mayMove), not the world's static ones.
  void updateAabbs() override;
  // Bullet's (btMultiBodyDynamicsWorld's), its rigid bodies taken from the objects that can move: a
  // kinematic rigid body is one of them, a static shape never is (the race circuit's 258 walls cost
  // the car's step 2 % walking past them).
  void saveKinematicState(btScalar timeStep) override;
  void performDiscreteCollisionDetection() override;
  // The dispatcher's near callback (set by the constructor on a btCollisionDispatcher): Bullet's,
  // less the narrow phase of two boxes whose broad-phase boxes lie apart. btDbvtBroadphase pairs
  // objects whose tree leaves overlap, and its leaves are the boxes grown by gDbvtMargin (5 cm): a
  // pile of 0.2 m boxes had 795 box-box pairs a step and about 30 touching, each pair a
  // btBoxBoxDetector query. Boxes whose broad-phase boxes (which hold the shapes) are farther apart
  // than the manifold's breaking threshold, and than 1 mm, give that query no point (it reports
  // boxes that overlap, and their separation along the best of its 15 axes is at least their
  // distance / sqrt(3), far above its 1e-5 tolerances): what is left of its work is the manifold's
  // refresh of the points it has, done here as btBoxBoxCollisionAlgorithm does it. Two free
  // bodies' boxes (multibodies without links) that far apart get no algorithm yet, and so no
  // manifold: the pile's empty manifolds, two for each one with points, went through the islands'
  // sort and the solver's setup every step. (Where a robot with joints is one side the algorithm
  // is made as Bullet makes it: the order of the manifolds, and so of the rows, stays Bullet's.)
  static void nearCallback(btBroadphasePair& pair, btCollisionDispatcher& dispatcher, const btDispatcherInfo& info);
  // The solver forgets what it keeps of the object (its bounce threshold and surfaces).
  void removeCollisionObject(btCollisionObject* object) override;
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

  // How far a collision object's points can move in this step (m), by its index in the world's
  // objects; 0 for objects that do not move.
  btScalar reachOf(const btCollisionObject& object) const;
  void measureReach();
  void setManifoldThresholds();
  // The object's shape's contact breaking threshold, once a step.
  btScalar breakingThreshold(const btCollisionObject& object);

  // The world's objects that can move (all but the static shapes: neverMoves), in the world's
  // order, made again after an object is added or removed (Bullet's removal reorders the world's).
  const std::vector<btCollisionObject*>& mayMove();
  std::vector<btCollisionObject*> may_move_;
  bool may_move_stale_ = true;

  std::vector<btScalar> reach_;
  std::vector<btScalar> breaking_;  // by the object's index in the world: its threshold this step, or -1
  std::vector<btVector3> link_omega_, link_velocity_;
  std::vector<StepState> states_;  // by multibody number
  std::vector<int> built_;         // the numbers of this step's current states, in the order built
  std::vector<btScalar> accelerations_;
};

// Wakes a multibody that sleeps or is about to (and with it, at the next step, every body asleep
// in its island). Contacts with a moving body wake a sleeping one from inside the step; what moves
// it from outside (a wrench, a joint effort, a new state or gravity) must call this.
void wakeUp(btMultiBody& body);

}  // namespace bullet_plant
