#include "physics/dense_row_solver.h"

#include <algorithm>
#include <cmath>

#include <BulletCollision/NarrowPhaseCollision/btManifoldPoint.h>

#include <BulletCollision/NarrowPhaseCollision/btPersistentManifold.h>
#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>

#include "physics/joint_drive.h"

namespace bullet_plant
{
namespace
{
int degreesOfFreedom(const btMultiBody* body) { return body->getNumDofs() + 6; }

// Velocity change of row i per unit impulse on row j: J_i M^-1 J_j^T over the multibodies the two
// rows share (a row acting between two links of one multibody shares it on both sides).
btScalar response(const btMultiBodySolverConstraint& i, const btMultiBodySolverConstraint& j,
                  const btMultiBodyJacobianData& data)
{
  btScalar sum = 0;
  const btMultiBody* sides_i[2] = {i.m_multiBodyA, i.m_multiBodyB};
  const int jacobian_i[2] = {i.m_jacAindex, i.m_jacBindex};
  const btMultiBody* sides_j[2] = {j.m_multiBodyA, j.m_multiBodyB};
  const int response_j[2] = {j.m_jacAindex, j.m_jacBindex};
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b)
      if (sides_i[a] && sides_i[a] == sides_j[b])
        sum += dot(&data.m_jacobians[jacobian_i[a]], &data.m_deltaVelocitiesUnitImpulse[response_j[b]],
                   degreesOfFreedom(sides_i[a]));
  return sum;
}
// What Bullet derives from a row's J M^-1 J^T + cfm (denominator): m_jacDiagABInv =
// sor / denominator, and the rhs and cfm scaled by it.
void scaleRow(btMultiBodySolverConstraint& row, btScalar denominator, btScalar velocity_error, btScalar cfm,
              btScalar sor)
{
  row.m_jacDiagABInv = denominator > SIMD_EPSILON ? sor / denominator : btScalar(0);
  row.m_rhs = velocity_error * row.m_jacDiagABInv;
  row.m_cfm = cfm * row.m_jacDiagABInv;
}

}  // namespace

btScalar DenseRowSolver::freeResponse(const BodyRows& slot, const btScalar* jacobian, btScalar* response)
{
  const btScalar* I = slot.inverse_inertia;
  btScalar diagonal = 0;
  for (int a = 0; a < 3; ++a)
  {
    response[a] = I[3 * a] * jacobian[0] + I[3 * a + 1] * jacobian[1] + I[3 * a + 2] * jacobian[2];
    response[3 + a] = jacobian[3 + a] * slot.inverse_mass;
  }
  for (int i = 0; i < 6; ++i)
    diagonal += jacobian[i] * response[i];
  return diagonal;
}

int DenseRowSolver::bodySlot(btMultiBody* body)
{
  const int number = MultibodyStates::numberOf(*body);
  if (number < 0 || size_t(number) >= slot_of_.size())  // no states_, or not numbered by them
    return -1;
  int& known = slot_of_[number];
  if (known < 0)
  {
    known = int(bodies_used_);
    if (bodies_used_ == body_rows_.size())
      body_rows_.emplace_back();
    BodyRows& slot = body_rows_[bodies_used_++];
    slot.body = body;
    slot.number = number;
    slot.state = states_->stateOf(*body);
    slot.rows.clear();
    slot.pair_rows = false;
    slot.free = slot.state && slot.state->free;
    if (slot.free)
    {
      for (int k = 0; k < 9; ++k)
        slot.inverse_inertia[k] = btScalar(slot.state->inverse_inertia[k]);
      slot.inverse_mass = btScalar(slot.state->inverse_mass);
    }
  }
  return body_rows_[known].state ? known : -1;
}

void DenseRowSolver::needArticulatedPass(btMultiBody* body)
{
  if (states_ && body)
    states_->needArticulatedPass(*body);
}

void DenseRowSolver::deferSide(btMultiBodyConstraintArray& rows, int index, int slot, int jacobian,
                               btScalar velocity_error, btScalar cfm, btScalar sor, btScalar other)
{
  std::vector<int>& own = body_rows_[slot].rows;
  own.push_back(int(deferred_.size()));
  deferred_.push_back(
      DeferredRow{&rows, index, slot, int(own.size() - 1), jacobian, -1, velocity_error, cfm, sor, 0, other});
}

void DenseRowSolver::deferResponse(btMultiBodyConstraintArray& rows, int index, int slot, btScalar velocity_error,
                                   btScalar cfm, btScalar sor)
{
  const btMultiBodySolverConstraint& row = rows[index];
  deferSide(rows, index, slot, row.m_multiBodyA ? row.m_jacAindex : row.m_jacBindex, velocity_error, cfm, sor, 0);
}

void DenseRowSolver::deferPairResponse(btMultiBodyConstraintArray& rows, int index, int slot_a, int slot_b,
                                       btScalar velocity_error, btScalar cfm, btScalar sor)
{
  const btMultiBodySolverConstraint& row = rows[index];
  const int first = int(deferred_.size());
  deferSide(rows, index, slot_a, row.m_jacAindex, velocity_error, cfm, sor, 0);
  deferSide(rows, index, slot_b, row.m_jacBindex, 0, 0, 0, 0);
  deferred_[first].partner = first + 1;
  deferred_[first + 1].partner = -2;
  body_rows_[slot_a].pair_rows = body_rows_[slot_b].pair_rows = true;
}

// The responses M^-1 J^T of each multibody's deferred rows, all at once, and what Bullet derives
// from them: m_jacDiagABInv = sor / (J M^-1 J^T + cfm) (the sum over a row's two sides between two
// multibodies), and the rhs and cfm scaled by it.
void DenseRowSolver::finishDeferredRows()
{
  for (size_t s = 0; s < bodies_used_; ++s)
  {
    BodyRows& slot = body_rows_[s];
    const int k = int(slot.rows.size());
    slot.has_gram = false;
    if (k == 0)
      continue;
    const int n = slot.state->n;
    const int padded = (k + kInertiaSides - 1) / kInertiaSides * kInertiaSides;
    slot.columns.assign(size_t(n) * padded, btScalar(0));
    slot.has_gram = !slot.pair_rows;
    if (slot.has_gram)
      slot.gram.resize(size_t(padded) * padded);
    slot.stride = padded;
    for (int p = 0; p < k; ++p)
    {
      const btScalar* jacobian = &m_data.m_jacobians[deferred_[slot.rows[p]].jacobian];
      for (int i = 0; i < n; ++i)
        slot.columns[size_t(i) * padded + p] = jacobian[i];
    }
    solveInertiaColumns(*slot.state, slot.columns.data(), padded, slot.has_gram ? slot.gram.data() : nullptr);
    for (int p = 0; p < k; ++p)
    {
      DeferredRow& d = deferred_[slot.rows[p]];
      btScalar* response = &m_data.m_deltaVelocitiesUnitImpulse[d.jacobian];
      for (int i = 0; i < n; ++i)
        response[i] = slot.columns[size_t(i) * padded + p];
      if (slot.has_gram)
        d.diagonal = slot.gram[size_t(p) * padded + p];
      else
      {
        const btScalar* jacobian = &m_data.m_jacobians[d.jacobian];
        btScalar diagonal = 0;
        for (int i = 0; i < n; ++i)
          diagonal += jacobian[i] * response[i];
        d.diagonal = diagonal;
      }
    }
  }
  for (const DeferredRow& d : deferred_)
  {
    if (d.partner == -2)
      continue;
    const btScalar denominator = d.partner >= 0 ? d.diagonal + deferred_[d.partner].diagonal + d.cfm
                                 : d.other != 0 ? d.diagonal + d.other + d.cfm
                                                : d.diagonal + d.cfm;
    scaleRow((*d.rows)[d.index], denominator, d.velocity_error, d.cfm, d.sor);
  }
}

// A friction row's constraint force mixing, in ODE's units (its rows divide it by the step): ODE's
// force-dependent slip where the point's surfaces give one (ODE's contact joint takes slip1 and
// slip2 as its friction rows' cfm: the contact slides at `slip` m/s per N of friction), else the
// world's friction CFM.
static btScalar frictionCfm(const btContactSolverInfo& info, btScalar slip)
{
  return slip > 0 ? slip : info.m_frictionCFM;
}

// A friction row of Bullet's setupMultiBodyContactConstraint given the cfm of `slip` in place of
// the world's: its diagonal, right-hand side and cfm as that setup would have made them.
static void setSlip(btMultiBodySolverConstraint& row, const btContactSolverInfo& info, btScalar slip,
                    btScalar relaxation)
{
  if (!(slip > 0) || !(row.m_jacDiagABInv > 0))
    return;
  const btScalar old_cfm = info.m_frictionCFM / info.m_timeStep, cfm = slip / info.m_timeStep;
  const btScalar denominator = relaxation / row.m_jacDiagABInv - old_cfm + cfm;
  const btScalar diagonal = relaxation / denominator;
  row.m_rhs *= diagonal / row.m_jacDiagABInv;
  row.m_rhsPenetration *= diagonal / row.m_jacDiagABInv;
  row.m_jacDiagABInv = diagonal;
  row.m_cfm = cfm * diagonal;
}

