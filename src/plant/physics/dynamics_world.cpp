#include "physics/dynamics_world.h"

#include <algorithm>
#include <typeinfo>

#include <BulletCollision/CollisionDispatch/btBoxBoxCollisionAlgorithm.h>
#include <BulletCollision/CollisionDispatch/btCollisionDispatcher.h>
#include <BulletCollision/CollisionShapes/btBoxShape.h>
#include <BulletCollision/CollisionShapes/btCollisionShape.h>
#include <BulletCollision/NarrowPhaseCollision/btPersistentManifold.h>
#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyInplaceSolverIslandCallback.h>
#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>

// solveExternalForces below restates Bullet 3.24's method of the same name.
static_assert(BT_BULLET_VERSION == 324,
              "DynamicsWorld::solveExternalForces restates Bullet 3.24's btMultiBodyDynamicsWorld::"
              "solveExternalForces: compare the new version's method with it (the forward kinematics, "
              "constraint sorting, island callback setup, prepareSolve and the per-multibody forward "
              "dynamics) and update it, then this check. What it leaves out on purpose: the RK4 "
              "integration path (handed to Bullet's method whole) and the gravity and force clearing that "
              "BT_USE_VIRTUAL_CLEARFORCES_AND_GRAVITY moves to applyGravity and clearForces.");

namespace bullet_plant
{
namespace
{
bool sleeping(const btMultiBody& body)
{
  // One that may not sleep is set ACTIVE_TAG by every step's updateActivationState, so its island
  // never sleeps: no need to look at each of its colliders (the car has thirteen).
  if (!body.getCanSleep())
    return false;
  if (body.getBaseCollider() && body.getBaseCollider()->getActivationState() == ISLAND_SLEEPING)
    return true;
  for (int i = 0; i < body.getNumLinks(); ++i)
    if (body.getLink(i).m_collider && body.getLink(i).m_collider->getActivationState() == ISLAND_SLEEPING)
      return true;
  return false;
}

// A plain static object: a world's static shape. Rigid bodies and multibody links may be moved,
// static or not (a fixed-base robot set elsewhere).
bool neverMoves(const btCollisionObject& object)
{
  return object.getInternalType() == btCollisionObject::CO_COLLISION_OBJECT && object.isStaticObject();
}
}  // namespace

void gravityOn(const btMultiBody& multibody, int body, const btVector3& g, btVector3& force, btVector3& torque)
{
  const PartialGravity* partial = PartialGravity::of(multibody);
  if (!partial)
  {
    force = g * (body == 0 ? multibody.getBaseMass() : multibody.getLinkMass(body - 1));
    torque.setZero();
    return;
  }
  force = g * partial->mass[size_t(body)];
  const btQuaternion to_world = body == 0 ? multibody.getWorldToBaseRot().inverse()
                                          : multibody.getLink(body - 1).m_cachedWorldTransform.getRotation();
  torque = quatRotate(to_world, partial->offset[size_t(body)]).cross(force);
}

void DynamicsWorld::applyGravity()
{
  btDiscreteDynamicsWorld::applyGravity();  // the rigid bodies' (the plant makes none)
  for (int i = 0; i < m_multiBodies.size(); ++i)
  {
    btMultiBody* body = m_multiBodies[i];
    if (sleeping(*body))
      continue;
    if (!PartialGravity::of(*body))  // Bullet's own arithmetic
    {
      body->addBaseForce(m_gravity * body->getBaseMass());
      for (int j = 0; j < body->getNumLinks(); ++j)
        body->addLinkForce(j, m_gravity * body->getLinkMass(j));
      continue;
    }
    btVector3 force, torque;
    for (int b = 0; b <= body->getNumLinks(); ++b)
    {
      gravityOn(*body, b, m_gravity, force, torque);
      if (b == 0)
      {
        body->addBaseForce(force);
        body->addBaseTorque(torque);
      }
      else
      {
        body->addLinkForce(b - 1, force);
        body->addLinkTorque(b - 1, torque);
      }
    }
  }
}

namespace
{
// Bullet's island callback (MultiBodyInplaceSolverIslandCallback), an island's joints found in the
// lists sorted by island by where each island's run starts, made once a step. Bullet scans both
// lists for every island, to their end: islands x constraints island lookups a step (each robot is
// an island, each wheel's drive a constraint), 30 000 with 100 diff-drive robots and 5 % of the
// node's time there (perf, make bench-fleet). The constraints handed to the solver, and their
// order, are Bullet's.
struct IslandRunsCallback : MultiBodyInplaceSolverIslandCallback
{
  using MultiBodyInplaceSolverIslandCallback::MultiBodyInplaceSolverIslandCallback;

