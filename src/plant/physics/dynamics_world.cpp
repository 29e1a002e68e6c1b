#include "physics/dynamics_world.h"

#include <algorithm>

#include <BulletCollision/CollisionDispatch/btCollisionDispatcher.h>
#include <BulletCollision/CollisionShapes/btCollisionShape.h>
#include <BulletCollision/NarrowPhaseCollision/btPersistentManifold.h>
#include <BulletDynamics/Featherstone/btMultiBody.h>
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

DynamicsWorld::DynamicsWorld(btDispatcher* dispatcher, btBroadphaseInterface* broadphase, DenseRowSolver* solver,
                             btCollisionConfiguration* configuration)
  : btMultiBodyDynamicsWorld(dispatcher, broadphase, solver, configuration), solver_(solver)
{
  solver->useStates(this);
}

void DynamicsWorld::removeCollisionObject(btCollisionObject* object)
{
  solver_->forgetBounce(object);
  btMultiBodyDynamicsWorld::removeCollisionObject(object);
}

DynamicsWorld::StepState& DynamicsWorld::stepState(btMultiBody& body)
{
  for (size_t k = 0; k < states_used_; ++k)
    if (states_[k].body == &body)
      return states_[k];
  if (states_used_ == states_.size())
    states_.emplace_back();
  StepState& step = states_[states_used_++];
  step.body = &body;
  step.articulated_pass_pending = false;
  if (!step.state)
    step.state.reset(new MultibodyState);
  if (!buildMultibodyState(body, *step.state))
    step.state.reset();
  return step;
}

const MultibodyState* DynamicsWorld::stateOf(btMultiBody& body) { return stepState(body).state.get(); }

void DynamicsWorld::addCollisionObject(btCollisionObject* object, int group, int mask)
{
  btMultiBodyDynamicsWorld::addCollisionObject(object, group, mask);
  if (neverMoves(*object))
    updateSingleAabb(object);
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
  for (int i = 0; i < m_collisionObjects.size(); ++i)
  {
    btCollisionObject* object = m_collisionObjects[i];
    if (neverMoves(*object))
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
// size (getAngularMotionDisc): about 0.05 mm for the car's wheels, not 1 mm.
btScalar DynamicsWorld::pairThreshold(const btPersistentManifold& manifold) const
{
  const auto* dispatcher = static_cast<const btCollisionDispatcher*>(m_dispatcher1);
  if (!(dispatcher->getDispatcherFlags() & btCollisionDispatcher::CD_USE_RELATIVE_CONTACT_BREAKING_THRESHOLD))
    return gContactBreakingThreshold;
  return std::min(manifold.getBody0()->getCollisionShape()->getContactBreakingThreshold(gContactBreakingThreshold),
                  manifold.getBody1()->getCollisionShape()->getContactBreakingThreshold(gContactBreakingThreshold));
}

void DynamicsWorld::setManifoldThresholds()
{
  for (int i = 0; i < m_dispatcher1->getNumManifolds(); ++i)
  {
    btPersistentManifold* manifold = m_dispatcher1->getManifoldByIndexInternal(i);
    btScalar threshold = pairThreshold(*manifold);
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

void DynamicsWorld::runArticulatedPass(StepState& step)
{
  if (!step.articulated_pass_pending)
    return;
  // With dt = 0 the pass leaves the velocities alone and only fills its caches, which depend on
  // the configuration alone.
  step.body->computeAccelerationsArticulatedBodyAlgorithmMultiDof(0, m_scratch_r, m_scratch_v, m_scratch_m, false,
                                                                  false, false);
  step.articulated_pass_pending = false;
}

void DynamicsWorld::needArticulatedPass(btMultiBody& body)
{
  for (size_t k = 0; k < states_used_; ++k)
    if (states_[k].body == &body)
      runArticulatedPass(states_[k]);
}

void DynamicsWorld::needArticulatedPasses()
{
  for (size_t k = 0; k < states_used_; ++k)
    runArticulatedPass(states_[k]);
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
  if (!step.state)
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
  states_used_ = 0;  // a new step: every multibody's state is rebuilt when first asked for
  for (int i = 0; i < m_multiBodies.size(); ++i)
    if (m_multiBodies[i]->isUsingRK4Integration())
    {
      btMultiBodyDynamicsWorld::solveExternalForces(info);
      return;
    }

  forwardKinematics();
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