// A friction row's coefficient, and the bounds its setup derives from it.
static void setFriction(btMultiBodySolverConstraint& row, btScalar mu)
{
  row.m_friction = mu;
  row.m_lowerLimit = -mu;
  row.m_upperLimit = mu;
}

// A contact between one multibody and the static world, with plain pyramid friction: what
// convertMultiBodyContact handles without its rigid-body, rolling, spinning, anisotropic and
// cached-direction cases.
bool DenseRowSolver::contactRowsApply(const btPersistentManifold& manifold, const btContactSolverInfo& info)
{
  const auto* a = btMultiBodyLinkCollider::upcast(manifold.getBody0());
  const auto* b = btMultiBodyLinkCollider::upcast(manifold.getBody1());
  if ((a != nullptr) == (b != nullptr))
    return false;
  const btCollisionObject* other = a ? manifold.getBody1() : manifold.getBody0();
  if (!other->isStaticObject() || btRigidBody::upcast(other))
    return false;
  for (const btCollisionObject* object : {manifold.getBody0(), manifold.getBody1()})
    if (object->hasAnisotropicFriction(btCollisionObject::CF_ANISOTROPIC_FRICTION |
                                       btCollisionObject::CF_ANISOTROPIC_ROLLING_FRICTION))
      return false;
  if (info.m_solverMode & SOLVER_ENABLE_FRICTION_DIRECTION_CACHING)
    return false;
  for (int j = 0; j < manifold.getNumContacts(); ++j)
  {
    const btManifoldPoint& point = manifold.getContactPoint(j);
    if (point.m_combinedRollingFriction > 0 || point.m_combinedSpinningFriction > 0)
      return false;
  }
  return bodySlot((a ? a : b)->m_multiBody) >= 0;
}

// The error reduction and constraint force mixing of a contact's normal row, as Bullet's solvers
// choose them from the point's flags (erp and cfm hold the solver's defaults on entry).
static void normalRowSoftness(const btManifoldPoint& point, const btContactSolverInfo& info, btScalar& erp, btScalar& cfm)
{
  if (point.m_contactPointFlags & (BT_CONTACT_FLAG_HAS_CONTACT_CFM | BT_CONTACT_FLAG_HAS_CONTACT_ERP))
  {
    if (point.m_contactPointFlags & BT_CONTACT_FLAG_HAS_CONTACT_CFM)
      cfm = point.m_contactCFM;
    if (point.m_contactPointFlags & BT_CONTACT_FLAG_HAS_CONTACT_ERP)
      erp = point.m_contactERP;
  }
  else if (point.m_contactPointFlags & BT_CONTACT_FLAG_CONTACT_STIFFNESS_DAMPING)
  {
    const btScalar denominator = std::max(info.m_timeStep * point.m_combinedContactStiffness1 + point.m_combinedContactDamping1,
                                          btScalar(SIMD_EPSILON));
    cfm = btScalar(1) / denominator;
    erp = info.m_timeStep * point.m_combinedContactStiffness1 / denominator;
  }
}

// ODE's contact_max_correcting_vel for every solver path (Bullet's rigid and multibody rows and
// setupContactRow): each turns a penetration into the velocity (depth - slop) * erp / dt, so the
// depth the rows see is held to what max_correcting_velocity_ corrects in one step, or a surface's
// max_vel where smaller. The manifold recomputes its depths from the bodies' positions next step,
// so nothing of the real depth is lost.
void DenseRowSolver::limitCorrectingVelocity(btPersistentManifold& manifold, const btContactSolverInfo& info,
                                             const PointSurface* surfaces) const
{
  for (int j = 0; j < manifold.getNumContacts(); ++j)
  {
    btManifoldPoint& point = manifold.getContactPoint(j);
    btScalar erp = info.m_erp2, cfm = info.m_globalCfm;
    normalRowSoftness(point, info, erp, cfm);
    if (erp <= 0)
      continue;
    const btScalar cap = surfaces ? std::min(max_correcting_velocity_, surfaces[j].max_vel) : max_correcting_velocity_;
    const btScalar deepest = -cap * info.m_timeStep / erp - info.m_linearSlop;
    if (point.m_distance1 < deepest)
      point.m_distance1 = deepest;
  }
}

void DenseRowSolver::setBounce(btCollisionObject& object, btScalar restitution, btScalar threshold)
{
  object.setRestitution(restitution);
  if (restitution > 0)
    bounce_thresholds_[&object] = threshold;
  else
    bounce_thresholds_.erase(&object);
}

btScalar DenseRowSolver::bounceThreshold(const btPersistentManifold& manifold) const
{
  btScalar threshold = BT_LARGE_FLOAT;
  for (const btCollisionObject* object : {manifold.getBody0(), manifold.getBody1()})
  {
    auto found = bounce_thresholds_.find(object);
    if (found != bounce_thresholds_.end())
      threshold = std::min(threshold, found->second);
  }
  return threshold;
}

// setupMultiBodyContactConstraint for a multibody on one side and the static world on the other.
void DenseRowSolver::setupContactRow(btMultiBodyConstraintArray& rows, int index, const btVector3& direction,
                                     btManifoldPoint& point, const btContactSolverInfo& info, bool friction,
                                     btScalar slip, btScalar bounce_threshold)
{
  btMultiBodySolverConstraint& row = rows[index];
  const bool on_a = row.m_multiBodyA != nullptr;
  btMultiBody* body = on_a ? row.m_multiBodyA : row.m_multiBodyB;
  const int link = on_a ? row.m_linkA : row.m_linkB;
  const btVector3& position = on_a ? point.getPositionWorldOnA() : point.getPositionWorldOnB();
  const btVector3 normal = on_a ? direction : -direction;  // the multibody's side of the row
  const int n = body->getNumDofs() + 6;

  btScalar cfm = friction ? frictionCfm(info, slip) : info.m_globalCfm;
  btScalar erp = friction ? info.m_frictionERP : info.m_erp2;
  if (!friction)
    normalRowSoftness(point, info, erp, cfm);
  cfm /= info.m_timeStep;

  int& velocity_index = on_a ? row.m_deltaVelAindex : row.m_deltaVelBindex;
  velocity_index = body->getCompanionId();
  if (velocity_index < 0)
  {
    velocity_index = m_data.m_deltaVelocities.size();
    body->setCompanionId(velocity_index);
    m_data.m_deltaVelocities.resize(m_data.m_deltaVelocities.size() + n);
  }
  int& jacobian_index = on_a ? row.m_jacAindex : row.m_jacBindex;
  jacobian_index = m_data.m_jacobians.size();
  // Both written whole below (J here, M^-1 J^T by the free body's response or finishDeferredRows).
  m_data.m_jacobians.resizeNoInitialize(m_data.m_jacobians.size() + n);
  m_data.m_deltaVelocitiesUnitImpulse.resizeNoInitialize(m_data.m_deltaVelocitiesUnitImpulse.size() + n);
  btScalar* jacobian = &m_data.m_jacobians[jacobian_index];
  const int slot = bodySlot(body);
  contactJacobianRow(*body_rows_[slot].state, link, position, normal, jacobian);

  // Lever arms as Bullet keeps them: the multibody's from its link's centre of mass, the static
  // side's from its solver body (whose velocity never changes).
  const btVector3 origin = link < 0 ? body->getBasePos() : body->getLink(link).m_cachedWorldTransform.getOrigin();
  const btSolverBody& fixed = m_tmpSolverBodyPool[on_a ? row.m_solverBodyIdB : row.m_solverBodyIdA];
  const btVector3 arm_a = on_a ? position - origin : point.getPositionWorldOnA() - fixed.getWorldTransform().getOrigin();
  const btVector3 arm_b = on_a ? point.getPositionWorldOnB() - fixed.getWorldTransform().getOrigin() : position - origin;
  row.m_relpos1CrossNormal = arm_a.cross(direction);
  row.m_contactNormal1 = direction;
  row.m_relpos2CrossNormal = -arm_b.cross(direction);
  row.m_contactNormal2 = -direction;
  row.m_angularComponentA.setZero();
  row.m_angularComponentB.setZero();

  btScalar relative_velocity = 0;
  const btScalar* velocity = body->getVelocityVector();
  for (int i = 0; i < n; ++i)
    relative_velocity += velocity[i] * jacobian[i];
  row.m_friction = point.m_combinedFriction;

  btScalar distance = 0, bounce = 0;
  if (!friction)
  {
    distance = point.getDistance() + info.m_linearSlop;
    // ODE's bounce (its contact joint's getInfo2): the surfaces part at restitution times the speed
    // they meet at, where that speed is above the threshold. A point still ahead (a speculative
    // contact, DynamicsWorld) bounces only if the bodies reach it within the step; they part from
    // where they touch then, not from the point's distance.
    const btScalar approach = -relative_velocity;
    if (point.m_combinedRestitution > 0 && approach > bounce_threshold && approach * info.m_timeStep > distance)
      bounce = point.m_combinedRestitution * approach;
  }
  else if (point.m_contactPointFlags & BT_CONTACT_FLAG_FRICTION_ANCHOR)
  {
    distance = (point.getPositionWorldOnA() - point.getPositionWorldOnB()).dot(direction);
  }
  btScalar positional_error = 0, velocity_error = -relative_velocity;
  if (!friction && distance > 0)
    velocity_error -= distance / info.m_timeStep;
  else
    positional_error = -distance * erp / info.m_timeStep;
  if (bounce > 0)
  {
    // ODE again: the speed apart is the larger of the bounce and the depth's correction, not their
    // sum (Bullet's), which would throw a body that landed deep higher than it fell.
    positional_error = std::max(positional_error - bounce, btScalar(0));
    velocity_error = bounce - relative_velocity;
  }
  row.m_rhsPenetration = 0;
  row.m_lowerLimit = friction ? -row.m_friction : btScalar(0);
  row.m_upperLimit = friction ? row.m_friction : btScalar(1e10);
  row.m_appliedImpulse = 0;
  row.m_appliedPushImpulse = 0;
  if (body_rows_[slot].free)
    scaleRow(row, freeResponse(body_rows_[slot], jacobian, &m_data.m_deltaVelocitiesUnitImpulse[jacobian_index]) + cfm,
             positional_error + velocity_error, cfm, info.m_sor);
  else
    deferResponse(rows, index, slot, positional_error + velocity_error, cfm, info.m_sor);
}

