#include "dynamics_world.h"

#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>

#include "dense_row_solver.h"

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
}  // namespace

DynamicsWorld::DynamicsWorld(btDispatcher* dispatcher, btBroadphaseInterface* broadphase, DenseRowSolver* solver,
                             btCollisionConfiguration* configuration)
  : btMultiBodyDynamicsWorld(dispatcher, broadphase, solver, configuration), solver_(solver)
{
}

// Bullet 3.24's btMultiBodyDynamicsWorld::solveExternalForces for bodies integrated with explicit
// Euler (gravity and clearing of forces live in applyGravity and clearForces with
// BT_USE_VIRTUAL_CLEARFORCES_AND_GRAVITY): the same preparation, then each awake multibody's
// velocities from the solver's joint-space dynamics where it can, else from Bullet's pass.
void DynamicsWorld::solveExternalForces(btContactSolverInfo& info)
{
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
    if (sleeping(*body) || solver_->integrateVelocities(*body, info.m_timeStep))
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