  // Where each island's run starts in a list sorted by `islandOf`, and how long it is.
  template <class Constraint, class IslandOf>
  static void findRuns(Constraint** sorted, int count, IslandOf islandOf, std::vector<std::pair<int, int>>& runs)
  {
    runs.clear();
    for (int i = 0; i < count;)
    {
      const int island = islandOf(sorted[i]);
      int end = i + 1;
      while (end < count && islandOf(sorted[end]) == island)
        ++end;
      if (island >= 0)
      {
        if (runs.size() <= size_t(island))
          runs.resize(island + 1, {0, 0});
        runs[island] = {i, end - i};
      }
      i = end;
    }
  }
  static std::pair<int, int> runOf(const std::vector<std::pair<int, int>>& runs, int island)
  {
    return size_t(island) < runs.size() ? runs[island] : std::pair<int, int>(0, 0);
  }

  void setup(btContactSolverInfo* info, btTypedConstraint** sorted, int count, btMultiBodyConstraint** sorted_multibody,
             int multibody_count, btIDebugDraw* debug_drawer) override
  {
    MultiBodyInplaceSolverIslandCallback::setup(info, sorted, count, sorted_multibody, multibody_count, debug_drawer);
    findRuns(sorted, count, btGetConstraintIslandId2, constraint_runs_);
    findRuns(sorted_multibody, multibody_count, btGetMultiBodyConstraintIslandId, multibody_runs_);
  }

  void processIsland(btCollisionObject** bodies, int num_bodies, btPersistentManifold** manifolds, int num_manifolds,
                     int island) override
  {
    if (island < 0)
    {
      MultiBodyInplaceSolverIslandCallback::processIsland(bodies, num_bodies, manifolds, num_manifolds, island);
      return;
    }
    const std::pair<int, int> constraints = runOf(constraint_runs_, island);
    const std::pair<int, int> multibody = runOf(multibody_runs_, island);
    for (int i = 0; i < num_bodies; ++i)
    {
      if (bodies[i]->getInternalType() & btCollisionObject::CO_SOFT_BODY)
        m_softBodies.push_back(bodies[i]);
      else
        m_bodies.push_back(bodies[i]);
    }
    for (int i = 0; i < num_manifolds; ++i)
      m_manifolds.push_back(manifolds[i]);
    for (int i = 0; i < constraints.second; ++i)
      m_constraints.push_back(m_sortedConstraints[constraints.first + i]);
    for (int i = 0; i < multibody.second; ++i)
      m_multiBodyConstraints.push_back(m_multiBodySortedConstraints[multibody.first + i]);
    if (m_multiBodyConstraints.size() + m_constraints.size() + m_manifolds.size() > m_solverInfo->m_minimumSolverBatchSize)
      processConstraints(island);
  }