// convertMultiBodyContact's rows (a normal row, then one or two friction rows per point), built by
// setupContactRow; with `surfaces`, each point's friction directions (ContactSurfaces::apply set
// them) and its mu2 on the second.
void DenseRowSolver::convertStaticContact(btPersistentManifold& manifold, const btContactSolverInfo& info,
                                          const PointSurface* surfaces)
{
  auto* object_a = const_cast<btCollisionObject*>(manifold.getBody0());
  auto* object_b = const_cast<btCollisionObject*>(manifold.getBody1());
  const auto* collider_a = btMultiBodyLinkCollider::upcast(object_a);
  const auto* collider_b = btMultiBodyLinkCollider::upcast(object_b);
  const int solver_body_a = collider_a ? -1 : getOrInitSolverBody(*object_a, info.m_timeStep);
  const int solver_body_b = collider_b ? -1 : getOrInitSolverBody(*object_b, info.m_timeStep);
  auto start = [&](btMultiBodySolverConstraint& row, btManifoldPoint& point) {
    row.m_orgConstraint = nullptr;
    row.m_orgDofIndex = -1;
    row.m_solverBodyIdA = solver_body_a;
    row.m_solverBodyIdB = solver_body_b;
    row.m_multiBodyA = collider_a ? collider_a->m_multiBody : nullptr;
    row.m_multiBodyB = collider_b ? collider_b->m_multiBody : nullptr;
    if (collider_a)
      row.m_linkA = collider_a->m_link;
    if (collider_b)
      row.m_linkB = collider_b->m_link;
    row.m_originalContactPoint = &point;
  };
  const bool two_directions = info.m_solverMode & SOLVER_USE_2_FRICTION_DIRECTIONS;
  const btScalar bounce_threshold = bounce_thresholds_.empty() ? BT_LARGE_FLOAT : bounceThreshold(manifold);
  for (int j = 0; j < manifold.getNumContacts(); ++j)
  {
    btManifoldPoint& point = manifold.getContactPoint(j);
    if (point.getDistance() > manifold.getContactProcessingThreshold())
    {
      point.m_appliedImpulse = 0;
      point.m_prevRHS = 0;
      continue;
    }
    const int normal_index = m_multiBodyNormalContactConstraints.size();
    btMultiBodySolverConstraint& normal = m_multiBodyNormalContactConstraints.expandNonInitializing();
    start(normal, point);
    normal.m_frictionIndex = m_multiBodyFrictionContactConstraints.size();
    setupContactRow(m_multiBodyNormalContactConstraints, normal_index, point.m_normalWorldOnB, point, info, false, 0,
                    bounce_threshold);

    if (!surfaces)
    {
      btPlaneSpace1(point.m_normalWorldOnB, point.m_lateralFrictionDir1, point.m_lateralFrictionDir2);
      point.m_lateralFrictionDir1.normalize();
      point.m_lateralFrictionDir2.normalize();
    }
    for (int d = 0; d < (two_directions ? 2 : 1); ++d)
    {
      btMultiBodySolverConstraint& row = m_multiBodyFrictionContactConstraints.expandNonInitializing();
      start(row, point);
      row.m_frictionIndex = normal_index;
      const btScalar slip = surfaces ? (d == 0 ? surfaces[j].slip1 : surfaces[j].slip2) : 0;
      setupContactRow(m_multiBodyFrictionContactConstraints, m_multiBodyFrictionContactConstraints.size() - 1,
                      d == 0 ? point.m_lateralFrictionDir1 : point.m_lateralFrictionDir2, point, info, true, slip);
      if (surfaces && d == 1)
        setFriction(m_multiBodyFrictionContactConstraints[m_multiBodyFrictionContactConstraints.size() - 1],
                    surfaces[j].mu2);
    }
    if (two_directions && (info.m_solverMode & SOLVER_DISABLE_VELOCITY_DEPENDENT_FRICTION_DIRECTION))
      point.m_contactPointFlags |= BT_CONTACT_FLAG_LATERAL_FRICTION_INITIALIZED;
  }
}

// Bullet's convertMultiBodyContact (a multibody against another) along the points' own friction
// directions, the second direction's rows with the points' mu2: Bullet's sets each point's
// directions from its normal (btPlaneSpace1) before it reads them, whatever its solver mode. Its
// rolling and spinning friction rows are left to it (the plant gives no object either).
void DenseRowSolver::convertMultiBodyContactWithSurfaces(btPersistentManifold& manifold,
                                                         const btContactSolverInfo& info,
                                                         const PointSurface* surfaces)
{
  for (int j = 0; j < manifold.getNumContacts(); ++j)
  {
    const btManifoldPoint& point = manifold.getContactPoint(j);
    if (point.m_combinedRollingFriction > 0 || point.m_combinedSpinningFriction > 0)
    {
      convertMultiBodyContact(&manifold, info);
      return;
    }
  }
  auto* object_a = const_cast<btCollisionObject*>(manifold.getBody0());
  auto* object_b = const_cast<btCollisionObject*>(manifold.getBody1());
  const auto* collider_a = btMultiBodyLinkCollider::upcast(object_a);
  const auto* collider_b = btMultiBodyLinkCollider::upcast(object_b);
  const int solver_body_a = collider_a ? -1 : getOrInitSolverBody(*object_a, info.m_timeStep);
  const int solver_body_b = collider_b ? -1 : getOrInitSolverBody(*object_b, info.m_timeStep);
  const bool two_directions = info.m_solverMode & SOLVER_USE_2_FRICTION_DIRECTIONS;
  for (int j = 0; j < manifold.getNumContacts(); ++j)
  {
    btManifoldPoint& point = manifold.getContactPoint(j);
    if (point.getDistance() > manifold.getContactProcessingThreshold())
    {
      point.m_appliedImpulse = 0;
      point.m_prevRHS = 0;
      continue;
    }
    const int normal_index = m_multiBodyNormalContactConstraints.size();
    btMultiBodySolverConstraint& normal = m_multiBodyNormalContactConstraints.expandNonInitializing();
    normal.m_orgConstraint = nullptr;
    normal.m_orgDofIndex = -1;
    normal.m_solverBodyIdA = solver_body_a;
    normal.m_solverBodyIdB = solver_body_b;
    normal.m_multiBodyA = collider_a ? collider_a->m_multiBody : nullptr;
    if (collider_a)
      normal.m_linkA = collider_a->m_link;
    normal.m_multiBodyB = collider_b ? collider_b->m_multiBody : nullptr;
    if (collider_b)
      normal.m_linkB = collider_b->m_link;
    normal.m_originalContactPoint = &point;
    btScalar relaxation;
    setupMultiBodyContactConstraint(normal, point.m_normalWorldOnB, point.m_appliedImpulse, point, info, relaxation,
                                    false);
    normal.m_frictionIndex = m_multiBodyFrictionContactConstraints.size();
    setSlip(addMultiBodyFrictionConstraint(point.m_lateralFrictionDir1, point.m_appliedImpulseLateral1, &manifold,
                                           normal_index, point, object_a, object_b, relaxation, info),
            info, surfaces[j].slip1, relaxation);
    if (two_directions)
    {
      btMultiBodySolverConstraint& second =
          addMultiBodyFrictionConstraint(point.m_lateralFrictionDir2, point.m_appliedImpulseLateral2, &manifold,
                                         normal_index, point, object_a, object_b, relaxation, info);
      setFriction(second, surfaces[j].mu2);
      setSlip(second, info, surfaces[j].slip2, relaxation);
    }
  }
}

