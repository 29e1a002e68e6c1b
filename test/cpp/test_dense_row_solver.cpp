// The dense row solver (physics/dense_row_solver.cpp) on the Tianracer standing on the ground and
// driving (contact rows and JointDrive rows): the rows' batched responses M^-1 J^T and the
// Delassus block A = J M^-1 J^T it iterates on, against J M^-1 J^T from Bullet's own per-row
// responses (calcAccelerationDeltasMultiDof after its articulated-body pass). Float tolerance, as
// in test_multibody_dynamics.cpp: Bullet's responses are float, the solver's come from a double
// factor rounded to float.
#include <gtest/gtest.h>

#include "multibody_fixtures.h"
#include "physics/dense_row_solver.h"
#include "physics/dynamics_world.h"

namespace bullet_plant
{
namespace
{
using namespace test;

// The plant's solver, checking each dense solve against Bullet's responses.
class CheckedSolver : public DenseRowSolver
{
public:
  double worst_response = 0, worst_delassus = 0;
  int rows = 0, contact_rows = 0, pairs = 0;

protected:
  btScalar solveGroupCacheFriendlyIterations(btCollisionObject** bodies, int numBodies,
                                             btPersistentManifold** manifolds, int numManifolds,
                                             btTypedConstraint** constraints, int numConstraints,
                                             const btContactSolverInfo& info, btIDebugDraw* debugDrawer) override
  {
    const btScalar residual = DenseRowSolver::solveGroupCacheFriendlyIterations(
        bodies, numBodies, manifolds, numManifolds, constraints, numConstraints, info, debugDrawer);
    check();
    return residual;
  }

private:
  struct Side
  {
    btMultiBody* body;
    int jacobian;
  };
  // A row's multibody side (the other is the static world here).
  static Side sideOf(const btMultiBodySolverConstraint& row)
  {
    return row.m_multiBodyA ? Side{row.m_multiBodyA, row.m_jacAindex} : Side{row.m_multiBodyB, row.m_jacBindex};
  }

  void check()
  {
    std::vector<const btMultiBodySolverConstraint*> all;
    for (const btMultiBodyConstraintArray* array :
         {&m_multiBodyNonContactConstraints, &m_multiBodyNormalContactConstraints, &m_multiBodyFrictionContactConstraints})
      for (int k = 0; k < array->size(); ++k)
        all.push_back(&(*array)[k]);
    contact_rows += m_multiBodyNormalContactConstraints.size();
    rows += int(all.size());
    // Bullet's response of each row, after Bullet's pass for its multibody.
    std::vector<std::vector<btScalar>> bullet(all.size());
    for (size_t i = 0; i < all.size(); ++i)
    {
      const Side side = sideOf(*all[i]);
      ASSERT_NE(side.body, nullptr);
      const int n = side.body->getNumDofs() + 6;
      articulatedPass(*side.body, scratch_);
      bullet[i].resize(n);
      side.body->calcAccelerationDeltasMultiDof(&m_data.m_jacobians[side.jacobian], bullet[i].data(), scratch_.r,
                                                scratch_.v);
      worst_response = std::max(
          worst_response, relativeDifference(&m_data.m_deltaVelocitiesUnitImpulse[side.jacobian], bullet[i], n));
    }
    double scale = 0, difference = 0;
    for (size_t i = 0; i < all.size(); ++i)
      for (size_t j = 0; j < all.size(); ++j)
      {
        const Side a = sideOf(*all[i]), b = sideOf(*all[j]);
        if (a.body != b.body)
          continue;
        const btScalar expected = dot(&m_data.m_jacobians[a.jacobian], bullet[j].data(), a.body->getNumDofs() + 6);
        scale = std::max(scale, double(std::abs(expected)));
        difference = std::max(difference, double(std::abs(delassusEntry(int(i), int(j)) - expected)));
        ++pairs;
      }
    if (scale > 0)
      worst_delassus = std::max(worst_delassus, difference / scale);
  }

  BulletScratch scratch_;
};

TEST(DenseRowSolver, DelassusBlockIsJMinvJtOfBulletsResponsesOnTheTianracer)
{
  World world;
  Robot& car = world.spawn(tianracerUrdf(), "tianracer", urdf::Pose());
  world.step(200);  // standing on its wheels

  // The world's solver, replaced by the checking one.
  World::Internals& w = *internalsOf(car).world;
  auto* dynamics = static_cast<DynamicsWorld*>(w.dynamics.get());
  auto* checked = new CheckedSolver;
  checked->useStates(dynamics);
  dynamics->setMultiBodyConstraintSolver(checked);
  w.solver.reset(checked);

  // Standing, then driving and steering: JointDrive rows join the contacts.
  world.step(5);
  for (const char* joint : {"left_rear_wheel_joint", "right_rear_wheel_joint"})
    ASSERT_NE(car.handle(joint), nullptr) << joint;
  for (JointHandle& handle : car.handles())
    handle.setCommand(handle.name().find("rear") != std::string::npos ? 20.0 : 0.3);
  world.step(50);

  report("Tianracer rows checked", checked->rows);
  report("Tianracer response relative difference", checked->worst_response);
  report("Tianracer Delassus relative difference", checked->worst_delassus);
  EXPECT_GE(checked->contact_rows, 4 * 55);  // four wheels on the ground every step
  EXPECT_GT(checked->rows, checked->contact_rows * 2);
  EXPECT_GT(checked->pairs, checked->rows);
  EXPECT_LT(checked->worst_response, 1e-4);
  EXPECT_LT(checked->worst_delassus, 1e-4);
}

}  // namespace
}  // namespace bullet_plant