  std::vector<std::pair<int, int>> constraint_runs_, multibody_runs_;  // by island: first, count
};
}  // namespace

DynamicsWorld::DynamicsWorld(btDispatcher* dispatcher, btBroadphaseInterface* broadphase, DenseRowSolver* solver,
                             btCollisionConfiguration* configuration)
  : btMultiBodyDynamicsWorld(dispatcher, broadphase, solver, configuration)
{
  delete m_solverMultiBodyIslandCallback;  // Bullet's world deletes whichever is here
  m_solverMultiBodyIslandCallback = new IslandRunsCallback(solver, dispatcher);
  solver->useStates(this);
  if (auto* collision_dispatcher = dynamic_cast<btCollisionDispatcher*>(dispatcher))
    collision_dispatcher->setNearCallback(&DynamicsWorld::nearCallback);
}

namespace
{
// The base of a multibody without links: a free body.
bool freeBody(const btCollisionObject& object)
{
  const btMultiBodyLinkCollider* collider = btMultiBodyLinkCollider::upcast(&object);
  return collider && collider->m_link < 0 && collider->m_multiBody->getNumLinks() == 0;
}
}  // namespace

void DynamicsWorld::nearCallback(btBroadphasePair& pair, btCollisionDispatcher& dispatcher, const btDispatcherInfo& info)
{
  const btBroadphaseProxy* proxy0 = pair.m_pProxy0;
  const btBroadphaseProxy* proxy1 = pair.m_pProxy1;
  const auto* object0 = static_cast<const btCollisionObject*>(proxy0->m_clientObject);
  const auto* object1 = static_cast<const btCollisionObject*>(proxy1->m_clientObject);
  if (info.m_dispatchFunc != btDispatcherInfo::DISPATCH_DISCRETE ||
      object0->getCollisionShape()->getShapeType() != BOX_SHAPE_PROXYTYPE ||
      object1->getCollisionShape()->getShapeType() != BOX_SHAPE_PROXYTYPE)
  {
    btCollisionDispatcher::defaultNearCallback(pair, dispatcher, info);
    return;
  }
  btScalar gap = 0;
  for (int a = 0; a < 3; ++a)
    gap = std::max(gap, std::max(proxy1->m_aabbMin[a] - proxy0->m_aabbMax[a], proxy0->m_aabbMin[a] - proxy1->m_aabbMax[a]));
  if (!pair.m_algorithm && gap > btScalar(1e-3) && freeBody(*object0) && freeBody(*object1))
  {
    // Two free boxes apart, not yet given an algorithm: none yet, and so no manifold (a pile's
    // boxes had two empty ones each for every one with points, all sorted into islands and
    // passed over every step). A manifold made now would be given the pair's breaking threshold
    // (getNewManifold): the smaller shape's size times gContactBreakingThreshold, or that alone.
    // The gap clears that when it clears gContactBreakingThreshold times the larger of 1 and the
    // smaller size (a box's half diagonal with its margin), with 1 % to spare.
    auto size2 = [](const btCollisionObject& object) {
      const auto* box = static_cast<const btBoxShape*>(object.getCollisionShape());
      const btScalar margin = box->getMarginNV();
      return (box->getImplicitShapeDimensions() + btVector3(margin, margin, margin)).length2();
    };
    const btScalar clears = gap / (btScalar(1.01) * gContactBreakingThreshold);
    if (clears > 1 && std::min(size2(*object0), size2(*object1)) < clears * clears)
      return;
  }
  if (pair.m_algorithm && typeid(*pair.m_algorithm) == typeid(btBoxBoxCollisionAlgorithm))
  {
    // The algorithm's manifold (it owns one, or has none), listed into a buffer on the stack.
    btPersistentManifold* listed[4];
    btManifoldArray manifolds;
    manifolds.initializeFromBuffer(listed, 0, 4);
    pair.m_algorithm->getAllContactManifolds(manifolds);
    btPersistentManifold* manifold = manifolds.size() ? manifolds[0] : nullptr;
    // Without a manifold the algorithm does nothing; with one, what it does for boxes this far apart.
    if (gap > btScalar(1e-3) && (!manifold || gap > manifold->getContactBreakingThreshold()))
    {
      if (manifold && manifold->getNumContacts() > 0 && dispatcher.needsCollision(object0, object1))
        manifold->refreshContactPoints(manifold->getBody0()->getWorldTransform(),
                                       manifold->getBody1()->getWorldTransform());
      return;
    }
  }
  btCollisionDispatcher::defaultNearCallback(pair, dispatcher, info);
}

void DynamicsWorld::removeCollisionObject(btCollisionObject* object)
{
  // The world's solver of the moment: setMultiBodyConstraintSolver may have replaced the first.
  if (auto* solver = dynamic_cast<DenseRowSolver*>(m_multiBodyConstraintSolver))
    solver->forget(object);
  btMultiBodyDynamicsWorld::removeCollisionObject(object);
  may_move_stale_ = true;
}

const std::vector<btCollisionObject*>& DynamicsWorld::mayMove()
{
  if (may_move_stale_)
  {
    may_move_.clear();
    for (int i = 0; i < m_collisionObjects.size(); ++i)
      if (!neverMoves(*m_collisionObjects[i]))
        may_move_.push_back(m_collisionObjects[i]);
    may_move_stale_ = false;
  }
  return may_move_;
}

void DynamicsWorld::saveKinematicState(btScalar timeStep)
{
  // btDiscreteDynamicsWorld's rigid bodies, then btMultiBodyDynamicsWorld's kinematic bases
  for (btCollisionObject* object : mayMove())
  {
    btRigidBody* body = btRigidBody::upcast(object);
    if (body && body->getActivationState() != ISLAND_SLEEPING && body->isKinematicObject())
      body->saveKinematicState(timeStep);
  }
  for (int i = 0; i < m_multiBodies.size(); ++i)
    if (m_multiBodies[i]->isBaseKinematic())
      m_multiBodies[i]->saveKinematicState(timeStep);
}

void wakeUp(btMultiBody& body)
{
  body.wakeUp();  // and its sleep timer starts again
  auto activate = [](btMultiBodyLinkCollider* collider) {
    if (collider && collider->getActivationState() != DISABLE_DEACTIVATION)
    {
      collider->setActivationState(ACTIVE_TAG);
      collider->setDeactivationTime(0);
    }
  };
  activate(body.getBaseCollider());
  for (int i = 0; i < body.getNumLinks(); ++i)
    activate(body.getLink(i).m_collider);
}

void DynamicsWorld::addMultiBody(btMultiBody* body, int group, int mask)
{
  btMultiBodyDynamicsWorld::addMultiBody(body, group, mask);
  body->setUserIndex(m_multiBodies.size() - 1);
  states_.emplace_back();
}

void DynamicsWorld::removeMultiBody(btMultiBody* body)
{
  btMultiBodyDynamicsWorld::removeMultiBody(body);  // moves the last multibody into its place
  for (int i = 0; i < m_multiBodies.size(); ++i)
    m_multiBodies[i]->setUserIndex(i);
  states_.clear();  // rebuilt at the next step anyway
  states_.resize(m_multiBodies.size());
  built_.clear();
}

DynamicsWorld::StepState& DynamicsWorld::stepState(btMultiBody& body)
{
  const int number = numberOf(body);
  StepState& step = states_[number];
  if (step.current)
    return step;
  step.current = true;
  built_.push_back(number);
  step.articulated_pass_pending = false;
  if (!step.state)
    step.state.reset(new MultibodyState);
  step.valid = buildMultibodyState(body, *step.state);
  return step;
}

const MultibodyState* DynamicsWorld::stateOf(btMultiBody& body)
{
  const StepState& step = stepState(body);
  return step.valid ? step.state.get() : nullptr;
}

void DynamicsWorld::addCollisionObject(btCollisionObject* object, int group, int mask)
{
  btMultiBodyDynamicsWorld::addCollisionObject(object, group, mask);
  may_move_stale_ = true;
  if (neverMoves(*object))
  {
    updateSingleAabb(object);
    // As btDiscreteDynamicsWorld::addRigidBody does for a static body: a pair of two inactive
    // objects is left out of the narrow phase (btCollisionDispatcher::needsCollision), so a body
    // asleep on the ground costs no contact test. A moving body's pairs with it are active.
    object->setActivationState(ISLAND_SLEEPING);
  }
}

// Each awake multibody link's reach: (|v| + |omega| * r) * dt, r the radius of a sphere about the
// link's frame that holds its shape, v and omega the link's velocities at the start of the step
// (gravity adds g * dt^2 = 10 um at 1 ms, well within the breaking threshold on top).
void DynamicsWorld::measureReach()
{
  reach_.assign(size_t(m_collisionObjects.size()), btScalar(0));
  const btScalar dt = getSolverInfo().m_timeStep;
  for (int i = 0; i < m_multiBodies.size(); ++i)
  {
    btMultiBody* body = m_multiBodies[i];
    if (sleeping(*body))
      continue;
    const int links = body->getNumLinks();
    link_omega_.resize(size_t(links) + 1);
    link_velocity_.resize(size_t(links) + 1);
    body->compTreeLinkVelocities(link_omega_.data(), link_velocity_.data());  // index 0: the base
    for (int link = -1; link < links; ++link)
    {
      btMultiBodyLinkCollider* collider = link < 0 ? body->getBaseCollider() : body->getLink(link).m_collider;
      if (!collider || collider->getWorldArrayIndex() < 0)
        continue;
      btVector3 centre;
      btScalar radius;
      collider->getCollisionShape()->getBoundingSphere(centre, radius);
      const size_t k = size_t(link + 1);
      reach_[size_t(collider->getWorldArrayIndex())] =
          (link_velocity_[k].length() + link_omega_[k].length() * (centre.length() + radius)) * dt;
    }
  }
}

btScalar DynamicsWorld::reachOf(const btCollisionObject& object) const
{
  const int index = object.getWorldArrayIndex();
  return index >= 0 && size_t(index) < reach_.size() ? reach_[size_t(index)] : btScalar(0);
}

void DynamicsWorld::updateAabbs()
{
  measureReach();
  for (btCollisionObject* object : mayMove())
  {
    if (object->getActivationState() == ISLAND_SLEEPING)
      continue;
    updateSingleAabb(object);
    // Bullet's box is the shape's grown by the breaking threshold; one that may move further in a
    // step than that is grown by twice its reach (see the header).
    const btScalar reach = reachOf(*object);
    btBroadphaseProxy* proxy = object->getBroadphaseHandle();
    if (reach > gContactBreakingThreshold && proxy && object->getActivationState() != DISABLE_SIMULATION)
    {
      const btVector3 grow(2 * reach, 2 * reach, 2 * reach);
      m_broadphasePairCache->setAabb(proxy, proxy->m_aabbMin - grow, proxy->m_aabbMax + grow, m_dispatcher1);
    }
  }
}

// The threshold btCollisionDispatcher::getNewManifold gives a pair: with its default
// CD_USE_RELATIVE_CONTACT_BREAKING_THRESHOLD, gContactBreakingThreshold times the smaller shape's
// size (getAngularMotionDisc, a bounding sphere through the shape's virtual box): about 0.05 mm for
// the car's wheels, not 1 mm. Each object's is found once a step (breaking_), not once for each of
// its manifolds (a box in a pile has a dozen).
btScalar DynamicsWorld::breakingThreshold(const btCollisionObject& object)
{
  const int index = object.getWorldArrayIndex();
  if (index < 0 || size_t(index) >= breaking_.size())
    return object.getCollisionShape()->getContactBreakingThreshold(gContactBreakingThreshold);
  btScalar& threshold = breaking_[size_t(index)];
  if (threshold < 0)
    threshold = object.getCollisionShape()->getContactBreakingThreshold(gContactBreakingThreshold);
  return threshold;
}

void DynamicsWorld::setManifoldThresholds()
{
  const auto* dispatcher = static_cast<const btCollisionDispatcher*>(m_dispatcher1);
  const bool relative = dispatcher->getDispatcherFlags() & btCollisionDispatcher::CD_USE_RELATIVE_CONTACT_BREAKING_THRESHOLD;
  breaking_.assign(size_t(m_collisionObjects.size()), btScalar(-1));
  for (int i = 0; i < m_dispatcher1->getNumManifolds(); ++i)
  {
    btPersistentManifold* manifold = m_dispatcher1->getManifoldByIndexInternal(i);
    btScalar threshold = relative ? std::min(breakingThreshold(*manifold->getBody0()),
                                             breakingThreshold(*manifold->getBody1()))
                                  : gContactBreakingThreshold;
    if (manifold->getNumContacts() == 0)
      threshold += reachOf(*manifold->getBody0()) + reachOf(*manifold->getBody1());
    manifold->setContactBreakingThreshold(threshold);
  }
}

// btCollisionWorld::performDiscreteCollisionDetection with the manifolds' thresholds set between
// the broad phase and the narrow phase.
void DynamicsWorld::performDiscreteCollisionDetection()
{
  updateAabbs();
  computeOverlappingPairs();
  setManifoldThresholds();
  if (m_dispatcher1)
    m_dispatcher1->dispatchAllCollisionPairs(m_broadphasePairCache->getOverlappingPairCache(), getDispatchInfo(),
                                             m_dispatcher1);
}

void DynamicsWorld::updateActivationState(btScalar timeStep)
{
  btMultiBodyDynamicsWorld::updateActivationState(timeStep);
  for (int i = 0; i < m_multiBodies.size(); ++i)
  {
    btMultiBody* body = m_multiBodies[i];
    if (!sleeping(*body))
      continue;
    body->setBaseVel(btVector3(0, 0, 0));
    body->setBaseOmega(btVector3(0, 0, 0));
    for (int link = 0; link < body->getNumLinks(); ++link)
      for (int dof = 0; dof < body->getLink(link).m_dofCount; ++dof)
        body->getJointVelMultiDof(link)[dof] = 0;
  }
}

void DynamicsWorld::runArticulatedPass(btMultiBody& body, StepState& step)
{
  if (!step.articulated_pass_pending)
    return;
  // With dt = 0 the pass leaves the velocities alone and only fills its caches, which depend on
  // the configuration alone.
  body.computeAccelerationsArticulatedBodyAlgorithmMultiDof(0, m_scratch_r, m_scratch_v, m_scratch_m, false, false,
                                                            false);
  step.articulated_pass_pending = false;
}

void DynamicsWorld::needArticulatedPass(btMultiBody& body)
{
  StepState& step = states_[numberOf(body)];
  if (step.current)
    runArticulatedPass(body, step);
}

void DynamicsWorld::needArticulatedPasses()
{
  for (int number : built_)
    runArticulatedPass(*m_multiBodies[number], states_[number]);
}

bool DynamicsWorld::integrateVelocities(btMultiBody& body, btScalar dt)
{
  // What the joint-space form does not cover: Bullet's RK4 integration, joint force feedback
  // (computed by the articulated-body pass itself), kinematic bases and links.
  if (body.isUsingRK4Integration() || (!body.hasFixedBase() && body.isBaseStaticOrKinematic()))
    return false;
  for (int i = 0; i < body.getNumLinks(); ++i)
    if (body.getLink(i).m_jointFeedback || body.isLinkAndAllAncestorsKinematic(i))
      return false;
  StepState& step = stepState(body);
  if (!step.valid)
    return false;
  accelerations_.resize(body.getNumDofs() + 6);
  forwardDynamics(body, *step.state, accelerations_.data());
  body.applyDeltaVeeMultiDof(accelerations_.data(), dt);
  step.articulated_pass_pending = true;
  return true;
}

// Bullet 3.24's btMultiBodyDynamicsWorld::solveExternalForces for bodies integrated with explicit
// Euler (gravity and clearing of forces live in applyGravity and clearForces with
// BT_USE_VIRTUAL_CLEARFORCES_AND_GRAVITY): the same preparation, then each awake multibody's
// velocities from its joint-space state where it can, else from Bullet's pass.
void DynamicsWorld::solveExternalForces(btContactSolverInfo& info)
{
  for (int number : built_)  // a new step: every multibody's state is rebuilt when first asked for
    states_[number].current = false;
  built_.clear();
  for (int i = 0; i < m_multiBodies.size(); ++i)
    if (m_multiBodies[i]->isUsingRK4Integration())
    {
      btMultiBodyDynamicsWorld::solveExternalForces(info);
      return;
    }

  // Bullet's forwardKinematics() for the awake multibodies: a sleeping one has not moved.
  for (int i = 0; i < m_multiBodies.size(); ++i)
    if (!sleeping(*m_multiBodies[i]))
      m_multiBodies[i]->forwardKinematics(m_scratch_world_to_local, m_scratch_local_origin);
  clearMultiBodyConstraintForces();
  m_sortedConstraints.resize(m_constraints.size());
  for (int i = 0; i < m_constraints.size(); ++i)
    m_sortedConstraints[i] = m_constraints[i];
  m_sortedConstraints.quickSort(btSortConstraintOnIslandPredicate2());
  m_sortedMultiBodyConstraints.resize(m_multiBodyConstraints.size());
  for (int i = 0; i < m_multiBodyConstraints.size(); ++i)
    m_sortedMultiBodyConstraints[i] = m_multiBodyConstraints[i];
  m_sortedMultiBodyConstraints.quickSort(btSortMultiBodyConstraintOnIslandPredicate());
  m_solverMultiBodyIslandCallback->setup(&info, m_sortedConstraints.size() ? &m_sortedConstraints[0] : nullptr,
                                         m_sortedConstraints.size(),
                                         m_sortedMultiBodyConstraints.size() ? &m_sortedMultiBodyConstraints[0] : nullptr,
                                         m_sortedMultiBodyConstraints.size(), getDebugDrawer());
  m_constraintSolver->prepareSolve(getCollisionWorld()->getNumCollisionObjects(),
                                   getCollisionWorld()->getDispatcher()->getNumManifolds());

  for (int i = 0; i < m_multiBodies.size(); ++i)
  {
    btMultiBody* body = m_multiBodies[i];
    if (sleeping(*body) || integrateVelocities(*body, info.m_timeStep))
      continue;
    m_scratch_r.resize(body->getNumLinks() + 1);
    m_scratch_v.resize(body->getNumLinks() + 1);
    m_scratch_m.resize(body->getNumLinks() + 1);
    body->computeAccelerationsArticulatedBodyAlgorithmMultiDof(info.m_timeStep, m_scratch_r, m_scratch_v, m_scratch_m,
                                                               false, getSolverInfo().m_jointFeedbackInWorldSpace,
                                                               getSolverInfo().m_jointFeedbackInJointFrame);
  }
}

}  // namespace bullet_plant