// A contact between two different multibodies whose states answer, with plain pyramid friction.
bool DenseRowSolver::pairRowsApply(const btPersistentManifold& manifold, const btContactSolverInfo& info)
{
  const auto* a = btMultiBodyLinkCollider::upcast(manifold.getBody0());
  const auto* b = btMultiBodyLinkCollider::upcast(manifold.getBody1());
  if (!a || !b || a->m_multiBody == b->m_multiBody)
    return false;
  for (const btCollisionObject* object : {manifold.getBody0(), manifold.getBody1()})
    if (object->hasAnisotropicFriction(btCollisionObject::CF_ANISOTROPIC_FRICTION |
                                       btCollisionObject::CF_ANISOTROPIC_ROLLING_FRICTION))
      return false;
  if (info.m_solverMode & SOLVER_ENABLE_FRICTION_DIRECTION_CACHING)
    return false;
  for (int j = 0; j < manifold.getNumContacts(); ++j)
  {
    const btManifoldPoint& point = manifold.getContactPoint(j);
    if (point.m_combinedRollingFriction > 0 || point.m_combinedSpinningFriction > 0)
      return false;
  }
  return bodySlot(a->m_multiBody) >= 0 && bodySlot(b->m_multiBody) >= 0;
}

btScalar DenseRowSolver::finishPairRow(btMultiBodySolverConstraint& row, const btManifoldPoint& point,
                                      const btContactSolverInfo& info, bool friction, const btVector3& direction,
                                      btScalar relative_velocity, btScalar erp)
{
  row.m_friction = point.m_combinedFriction;

  btScalar distance = 0, restitution = 0;
  if (!friction)
  {
    distance = point.getDistance() + info.m_linearSlop;
    restitution = std::max(restitutionCurve(relative_velocity, point.m_combinedRestitution,
                                            info.m_restitutionVelocityThreshold),
                           btScalar(0));
  }
  else if (point.m_contactPointFlags & BT_CONTACT_FLAG_FRICTION_ANCHOR)
  {
    distance = (point.getPositionWorldOnA() - point.getPositionWorldOnB()).dot(direction);
  }
  btScalar positional_error = 0, velocity_error = restitution - relative_velocity;
  if (!friction && distance > 0)
    velocity_error -= distance / info.m_timeStep;
  else
    positional_error = -distance * erp / info.m_timeStep;
  row.m_rhsPenetration = 0;
  row.m_lowerLimit = friction ? -row.m_friction : btScalar(0);
  row.m_upperLimit = friction ? row.m_friction : btScalar(1e10);
  row.m_appliedImpulse = 0;
  row.m_appliedPushImpulse = 0;
  return positional_error + velocity_error;
}

void DenseRowSolver::setupPairRow(btMultiBodyConstraintArray& rows, int index, const btVector3& direction,
                                  btManifoldPoint& point, const btContactSolverInfo& info, bool friction, btScalar slip,
                                  int slot_a, int slot_b)
{
  btMultiBodySolverConstraint& row = rows[index];
  btScalar cfm = friction ? frictionCfm(info, slip) : info.m_globalCfm;
  btScalar erp = friction ? info.m_frictionERP : info.m_erp2;
  if (!friction)
    normalRowSoftness(point, info, erp, cfm);
  cfm *= btScalar(1) / info.m_timeStep;

  // Side A moves along the direction, side B against it; each J from its multibody's state.
  btScalar relative_velocity = 0;
  btVector3 arms[2];
  for (int side = 0; side < 2; ++side)
  {
    btMultiBody* body = side == 0 ? row.m_multiBodyA : row.m_multiBodyB;
    const int link = side == 0 ? row.m_linkA : row.m_linkB;
    const btVector3& position = side == 0 ? point.getPositionWorldOnA() : point.getPositionWorldOnB();
    const int n = body->getNumDofs() + 6;
    int& velocity_index = side == 0 ? row.m_deltaVelAindex : row.m_deltaVelBindex;
    velocity_index = body->getCompanionId();
    if (velocity_index < 0)
    {
      velocity_index = m_data.m_deltaVelocities.size();
      body->setCompanionId(velocity_index);
      m_data.m_deltaVelocities.resize(m_data.m_deltaVelocities.size() + n);
    }
    int& jacobian_index = side == 0 ? row.m_jacAindex : row.m_jacBindex;
    jacobian_index = m_data.m_jacobians.size();
    m_data.m_jacobians.resizeNoInitialize(m_data.m_jacobians.size() + n);
    m_data.m_deltaVelocitiesUnitImpulse.resizeNoInitialize(m_data.m_deltaVelocitiesUnitImpulse.size() + n);
    btScalar* jacobian = &m_data.m_jacobians[jacobian_index];
    contactJacobianRow(*body_rows_[side == 0 ? slot_a : slot_b].state, link, position,
                       side == 0 ? direction : -direction, jacobian);
    const btVector3 origin = link < 0 ? body->getBasePos() : body->getLink(link).m_cachedWorldTransform.getOrigin();
    arms[side] = position - origin;
    const btScalar* velocity = body->getVelocityVector();
    for (int i = 0; i < n; ++i)
      relative_velocity += velocity[i] * jacobian[i];
  }
  row.m_relpos1CrossNormal = arms[0].cross(direction);
  row.m_contactNormal1 = direction;
  row.m_relpos2CrossNormal = -arms[1].cross(direction);
  row.m_contactNormal2 = -direction;
  row.m_angularComponentA.setZero();
  row.m_angularComponentB.setZero();
  const btScalar velocity_error_all = finishPairRow(row, point, info, friction, direction, relative_velocity, erp);
  // A free body's side is answered now; the others wait for their multibody's other rows.
  const int slots[2] = {slot_a, slot_b};
  const int jacobians[2] = {row.m_jacAindex, row.m_jacBindex};
  btScalar diagonal[2] = {0, 0};
  for (int side = 0; side < 2; ++side)
    if (body_rows_[slots[side]].free)
      diagonal[side] = freeResponse(body_rows_[slots[side]], &m_data.m_jacobians[jacobians[side]],
                                    &m_data.m_deltaVelocitiesUnitImpulse[jacobians[side]]);
  if (body_rows_[slot_a].free && body_rows_[slot_b].free)
    scaleRow(row, diagonal[0] + diagonal[1] + cfm, velocity_error_all, cfm, info.m_sor);
  else if (body_rows_[slot_a].free || body_rows_[slot_b].free)
  {
    const int side = body_rows_[slot_a].free ? 1 : 0;
    deferSide(rows, index, slots[side], jacobians[side], velocity_error_all, cfm, info.m_sor, diagonal[1 - side]);
    body_rows_[slots[side]].pair_rows = true;
  }
  else
    deferPairResponse(rows, index, slot_a, slot_b, velocity_error_all, cfm, info.m_sor);
}

