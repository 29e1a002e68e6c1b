// The joint-space algorithms (physics/multibody_dynamics.cpp) against Bullet's articulated-body
// pass on random chains (free and fixed base, with and without spherical joints), free bodies (no
// links) and on the Tianracer spawned through the plant.
//
// Tolerances: Bullet computes in float (btScalar), the algorithms here in double from the same
// float inputs, so the two differ by Bullet's rounding, which the articulated-body pass amplifies
// by the conditioning of the multibody (masses and inertias over two orders of magnitude in the
// chains; wheels of 4e-5 kg m^2 on a 2 kg chassis in the car). Measured differences are printed;
// the bound, 1e-4 of the largest entry, is float's 6e-8 times a conditioning allowance of ~1000.
// A wrong term (a sign, a missing cross product, a wrong frame) shows as 1e-2 or more.
#include <gtest/gtest.h>

#include "multibody_fixtures.h"
#include "physics/multibody_dynamics.h"

namespace bullet_plant
{
namespace
{
using namespace test;

constexpr double kFloatBound = 1e-4;

// forwardDynamics against Bullet's pass (which adds qdd * dt to the velocities: dt = 1).
double forwardDynamicsDifference(btMultiBody& body)
{
  updateKinematics(body);
  MultibodyState state;
  EXPECT_TRUE(buildMultibodyState(body, state));
  const int n = body.getNumDofs() + 6;
  std::vector<btScalar> ours(n), before(body.getVelocityVector(), body.getVelocityVector() + n), bullet(n);
  forwardDynamics(body, state, ours.data());
  BulletScratch scratch;
  body.computeAccelerationsArticulatedBodyAlgorithmMultiDof(1, scratch.r, scratch.v, scratch.m, false, false, false);
  for (int i = 0; i < n; ++i)
    bullet[i] = body.getVelocityVector()[i] - before[i];
  for (int i = 0; i < n; ++i)  // back to where it was
    const_cast<btScalar*>(body.getVelocityVector())[i] = before[i];
  return relativeDifference(ours, bullet, n, state.first);
}

// solveInertia (M^-1 e_k, column by column) against Bullet's response to unit generalized
// impulses after its pass; solveInertiaColumns (float, with the Gram block) against Bullet's
// responses to random Jacobian rows.
void expectInverseInertiaMatchesBullet(btMultiBody& body, std::mt19937& rng, const std::string& name)
{
  updateKinematics(body);
  MultibodyState state;
  ASSERT_TRUE(buildMultibodyState(body, state));
  BulletScratch scratch;
  articulatedPass(body, scratch);
  const int n = state.n;
  double worst = 0;
  std::vector<double> ours(n);
  std::vector<btScalar> unit(n), bullet(n);
  for (int k = state.first; k < n; ++k)
  {
    std::fill(ours.begin(), ours.end(), 0.0);
    std::fill(unit.begin(), unit.end(), btScalar(0));
    ours[k] = unit[k] = 1;
    solveInertia(state, ours.data());
    body.calcAccelerationDeltasMultiDof(unit.data(), bullet.data(), scratch.r, scratch.v);
    worst = std::max(worst, relativeDifference(ours, bullet, n, state.first));
  }
  report(name + " M^-1 relative difference", worst);
  EXPECT_LT(worst, kFloatBound);

  const int sides = 2 * kInertiaSides;
  std::vector<std::vector<btScalar>> rows(sides, std::vector<btScalar>(n, 0)), responses(sides, std::vector<btScalar>(n));
  std::vector<btScalar> columns(size_t(n) * sides), gram(size_t(sides) * sides);
  for (int r = 0; r < sides; ++r)
    for (int i = state.first; i < n; ++i)
      columns[size_t(i) * sides + r] = rows[r][i] = uniform(rng, -1, 1);
  solveInertiaColumns(state, columns.data(), sides, gram.data());
  double worst_response = 0, worst_gram = 0, gram_scale = 0;
  for (int r = 0; r < sides; ++r)
  {
    body.calcAccelerationDeltasMultiDof(rows[r].data(), responses[r].data(), scratch.r, scratch.v);
    std::vector<btScalar> column(n);
    for (int i = 0; i < n; ++i)
      column[i] = columns[size_t(i) * sides + r];
    worst_response = std::max(worst_response, relativeDifference(column, responses[r], n, state.first));
  }
  for (int r = 0; r < sides; ++r)
    for (int s = 0; s < sides; ++s)
    {
      double expected = 0;
      for (int i = state.first; i < n; ++i)
        expected += double(rows[r][i]) * responses[s][i];
      worst_gram = std::max(worst_gram, std::abs(gram[size_t(r) * sides + s] - expected));
      gram_scale = std::max(gram_scale, std::abs(expected));
    }
  report(name + " solveInertiaColumns response relative difference", worst_response);
  report(name + " solveInertiaColumns Gram relative difference", worst_gram / gram_scale);
  EXPECT_LT(worst_response, kFloatBound);
  EXPECT_LT(worst_gram / gram_scale, kFloatBound);
}

// contactJacobianRow against fillContactJacobianMultiDof: a point near each body, several
// directions. With a fixed base Bullet fills the base's six entries too (they meet velocities that
// are always zero); contactJacobianRow leaves them zero.
void expectContactJacobianMatchesBullet(btMultiBody& body, std::mt19937& rng, const std::string& name)
{
  updateKinematics(body);
  MultibodyState state;
  linkKinematics(body, state);
  const int n = state.n;
  BulletScratch scratch;
  std::vector<btScalar> ours(n), bullet(n);
  double worst = 0;
  for (int link = -1; link < body.getNumLinks(); ++link)
  {
    const btVector3 origin = link < 0 ? body.getBasePos() : body.getLink(link).m_cachedWorldTransform.getOrigin();
    for (int k = 0; k < 4; ++k)
    {
      const btVector3 point = origin + randomVector(rng, -0.2, 0.2), direction = randomDirection(rng);
      contactJacobianRow(state, link, point, direction, ours.data());
      body.fillContactJacobianMultiDof(link, point, direction, bullet.data(), scratch.r, scratch.v, scratch.m);
      worst = std::max(worst, relativeDifference(ours, bullet, n, state.first));
      for (int i = 0; i < state.first; ++i)
        EXPECT_EQ(ours[i], 0);
    }
  }
  report(name + " contact Jacobian relative difference", worst);
  EXPECT_LT(worst, kFloatBound);
}

TEST(MultibodyDynamics, ForwardDynamicsMatchesArticulatedBodyPassOnRandomChains)
{
  for (bool fixed_base : {false, true})
  {
    double worst = 0;
    for (unsigned seed = 1; seed <= 20; ++seed)
    {
      std::mt19937 rng(seed);
      std::unique_ptr<btMultiBody> chain = randomChain(rng, fixed_base);
      applyRandomLoads(rng, *chain);
      worst = std::max(worst, forwardDynamicsDifference(*chain));
    }
    report(std::string(fixed_base ? "fixed" : "free") + "-base chains qdd relative difference", worst);
    EXPECT_LT(worst, kFloatBound);
  }
}

TEST(MultibodyDynamics, InverseInertiaMatchesBulletOnRandomChains)
{
  for (bool fixed_base : {false, true})
    for (unsigned seed = 1; seed <= 5; ++seed)
    {
      std::mt19937 rng(seed);
      std::unique_ptr<btMultiBody> chain = randomChain(rng, fixed_base);
      expectInverseInertiaMatchesBullet(*chain, rng, std::string(fixed_base ? "fixed" : "free") + "-base chain " +
                                                        std::to_string(seed));
    }
}

TEST(MultibodyDynamics, ContactJacobianMatchesBulletOnRandomChains)
{
  for (bool fixed_base : {false, true})
  {
    std::mt19937 rng(7);
    std::unique_ptr<btMultiBody> chain = randomChain(rng, fixed_base);
    expectContactJacobianMatchesBullet(*chain, rng, std::string(fixed_base ? "fixed" : "free") + "-base chain");
  }
}

// SDF ball joints are Bullet's spherical links: three degrees of freedom on one link, whose motion
// subspace (axis top and bottom per dof) every algorithm here walks dof by dof. Bound: 3e-4. Of the
// 20 chains one (fixed base, seed 8) differs by 1.3e-4, its M^-1 alone (no velocities) as much and
// solveInertiaColumns (float) as much as solveInertia (double), the others by 2e-6 to 2e-5 as the
// chains without ball joints: Bullet's float pass on a worse conditioned chain (a 3x3 joint inverse
// per ball), not a term of ours, which would show on every chain at 1e-2.
TEST(MultibodyDynamics, AlgorithmsMatchBulletOnRandomChainsWithBallJoints)
{
  constexpr double kBallChainBound = 3e-4;
  for (bool fixed_base : {false, true})
  {
    const std::string name = std::string(fixed_base ? "fixed" : "free") + "-base chains with ball joints";
    double worst = 0;
    for (unsigned seed = 1; seed <= 10; ++seed)
    {
      std::mt19937 rng(seed);
      std::unique_ptr<btMultiBody> chain = randomChain(rng, fixed_base, 10, true);
      ASSERT_EQ(chain->getNumDofs(), 16);  // links 1, 4, 7 spherical
      applyRandomLoads(rng, *chain);
      worst = std::max(worst, forwardDynamicsDifference(*chain));
      if (seed == 1)
      {
        expectInverseInertiaMatchesBullet(*chain, rng, name);
        expectContactJacobianMatchesBullet(*chain, rng, name);
      }
    }
    report(name + " qdd relative difference", worst);
    EXPECT_LT(worst, kBallChainBound);
  }
}

// A free body (no links, a floating base) takes the closed form M^-1 = diag(I^-1, 1 / m)
// (factorInertia): the same checks on random ones.
TEST(MultibodyDynamics, FreeBodiesMatchBullet)
{
  double worst = 0;
  for (unsigned seed = 1; seed <= 10; ++seed)
  {
    std::mt19937 rng(seed);
    std::unique_ptr<btMultiBody> body = randomChain(rng, false, 0);
    applyRandomLoads(rng, *body);
    updateKinematics(*body);
    MultibodyState state;
    ASSERT_TRUE(buildMultibodyState(*body, state));
    EXPECT_TRUE(state.free);
    worst = std::max(worst, forwardDynamicsDifference(*body));
    expectInverseInertiaMatchesBullet(*body, rng, "free body " + std::to_string(seed));
    expectContactJacobianMatchesBullet(*body, rng, "free body " + std::to_string(seed));
  }
  report("free bodies qdd relative difference", worst);
  EXPECT_LT(worst, kFloatBound);
}

TEST(MultibodyDynamics, StateIsNotBuiltForAnInertiaThatIsNotPositiveDefinite)
{
  std::mt19937 rng(3);
  std::unique_ptr<btMultiBody> chain = randomChain(rng, true, 3);
  chain->getLink(2).m_mass = 0;
  chain->getLink(2).m_inertiaLocal.setZero();
  updateKinematics(*chain);
  MultibodyState state;
  EXPECT_FALSE(buildMultibodyState(*chain, state));
}

// The car spawned through the plant, moving: random joint and base velocities, loads.
class TianracerDynamics : public ::testing::Test
{
protected:
  void SetUp() override
  {
    const std::string urdf = tianracerUrdf();
    ASSERT_FALSE(urdf.empty());
    car_ = &world_.spawn(urdf, "tianracer", urdf::Pose());
    world_.step(10);
    btMultiBody& body = multibodyOf(*car_);
    body.setMaxCoordinateVelocity(btScalar(1e6));
    body.setBaseVel(randomVector(rng_, -1, 1));
    body.setBaseOmega(randomVector(rng_, -2, 2));
    for (int i = 0; i < body.getNumLinks(); ++i)
      for (int d = 0; d < body.getLink(i).m_dofCount; ++d)
        body.getJointVelMultiDof(i)[d] = uniform(rng_, -30, 30);
    applyRandomLoads(rng_, body);
  }

  World world_;
  Robot* car_ = nullptr;
  std::mt19937 rng_{11};
};

TEST_F(TianracerDynamics, ForwardDynamicsMatchesArticulatedBodyPass)
{
  btMultiBody& body = multibodyOf(*car_);
  EXPECT_GT(body.getNumDofs(), 4);
  const double difference = forwardDynamicsDifference(body);
  report("Tianracer qdd relative difference", difference);
  EXPECT_LT(difference, kFloatBound);
}

TEST_F(TianracerDynamics, InverseInertiaMatchesBullet) { expectInverseInertiaMatchesBullet(multibodyOf(*car_), rng_, "Tianracer"); }

TEST_F(TianracerDynamics, ContactJacobianMatchesBullet) { expectContactJacobianMatchesBullet(multibodyOf(*car_), rng_, "Tianracer"); }

}  // namespace
}  // namespace bullet_plant
