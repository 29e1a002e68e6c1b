#include "dense_row_solver.h"

#include <algorithm>

#include <BulletCollision/NarrowPhaseCollision/btManifoldPoint.h>

#include <BulletDynamics/Featherstone/btMultiBody.h>

namespace bullet_plant
{
namespace
{
btScalar dot(const btScalar* a, const btScalar* b, int n)
{
  btScalar sum = 0;
  for (int i = 0; i < n; ++i)
    sum += a[i] * b[i];
  return sum;
}

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
}  // namespace

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
  auto node = [this](btMultiBody* body) {
    for (size_t k = 0; k < bodies_.size(); ++k)
      if (bodies_[k] == body)
        return int(k);
    bodies_.push_back(body);
    parent_.push_back(int(parent_.size()));
    return int(bodies_.size() - 1);
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
      const int a = c.m_multiBodyA ? node(c.m_multiBodyA) : -1;
      const int b = c.m_multiBodyB ? node(c.m_multiBodyB) : -1;
      if (a >= 0 && b >= 0)
        parent_[root(a)] = root(b);
      rows_.push_back(Row{&c, a >= 0 ? a : b, 0});
    }

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
}

void DenseRowSolver::buildBlocks()
{
  int offset = 0, block = 0;
  for (Group& g : groups_)
  {
    g.offset = offset;
    g.block = block;
    offset += g.size;
    block += g.size * g.size;
  }
  delassus_.assign(block, 0);
  row_velocity_.assign(offset, 0);
  impulse_change_.assign(offset, 0);
  members_.resize(offset);
  for (size_t k = 0; k < rows_.size(); ++k)
    members_[groups_[rows_[k].group].offset + rows_[k].local] = int(k);

  for (const Row& row : rows_)
  {
    const Group& g = groups_[row.group];
    const btMultiBodySolverConstraint& c = *row.constraint;
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
    for (int other = 0; other <= row.local; ++other)
    {
      const btScalar a = response(c, *rows_[members[other]].constraint, m_data);
      matrix[row.local * g.size + other] = a;
      matrix[other * g.size + row.local] = a;
    }
  }
}

void DenseRowSolver::startAt(const Row& row, btScalar impulse)
{
  btMultiBodySolverConstraint& c = *row.constraint;
  if (c.m_appliedImpulse != 0 || !(impulse != 0))  // already started by Bullet, or nothing to start from
    return;
  impulse = std::min(std::max(impulse, c.m_lowerLimit), c.m_upperLimit);
  c.m_appliedImpulse = impulse;
  const Group& g = groups_[row.group];
  const btScalar* column = &delassus_[g.block + row.local * g.size];
  btScalar* velocity = &row_velocity_[g.offset];
  for (int k = 0; k < g.size; ++k)
    velocity[k] += column[k] * impulse;
  impulse_change_[g.offset + row.local] += impulse;
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
    btMultiBodySolverConstraint& c = *rows_[j].constraint;
    if (c.m_orgConstraint)
      startAt(rows_[j], factor * c.m_orgConstraint->getAppliedImpulse(c.m_orgDofIndex));
  }
  // Friction rows follow their contact's normal row, one or two each (more when Bullet adds
  // rolling friction rows to the same array: then friction starts cold).
  const int per_contact = (info.m_solverMode & SOLVER_USE_2_FRICTION_DIRECTIONS) ? 2 : 1;
  const bool friction_paired = m_multiBodyFrictionContactConstraints.size() == per_contact * normal;
  for (int j = 0; j < normal; ++j)
  {
    const Row& row = rows_[non_contact + j];
    const auto* point = static_cast<const btManifoldPoint*>(row.constraint->m_originalContactPoint);
    if (!point)
      continue;
    startAt(row, factor * point->m_appliedImpulse);
    if (!friction_paired)
      continue;
    const btScalar normal_impulse = row.constraint->m_appliedImpulse;
    const btScalar lateral[2] = {point->m_appliedImpulseLateral1, point->m_appliedImpulseLateral2};
    for (int d = 0; d < per_contact; ++d)
    {
      const Row& friction = rows_[non_contact + normal + row.constraint->m_frictionIndex + d];
      btMultiBodySolverConstraint& f = *friction.constraint;
      // Within the friction pyramid of the normal impulse just started.
      f.m_lowerLimit = -f.m_friction * normal_impulse;
      f.m_upperLimit = f.m_friction * normal_impulse;
      startAt(friction, factor * lateral[d]);
    }
  }
}

btScalar DenseRowSolver::visit(const Row& row)
{
  btMultiBodySolverConstraint& c = *row.constraint;
  const Group& g = groups_[row.group];
  btScalar* velocity = &row_velocity_[g.offset];
  const btScalar applied = c.m_appliedImpulse;
  btScalar delta = c.m_rhs - applied * c.m_cfm - velocity[row.local] * c.m_jacDiagABInv;
  const btScalar sum = applied + delta;
  if (sum < c.m_lowerLimit)
  {
    delta = c.m_lowerLimit - applied;
    c.m_appliedImpulse = c.m_lowerLimit;
  }
  else if (sum > c.m_upperLimit)
  {
    delta = c.m_upperLimit - applied;
    c.m_appliedImpulse = c.m_upperLimit;
  }
  else
  {
    c.m_appliedImpulse = sum;
  }
  if (delta != 0)
  {
    const btScalar* column = &delassus_[g.block + row.local * g.size];
    for (int k = 0; k < g.size; ++k)
      velocity[k] += column[k] * delta;
    impulse_change_[g.offset + row.local] += delta;
  }
  // Bullet's residual is the velocity change; a row Bullet disabled (no effective mass) has none.
  return c.m_jacDiagABInv != 0 ? delta / c.m_jacDiagABInv : btScalar(0);
}

void DenseRowSolver::applyVelocityChanges()
{
  velocity_change_.assign(m_data.m_deltaVelocities.size(), 0);
  for (const Row& row : rows_)
  {
    const btScalar impulse = impulse_change_[groups_[row.group].offset + row.local];
    if (impulse == 0)
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
  for (btMultiBody* body : bodies_)
  {
    const int first = body->getCompanionId();
    const int n = degreesOfFreedom(body);
    for (int k = 0; k < n; ++k)
      m_data.m_deltaVelocities[first + k] += velocity_change_[first + k];
    body->applyDeltaVeeMultiDof2(&velocity_change_[first], 1);
    body->setPosUpdated(false);
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
  warmStart(info);

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
        const btScalar r = visit(rows_[(iteration & 1) ? j : non_contact - 1 - j]);
        residual = std::max(residual, r * r);
      }
    }
    if (iteration < info.m_numIterations)
    {
      for (int j = 0; j < normal; ++j)
      {
        const btScalar r = visit(rows_[non_contact + j]);
        residual = std::max(residual, r * r);
      }
      for (int j = 0; j < friction; ++j)
      {
        const Row& row = rows_[non_contact + normal + j];
        btMultiBodySolverConstraint& c = *row.constraint;
        const btScalar normal_impulse = m_multiBodyNormalContactConstraints[c.m_frictionIndex].m_appliedImpulse;
        if (normal_impulse > 0)
        {
          c.m_lowerLimit = -c.m_friction * normal_impulse;
          c.m_upperLimit = c.m_friction * normal_impulse;
          const btScalar r = visit(row);
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
  applyVelocityChanges();
  return 0;
}

}  // namespace bullet_plant