void DenseRowSolver::setupFreePairRow(btMultiBodyConstraintArray& rows, int index, const btVector3& direction,
                                      btManifoldPoint& point, const btContactSolverInfo& info, bool friction,
                                      btScalar slip, const FreeSide (&sides)[2])
{
  btMultiBodySolverConstraint& row = rows[index];
  btScalar cfm = friction ? frictionCfm(info, slip) : info.m_globalCfm;
  btScalar erp = friction ? info.m_frictionERP : info.m_erp2;
  if (!friction)
    normalRowSoftness(point, info, erp, cfm);
  cfm *= btScalar(1) / info.m_timeStep;

  // J = (arm x d, d) for side A, (arm x -d, -d) for side B: what contactJacobianRow gives a free body.
  const int first = m_data.m_jacobians.size();
  m_data.m_jacobians.resizeNoInitialize(first + 12);
  m_data.m_deltaVelocitiesUnitImpulse.resizeNoInitialize(first + 12);
  btScalar relative_velocity = 0, denominator = cfm;
  btVector3 angular[2];
  for (int side = 0; side < 2; ++side)
  {
    const FreeSide& free = sides[side];
    const btVector3 linear = side == 0 ? direction : -direction;
    angular[side] = free.arm.cross(linear);
    int& velocity_index = side == 0 ? row.m_deltaVelAindex : row.m_deltaVelBindex;
    velocity_index = free.body->getCompanionId();
    if (velocity_index < 0)
    {
      velocity_index = m_data.m_deltaVelocities.size();
      free.body->setCompanionId(velocity_index);
      m_data.m_deltaVelocities.resize(m_data.m_deltaVelocities.size() + 6);
    }
    (side == 0 ? row.m_jacAindex : row.m_jacBindex) = first + 6 * side;
    btScalar* jacobian = &m_data.m_jacobians[first + 6 * side];
    btScalar* response = &m_data.m_deltaVelocitiesUnitImpulse[first + 6 * side];
    const btScalar* I = free.slot->inverse_inertia;
    for (int a = 0; a < 3; ++a)
    {
      jacobian[a] = angular[side][a];
      jacobian[3 + a] = linear[a];
      response[a] = I[3 * a] * angular[side][0] + I[3 * a + 1] * angular[side][1] + I[3 * a + 2] * angular[side][2];
      response[3 + a] = linear[a] * free.slot->inverse_mass;
    }
    const btScalar* velocity = free.body->getVelocityVector();
    for (int i = 0; i < 6; ++i)
    {
      denominator += jacobian[i] * response[i];
      relative_velocity += velocity[i] * jacobian[i];
    }
  }
  row.m_relpos1CrossNormal = angular[0];
  row.m_contactNormal1 = direction;
  row.m_relpos2CrossNormal = angular[1];
  row.m_contactNormal2 = -direction;
  row.m_angularComponentA.setZero();
  row.m_angularComponentB.setZero();
  scaleRow(row, denominator, finishPairRow(row, point, info, friction, direction, relative_velocity, erp), cfm,
           info.m_sor);
}

void DenseRowSolver::convertPairContact(btPersistentManifold& manifold, const btContactSolverInfo& info,
                                        const PointSurface* surfaces)
{
  const auto* collider_a = btMultiBodyLinkCollider::upcast(manifold.getBody0());
  const auto* collider_b = btMultiBodyLinkCollider::upcast(manifold.getBody1());
  const int slot_a = bodySlot(collider_a->m_multiBody);
  const int slot_b = bodySlot(collider_b->m_multiBody);
  auto start = [&](btMultiBodySolverConstraint& row, btManifoldPoint& point) {
    row.m_orgConstraint = nullptr;
    row.m_orgDofIndex = -1;
    row.m_solverBodyIdA = -1;
    row.m_solverBodyIdB = -1;
    row.m_multiBodyA = collider_a->m_multiBody;
    row.m_multiBodyB = collider_b->m_multiBody;
    row.m_linkA = collider_a->m_link;
    row.m_linkB = collider_b->m_link;
    row.m_originalContactPoint = &point;
  };
  const bool two_directions = info.m_solverMode & SOLVER_USE_2_FRICTION_DIRECTIONS;
  // Free bodies have no links: their points' lever arms are from the base.
  const bool free_pair = body_rows_[slot_a].free && body_rows_[slot_b].free;
  for (int j = 0; j < manifold.getNumContacts(); ++j)
  {
    btManifoldPoint& point = manifold.getContactPoint(j);
    if (point.getDistance() > manifold.getContactProcessingThreshold())
    {
      point.m_appliedImpulse = 0;
      point.m_prevRHS = 0;
      continue;
    }
    const int normal_index = m_multiBodyNormalContactConstraints.size();
    btMultiBodySolverConstraint& normal = m_multiBodyNormalContactConstraints.expandNonInitializing();
    start(normal, point);
    normal.m_frictionIndex = m_multiBodyFrictionContactConstraints.size();
    const FreeSide sides[2] = {
        {&body_rows_[slot_a], collider_a->m_multiBody, point.getPositionWorldOnA() - collider_a->m_multiBody->getBasePos()},
        {&body_rows_[slot_b], collider_b->m_multiBody, point.getPositionWorldOnB() - collider_b->m_multiBody->getBasePos()}};
    if (free_pair)
      setupFreePairRow(m_multiBodyNormalContactConstraints, normal_index, point.m_normalWorldOnB, point, info, false,
                       0, sides);
    else
      setupPairRow(m_multiBodyNormalContactConstraints, normal_index, point.m_normalWorldOnB, point, info, false, 0,
                   slot_a, slot_b);

    if (!surfaces)  // with surfaces, ContactSurfaces::apply has set the point's directions
    {
      btPlaneSpace1(point.m_normalWorldOnB, point.m_lateralFrictionDir1, point.m_lateralFrictionDir2);
      point.m_lateralFrictionDir1.normalize();
      point.m_lateralFrictionDir2.normalize();
    }
    for (int d = 0; d < (two_directions ? 2 : 1); ++d)
    {
      btMultiBodySolverConstraint& row = m_multiBodyFrictionContactConstraints.expandNonInitializing();
      start(row, point);
      row.m_frictionIndex = normal_index;
      const btVector3& direction = d == 0 ? point.m_lateralFrictionDir1 : point.m_lateralFrictionDir2;
      const int index = m_multiBodyFrictionContactConstraints.size() - 1;
      const btScalar slip = surfaces ? (d == 0 ? surfaces[j].slip1 : surfaces[j].slip2) : 0;
      if (free_pair)
        setupFreePairRow(m_multiBodyFrictionContactConstraints, index, direction, point, info, true, slip, sides);
      else
        setupPairRow(m_multiBodyFrictionContactConstraints, index, direction, point, info, true, slip, slot_a, slot_b);
      if (surfaces && d == 1)
        setFriction(m_multiBodyFrictionContactConstraints[index], surfaces[j].mu2);
    }
    if (two_directions && (info.m_solverMode & SOLVER_DISABLE_VELOCITY_DEPENDENT_FRICTION_DIRECTION))
      point.m_contactPointFlags |= BT_CONTACT_FLAG_LATERAL_FRICTION_INITIALIZED;
  }
}

void DenseRowSolver::reserveRowData(btPersistentManifold** manifolds, int numManifolds, const btContactSolverInfo& info)
{
  auto dofs = [](const btCollisionObject* object) {
    const btMultiBodyLinkCollider* collider = btMultiBodyLinkCollider::upcast(object);
    return collider ? collider->m_multiBody->getNumDofs() + 6 : 0;
  };
  const int rows_per_point = (info.m_solverMode & SOLVER_USE_2_FRICTION_DIRECTIONS) ? 3 : 2;
  int entries = m_data.m_jacobians.size();
  for (int i = 0; i < numManifolds; ++i)
    entries += manifolds[i]->getNumContacts() * rows_per_point *
               (dofs(manifolds[i]->getBody0()) + dofs(manifolds[i]->getBody1()));
  if (m_data.m_jacobians.capacity() < entries)
  {
    m_data.m_jacobians.reserve(entries + entries / 2);
    m_data.m_deltaVelocitiesUnitImpulse.reserve(entries + entries / 2);
  }
}

void DenseRowSolver::convertContacts(btPersistentManifold** manifolds, int numManifolds, const btContactSolverInfo& info)
{
  auto multiBody = [](const btCollisionObject* object) {
    const btMultiBodyLinkCollider* collider = btMultiBodyLinkCollider::upcast(object);
    return collider ? collider->m_multiBody : nullptr;
  };
  // The points' surfaces first: their stiffness and min_depth change what the cap below sees.
  const bool any_surfaces = !surfaces_.empty();
  if (any_surfaces)
  {
    point_surfaces_.clear();
    manifold_surfaces_.assign(size_t(numManifolds), -1);
    for (int i = 0; i < numManifolds; ++i)
    {
      const size_t offset = point_surfaces_.size();
      point_surfaces_.resize(offset + size_t(manifolds[i]->getNumContacts()));
      if (surfaces_.apply(*manifolds[i], point_surfaces_.data() + offset))
        manifold_surfaces_[size_t(i)] = int(offset);
      else
        point_surfaces_.resize(offset);
    }
  }
  auto surfacesOf = [&](int i) -> const PointSurface* {
    return any_surfaces && manifold_surfaces_[size_t(i)] >= 0 ? &point_surfaces_[size_t(manifold_surfaces_[size_t(i)])]
                                                              : nullptr;
  };
  for (int i = 0; i < numManifolds; ++i)
    limitCorrectingVelocity(*manifolds[i], info, surfacesOf(i));
  // Bullet's articulated warm starting moves velocities while it builds rows: left to Bullet.
  if (info.m_solverMode & SOLVER_USE_ARTICULATED_WARMSTARTING)
  {
    if (states_)
      states_->needArticulatedPasses();
    btMultiBodyConstraintSolver::convertContacts(manifolds, numManifolds, info);
    return;
  }
  for (size_t k = 0; k < bodies_used_; ++k)  // the last solve's slots (numbered as they were then)
    slot_of_[body_rows_[k].number] = -1;
  slot_of_.resize(states_ ? states_->multibodyCount() : 0, -1);
  bodies_used_ = 0;
  deferred_.clear();
  reserveRowData(manifolds, numManifolds, info);
  for (int i = 0; i < numManifolds; ++i)
  {
    btPersistentManifold* manifold = manifolds[i];
    if (manifold->getNumContacts() == 0)  // no rows in any of the forms below (a pile has hundreds)
      continue;
    btMultiBody* a = multiBody(manifold->getBody0());
    btMultiBody* b = multiBody(manifold->getBody1());
    const PointSurface* surfaces = surfacesOf(i);
    if (!a && !b)
      convertContact(manifold, info);
    else if (contactRowsApply(*manifold, info))
      convertStaticContact(*manifold, info, surfaces);
    else if (a && b && pairRowsApply(*manifold, info))
      convertPairContact(*manifold, info, surfaces);
    else
    {
      needArticulatedPass(a);
      needArticulatedPass(b);
      if (surfaces)
        convertMultiBodyContactWithSurfaces(*manifold, info, surfaces);
      else
        convertMultiBodyContact(manifold, info);
    }
  }
  m_data.m_solverBodyPool = &m_tmpSolverBodyPool;
  m_data.m_fixedBodyId = m_fixedBodyId;
  for (int i = 0; i < m_tmpNumMultiBodyConstraints; ++i)
  {
    btMultiBodyConstraint* constraint = m_tmpMultiBodyConstraints[i];
    auto* drive = dynamic_cast<JointDrive*>(constraint);
    const int slot = drive ? bodySlot(drive->getMultiBodyA()) : -1;
    if (slot < 0)
    {
      needArticulatedPass(constraint->getMultiBodyA());
      needArticulatedPass(constraint->getMultiBodyB());
      constraint->createConstraintRows(m_multiBodyNonContactConstraints, m_data, info);
      continue;
    }
    btScalar velocity_error = 0, cfm = 0;
    const int index = drive->createRowWithoutResponse(m_multiBodyNonContactConstraints, m_data, velocity_error, cfm);
    if (index >= 0)
      deferResponse(m_multiBodyNonContactConstraints, index, slot, velocity_error, cfm, 1);
  }
  finishDeferredRows();
  for (int i = 0; i < m_multiBodyNonContactConstraints.size(); ++i)
    m_multiBodyNonContactConstraints[i].m_appliedImpulse = 0;
}

bool DenseRowSolver::denseApplies(const btContactSolverInfo& info) const
{
  // Rigid-body rows, and cone friction (rows solved in pairs), are left to Bullet.
  if (m_tmpSolverContactConstraintPool.size() || m_tmpSolverNonContactConstraintPool.size() ||
      m_tmpSolverContactFrictionConstraintPool.size() || m_tmpSolverContactRollingFrictionConstraintPool.size())
    return false;
  if ((info.m_solverMode & SOLVER_USE_2_FRICTION_DIRECTIONS) && !(info.m_solverMode & SOLVER_DISABLE_IMPLICIT_CONE_FRICTION))
    return false;
  const btMultiBodyConstraintArray* arrays[] = {&m_multiBodyNonContactConstraints, &m_multiBodyNormalContactConstraints,
                                                &m_multiBodyFrictionContactConstraints};
  for (const btMultiBodyConstraintArray* rows : arrays)
    for (int k = 0; k < rows->size(); ++k)
    {
      const btMultiBodySolverConstraint& c = (*rows)[k];
      if (!c.m_multiBodyA && !c.m_multiBodyB)
        return false;
      // The other side of a row must be something that never moves (the static world).
      for (int id : {c.m_multiBodyA ? -1 : c.m_solverBodyIdA, c.m_multiBodyB ? -1 : c.m_solverBodyIdB})
        if (id >= 0 && m_tmpSolverBodyPool[id].m_originalBody)
          return false;
    }
  return true;
}

void DenseRowSolver::collectRows()
{
  rows_.clear();
  bodies_.clear();
  parent_.clear();
  // A multibody's rows all name the same offset of its degrees of freedom in m_deltaVelocities.
  node_of_.assign(m_data.m_deltaVelocities.size(), -1);
  auto node = [this](btMultiBody* body, int offset) {
    int& k = node_of_[offset];
    if (k < 0)
    {
      k = int(bodies_.size());
      bodies_.push_back(body);
      parent_.push_back(k);
    }
    return k;
  };
  auto root = [this](int k) {
    while (parent_[k] != k)
      k = parent_[k] = parent_[parent_[k]];
    return k;
  };
  btMultiBodyConstraintArray* arrays[] = {&m_multiBodyNonContactConstraints, &m_multiBodyNormalContactConstraints,
                                          &m_multiBodyFrictionContactConstraints};
  for (btMultiBodyConstraintArray* rows : arrays)
    for (int k = 0; k < rows->size(); ++k)
    {
      btMultiBodySolverConstraint& c = (*rows)[k];
      const int a = c.m_multiBodyA ? node(c.m_multiBodyA, c.m_deltaVelAindex) : -1;
      const int b = c.m_multiBodyB ? node(c.m_multiBodyB, c.m_deltaVelBindex) : -1;
      if (a >= 0 && b >= 0)
        parent_[root(a)] = root(b);
      Row row{};
      row.constraint = &c;
      row.group = a >= 0 ? a : b;
      row.deferred = -1;
      rows_.push_back(row);
    }
  // Rows whose responses were computed together know their Delassus entries already.
  const int first_of[3] = {0, m_multiBodyNonContactConstraints.size(),
                           m_multiBodyNonContactConstraints.size() + m_multiBodyNormalContactConstraints.size()};
  for (size_t d = 0; d < deferred_.size(); ++d)
    for (int a = 0; a < 3; ++a)
      if (deferred_[d].rows == arrays[a] && deferred_[d].partner != -2)
        rows_[first_of[a] + deferred_[d].index].deferred = int(d);

  // Groups are the union-find roots, numbered in order of first appearance.
  std::vector<int> group_of_root(bodies_.size(), -1);
  groups_.clear();
  for (Row& row : rows_)
  {
    int& group = group_of_root[root(row.group)];
    if (group < 0)
    {
      group = int(groups_.size());
      groups_.emplace_back();
    }
    row.group = group;
    row.local = groups_[group].size++;
  }
  for (size_t k = 0; k < bodies_.size(); ++k)
    if (bodies_[k]->getNumDofs() > 0)
      groups_[group_of_root[root(int(k))]].articulated = true;
}

void DenseRowSolver::buildBlocks()
{
  // Each group's block and velocities are padded to a multiple of kLanes rows (zeros), so a
  // visit's update is whole Lanes.
  // A group too large for a block keeps none (stride 0) and is iterated in Bullet's sparse form.
  int offset = 0, block = 0;
  any_sparse_ = false;
  for (Group& g : groups_)
  {
    g.dense = g.size <= (g.articulated ? kMaxDenseRows : kMaxDenseFreeRows);
    any_sparse_ |= !g.dense;
    g.offset = offset;
    g.block = block;
    g.stride = g.dense ? (g.size + kLanes - 1) / kLanes * kLanes : 0;
    offset += g.dense ? g.stride : g.size;
    block += g.stride * g.stride;
  }
  delassus_.assign(block, 0);
  row_velocity_.assign(offset, 0);
  members_.resize(offset);
  for (size_t k = 0; k < rows_.size(); ++k)
    members_[groups_[rows_[k].group].offset + rows_[k].local] = int(k);
  if (any_sparse_)
  {
    // Each multibody's degrees of freedom padded to whole Lanes, starting from where Bullet's
    // setup may already have moved the velocities (warm starting).
    packed_offset_.resize(bodies_.size());
    int size = 0;
    for (size_t k = 0; k < bodies_.size(); ++k)
    {
      packed_offset_[k] = size;
      size += (degreesOfFreedom(bodies_[k]) + kLanes - 1) / kLanes * kLanes;
    }
    dof_velocity_.assign(size, 0);
    for (size_t k = 0; k < bodies_.size(); ++k)
    {
      const int first = bodies_[k]->getCompanionId();
      for (int i = 0, n = degreesOfFreedom(bodies_[k]); i < n; ++i)
        dof_velocity_[packed_offset_[k] + i] = m_data.m_deltaVelocities[first + i];
    }
  }
  size_t sparse_size = 0;

  for (Row& row : rows_)
  {
    const Group& g = groups_[row.group];
    const btMultiBodySolverConstraint& c = *row.constraint;
    row.sparse = !g.dense;
    if (row.sparse)
    {
      row.velocity = row.column = -1;
      row.stride = 0;
      // Its sides' J and M^-1 J^T go to sparse_data_ (below, once its size is known).
      for (const btMultiBody* body : {c.m_multiBodyA, c.m_multiBodyB})
        if (body)
          sparse_size += 2 * size_t((degreesOfFreedom(body) + kLanes - 1) / kLanes * kLanes);
      continue;
    }
    row.velocity = g.offset;
    row.column = g.block + row.local * g.stride;
    row.stride = g.stride;
    // Bullet's setup may already have moved the velocities (warm starting): start from there.
    btScalar velocity = 0;
    if (c.m_multiBodyA)
      velocity += dot(&m_data.m_jacobians[c.m_jacAindex], &m_data.m_deltaVelocities[c.m_deltaVelAindex],
                      degreesOfFreedom(c.m_multiBodyA));
    if (c.m_multiBodyB)
      velocity += dot(&m_data.m_jacobians[c.m_jacBindex], &m_data.m_deltaVelocities[c.m_deltaVelBindex],
                      degreesOfFreedom(c.m_multiBodyB));
    row_velocity_[g.offset + row.local] = velocity;

    btScalar* matrix = &delassus_[g.block];
    const int* members = &members_[g.offset];
    // Rows of one multibody whose responses were computed together: their entry is in its gram.
    const DeferredRow* deferred = row.deferred >= 0 ? &deferred_[row.deferred] : nullptr;
    const btScalar* gram = deferred && body_rows_[deferred->body].has_gram
                               ? &body_rows_[deferred->body].gram[size_t(deferred->position) *
                                                                  body_rows_[deferred->body].stride]
                               : nullptr;
    for (int other = 0; other <= row.local; ++other)
    {
      const Row& o = rows_[members[other]];
      const DeferredRow* od = o.deferred >= 0 ? &deferred_[o.deferred] : nullptr;
      const btScalar a = gram && od && od->body == deferred->body ? gram[od->position]
                                                                  : response(c, *o.constraint, m_data);
      matrix[row.local * g.stride + other] = a;
      matrix[other * g.stride + row.local] = a;
    }
  }
  if (!any_sparse_)
    return;
  // The sparse rows' J and M^-1 J^T, padded with zeros as their multibodies' velocities.
  sparse_data_.assign(sparse_size, btScalar(0));
  body_sparse_.assign(bodies_.size(), 0);
  std::fill(std::begin(sparse_zero_dof_), std::end(sparse_zero_dof_), btScalar(0));
  std::fill(std::begin(sparse_zero_data_), std::end(sparse_zero_data_), btScalar(0));
  btScalar* data = sparse_data_.data();
  for (Row& row : rows_)
  {
    if (!row.sparse)
      continue;
    const btMultiBodySolverConstraint& c = *row.constraint;
    const btMultiBody* bodies[2] = {c.m_multiBodyA, c.m_multiBodyB};
    const int jacobians[2] = {c.m_jacAindex, c.m_jacBindex};
    const int velocities[2] = {c.m_deltaVelAindex, c.m_deltaVelBindex};
    for (int side = 0; side < 2; ++side)
    {
      row.lanes[side] = 0;
      row.dof[side] = nullptr;
      row.jacobian[side] = nullptr;
      if (!bodies[side])
        continue;
      const int n = degreesOfFreedom(bodies[side]);
      const int lanes = (n + kLanes - 1) / kLanes;
      const int node = node_of_[velocities[side]];
      body_sparse_[node] = 1;
      row.lanes[side] = lanes;
      row.dof[side] = &dof_velocity_[packed_offset_[node]];
      row.jacobian[side] = data;
      const btScalar* jacobian = &m_data.m_jacobians[jacobians[side]];
      const btScalar* response = &m_data.m_deltaVelocitiesUnitImpulse[jacobians[side]];
      if (n == 6)  // a free body: copies of a known size
      {
        std::copy_n(jacobian, 6, data);
        std::copy_n(response, 6, data + 2 * kLanes);
      }
      else
      {
        std::copy_n(jacobian, n, data);
        std::copy_n(response, n, data + lanes * kLanes);
      }
      data += 2 * lanes * kLanes;
    }
    row.two_lanes = row.lanes[0] <= 2 && row.lanes[1] <= 2;
    for (int side = 0; row.two_lanes && side < 2; ++side)
      if (!row.lanes[side])
      {
        row.lanes[side] = 2;
        row.dof[side] = sparse_zero_dof_;
        row.jacobian[side] = sparse_zero_data_;
      }
  }
}

btScalar DenseRowSolver::delassusEntry(int i, int j) const
{
  const Row& a = rows_.at(i);
  const Row& b = rows_.at(j);
  if (a.group != b.group)
    return 0;
  return a.sparse ? response(*a.constraint, *b.constraint, m_data) : delassus_[a.column + b.local];
}

void DenseRowSolver::loadRows()
{
  const int non_contact = m_multiBodyNonContactConstraints.size();
  const int normal = m_multiBodyNormalContactConstraints.size();
  for (size_t k = 0; k < rows_.size(); ++k)
  {
    Row& row = rows_[k];
    const btMultiBodySolverConstraint& c = *row.constraint;
    row.rhs = c.m_rhs;
    row.cfm = c.m_cfm;
    row.inverse_mass = c.m_jacDiagABInv;
    row.mass = c.m_jacDiagABInv != 0 ? 1 / c.m_jacDiagABInv : btScalar(0);
    row.lower = c.m_lowerLimit;
    row.upper = c.m_upperLimit;
    row.friction = c.m_friction;
    row.impulse = row.start_impulse = c.m_appliedImpulse;
    row.normal = int(k) >= non_contact + normal ? non_contact + c.m_frictionIndex : -1;
  }
}

void DenseRowSolver::storeRows()
{
  for (const Row& row : rows_)
  {
    btMultiBodySolverConstraint& c = *row.constraint;
    c.m_appliedImpulse = row.impulse;
    c.m_lowerLimit = row.lower;
    c.m_upperLimit = row.upper;
  }
}

void DenseRowSolver::startAt(Row& row, btScalar impulse)
{
  if (row.impulse != 0 || impulse == 0 || !std::isfinite(impulse))  // started by Bullet, or nothing to start from
    return;
  row.impulse = std::min(std::max(impulse, row.lower), row.upper);
  if (row.sparse)
    addToDofVelocities(row, row.impulse);
  else
    addToVelocities(row, row.impulse);
}

void DenseRowSolver::warmStart(const btContactSolverInfo& info)
{
  if (!(info.m_solverMode & SOLVER_USE_WARMSTARTING))
    return;
  const btScalar factor = info.m_warmstartingFactor;
  const int non_contact = m_multiBodyNonContactConstraints.size();
  const int normal = m_multiBodyNormalContactConstraints.size();
  for (int j = 0; j < non_contact; ++j)
  {
    const btMultiBodySolverConstraint& c = *rows_[j].constraint;
    if (c.m_orgConstraint)
      startAt(rows_[j], factor * c.m_orgConstraint->getAppliedImpulse(c.m_orgDofIndex));
  }
  // Friction rows follow their contact's normal row, one or two each (more when Bullet adds
  // rolling friction rows to the same array: then friction starts cold).
  const int per_contact = (info.m_solverMode & SOLVER_USE_2_FRICTION_DIRECTIONS) ? 2 : 1;
  const bool friction_paired = m_multiBodyFrictionContactConstraints.size() == per_contact * normal;
  for (int j = 0; j < normal; ++j)
  {
    Row& row = rows_[non_contact + j];
    const auto* point = static_cast<const btManifoldPoint*>(row.constraint->m_originalContactPoint);
    if (!point)
      continue;
    startAt(row, factor * point->m_appliedImpulse);
    if (!friction_paired)
      continue;
    const btScalar lateral[2] = {point->m_appliedImpulseLateral1, point->m_appliedImpulseLateral2};
    for (int d = 0; d < per_contact; ++d)
    {
      Row& friction = rows_[non_contact + normal + row.constraint->m_frictionIndex + d];
      // Within the friction pyramid of the normal impulse just started.
      friction.lower = -friction.friction * row.impulse;
      friction.upper = friction.friction * row.impulse;
      startAt(friction, factor * lateral[d]);
    }
  }
}

// velocities of the row's group += impulse * the row's column of the Delassus block.
inline void DenseRowSolver::addToVelocities(const Row& row, btScalar impulse)
{
  Lanes* velocity = reinterpret_cast<Lanes*>(&row_velocity_[row.velocity]);
  const Lanes* column = reinterpret_cast<const Lanes*>(&delassus_[row.column]);
  const int lanes = row.stride / kLanes;
  for (int q = 0; q < lanes; ++q)
    velocity[q] += impulse * column[q];
}

inline btScalar DenseRowSolver::sparseVelocity(const Row& row)
{
  if (row.two_lanes)
  {
    const Lanes* ja = reinterpret_cast<const Lanes*>(row.jacobian[0]);
    const Lanes* va = reinterpret_cast<const Lanes*>(row.dof[0]);
    const Lanes* jb = reinterpret_cast<const Lanes*>(row.jacobian[1]);
    const Lanes* vb = reinterpret_cast<const Lanes*>(row.dof[1]);
    const Lanes sum = (ja[0] * va[0] + ja[1] * va[1]) + (jb[0] * vb[0] + jb[1] * vb[1]);
    return (sum[0] + sum[1]) + (sum[2] + sum[3]);
  }
  Lanes sum = {};
  for (int side = 0; side < 2; ++side)
  {
    const Lanes* jacobian = reinterpret_cast<const Lanes*>(row.jacobian[side]);
    const Lanes* velocity = reinterpret_cast<const Lanes*>(row.dof[side]);
    if (row.lanes[side] == 2)  // a free body's 6 degrees of freedom
      sum += jacobian[0] * velocity[0] + jacobian[1] * velocity[1];
    else
      for (int q = 0; q < row.lanes[side]; ++q)
        sum += jacobian[q] * velocity[q];
  }
  return (sum[0] + sum[1]) + (sum[2] + sum[3]);
}

inline void DenseRowSolver::addToDofVelocities(const Row& row, btScalar impulse)
{
  if (row.two_lanes)
  {
    const Lanes* ua = reinterpret_cast<const Lanes*>(row.jacobian[0]) + 2;
    Lanes* va = reinterpret_cast<Lanes*>(row.dof[0]);
    const Lanes* ub = reinterpret_cast<const Lanes*>(row.jacobian[1]) + 2;
    Lanes* vb = reinterpret_cast<Lanes*>(row.dof[1]);
    va[0] += ua[0] * impulse;
    va[1] += ua[1] * impulse;
    vb[0] += ub[0] * impulse;
    vb[1] += ub[1] * impulse;
    return;
  }
  for (int side = 0; side < 2; ++side)
  {
    const int lanes = row.lanes[side];
    const Lanes* unit = reinterpret_cast<const Lanes*>(row.jacobian[side]) + lanes;
    Lanes* velocity = reinterpret_cast<Lanes*>(row.dof[side]);
    if (lanes == 2)
    {
      velocity[0] += unit[0] * impulse;
      velocity[1] += unit[1] * impulse;
    }
    else
      for (int q = 0; q < lanes; ++q)
        velocity[q] += unit[q] * impulse;
  }
}

template <bool kSparseRows>
inline btScalar DenseRowSolver::visit(Row& row)
{
  const btScalar applied = row.impulse;
  const btScalar velocity = kSparseRows && row.sparse ? sparseVelocity(row) : row_velocity_[row.velocity + row.local];
  btScalar delta = row.rhs - applied * row.cfm - velocity * row.inverse_mass;
  const btScalar sum = applied + delta;
  if (sum < row.lower)
  {
    delta = row.lower - applied;
    row.impulse = row.lower;
  }
  else if (sum > row.upper)
  {
    delta = row.upper - applied;
    row.impulse = row.upper;
  }
  else
  {
    row.impulse = sum;
  }
  if (delta != 0)
  {
    if (kSparseRows && row.sparse)
      addToDofVelocities(row, delta);
    else
      addToVelocities(row, delta);
  }
  // Bullet's residual is the velocity change; a row Bullet disabled (no effective mass) has none.
  return delta * row.mass;
}

void DenseRowSolver::applyVelocityChanges()
{
  velocity_change_.assign(m_data.m_deltaVelocities.size(), 0);
  for (const Row& row : rows_)
  {
    const btScalar impulse = row.impulse - row.start_impulse;
    if (impulse == 0 || row.sparse)  // a sparse group's bodies have theirs in dof_velocity_
      continue;
    const btMultiBodySolverConstraint& c = *row.constraint;
    if (c.m_multiBodyA)
    {
      const btScalar* unit = &m_data.m_deltaVelocitiesUnitImpulse[c.m_jacAindex];
      for (int k = 0, n = degreesOfFreedom(c.m_multiBodyA); k < n; ++k)
        velocity_change_[c.m_deltaVelAindex + k] += unit[k] * impulse;
    }
    if (c.m_multiBodyB)
    {
      const btScalar* unit = &m_data.m_deltaVelocitiesUnitImpulse[c.m_jacBindex];
      for (int k = 0, n = degreesOfFreedom(c.m_multiBodyB); k < n; ++k)
        velocity_change_[c.m_deltaVelBindex + k] += unit[k] * impulse;
    }
  }
  // Bullet (DIRECTLY_UPDATE_VELOCITY_DURING_SOLVER_ITERATIONS) moves both its buffer and the
  // multibody's pending velocity change; its write-back reads neither again.
  for (size_t b = 0; b < bodies_.size(); ++b)
  {
    btMultiBody* body = bodies_[b];
    const int first = body->getCompanionId();
    const int n = degreesOfFreedom(body);
    if (any_sparse_ && body_sparse_[b])
      for (int k = 0; k < n; ++k)
        velocity_change_[first + k] = dof_velocity_[packed_offset_[b] + k] - m_data.m_deltaVelocities[first + k];
    for (int k = 0; k < n; ++k)
      m_data.m_deltaVelocities[first + k] += velocity_change_[first + k];
    body->applyDeltaVeeMultiDof2(&velocity_change_[first], 1);
    body->setPosUpdated(false);
  }
}

template <bool kSparseRows>
void DenseRowSolver::iterate(const btContactSolverInfo& info, btCollisionObject** bodies, int numBodies, int numManifolds)
{
  const int non_contact = m_multiBodyNonContactConstraints.size();
  const int normal = m_multiBodyNormalContactConstraints.size();
  const int friction = m_multiBodyFrictionContactConstraints.size();
  const int max_iterations = std::max(m_maxOverrideNumSolverIterations, info.m_numIterations);
  for (int iteration = 0; iteration < max_iterations; ++iteration)
  {
    // The largest squared velocity change of any row, as Bullet's; of the non-contact rows, that
    // of their last inner pass.
    btScalar residual = 0;
    for (int inner = 0; inner < info.m_numNonContactInnerIterations; ++inner)
    {
      residual = 0;
      for (int j = 0; j < non_contact; ++j)
      {
        // Bullet alternates the direction over these rows from one iteration to the next.
        const btScalar r = visit<kSparseRows>(rows_[(iteration & 1) ? j : non_contact - 1 - j]);
        residual = std::max(residual, r * r);
      }
    }
    if (iteration < info.m_numIterations)
    {
      for (int j = 0; j < normal; ++j)
      {
        const btScalar r = visit<kSparseRows>(rows_[non_contact + j]);
        residual = std::max(residual, r * r);
      }
      for (int j = 0; j < friction; ++j)
      {
        Row& row = rows_[non_contact + normal + j];
        const btScalar normal_impulse = rows_[row.normal].impulse;
        if (normal_impulse > 0)
        {
          row.lower = -row.friction * normal_impulse;
          row.upper = row.friction * normal_impulse;
          const btScalar r = visit<kSparseRows>(row);
          residual = std::max(residual, r * r);
        }
        else if (row.impulse != 0)
        {
          // The contact let go in this pass: so does its friction (ODE's bounds, mu times the
          // normal force, are zero then). Bullet skips the row and keeps the impulse an earlier
          // pass or the warm start gave it: friction with no normal force under it.
          row.lower = row.upper = 0;
          const btScalar r = visit<kSparseRows>(row);
          residual = std::max(residual, r * r);
        }
      }
    }
    m_leastSquaresResidual = residual;
    if (residual <= info.m_leastSquaresResidualThreshold || iteration >= max_iterations - 1)
    {
      m_analyticsData.m_numSolverCalls++;
      m_analyticsData.m_numIterationsUsed = iteration + 1;
      m_analyticsData.m_islandId = numBodies > 0 ? bodies[0]->getCompanionId() : -2;
      m_analyticsData.m_numBodies = numBodies;
      m_analyticsData.m_numContactManifolds = numManifolds;
      m_analyticsData.m_remainingLeastSquaresResidual = m_leastSquaresResidual;
      break;
    }
  }
}

btScalar DenseRowSolver::solveGroupCacheFriendlyIterations(btCollisionObject** bodies, int numBodies,
                                                           btPersistentManifold** manifolds, int numManifolds,
                                                           btTypedConstraint** constraints, int numConstraints,
                                                           const btContactSolverInfo& info, btIDebugDraw* debugDrawer)
{
  if (!denseApplies(info))
    return btMultiBodyConstraintSolver::solveGroupCacheFriendlyIterations(bodies, numBodies, manifolds, numManifolds,
                                                                          constraints, numConstraints, info, debugDrawer);
  collectRows();
  buildBlocks();
  loadRows();
  warmStart(info);

  if (any_sparse_)
    iterate<true>(info, bodies, numBodies, numManifolds);
  else
    iterate<false>(info, bodies, numBodies, numManifolds);
  storeRows();
  applyVelocityChanges();
  return 0;
}

}  // namespace bullet_plant
