// JointDrive (physics/joint_drive.cpp): one row on a joint's velocity, rigid or soft, clamped,
// one-sided for limits; in the plant's world (its rows built by the dense solver without their
// response, createRowWithoutResponse) and in Bullet's (createConstraintRows), against the
// closed form for one joint.
#include <gtest/gtest.h>

#include <limits>
#include <memory>

#include <BulletCollision/CollisionShapes/btSphereShape.h>
#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>

#include "multibody_fixtures.h"
#include "physics/joint_drive.h"

namespace bullet_plant
{
namespace
{
constexpr double kBaseInertia = 0.5, kLinkInertia = 0.3;  // about z
constexpr double kStep = 0.001;
// A joint impulse P changes the joint rate by P / kEffective: the link turns against the free
// base about their common axis z (both centres of mass on it).
constexpr double kEffective = kBaseInertia * kLinkInertia / (kBaseInertia + kLinkInertia);

// A free base and one revolute link about z, no gravity or damping, in either world.
struct Scene : test::HandBuiltWorld
{
  btSphereShape sphere{btScalar(0.05)};
  btMultiBody body{1, 2, btVector3(0.4f, 0.4f, btScalar(kBaseInertia)), false, false};
  std::vector<std::unique_ptr<btMultiBodyLinkCollider>> colliders;
  std::unique_ptr<JointDrive> drive;

  explicit Scene(bool plant) : HandBuiltWorld(plant, btVector3(0, 0, 0))
  {
    body.setupRevolute(0, 1, btVector3(0.1f, 0.2f, btScalar(kLinkInertia)), -1, btQuaternion::getIdentity(),
                       btVector3(0, 0, 1), btVector3(0, 0, 0), btVector3(0, 0, 0), true);
    body.finalizeMultiDof();
    body.setLinearDamping(0);
    body.setAngularDamping(0);
    body.setMaxCoordinateVelocity(btScalar(1e6));
    world->addMultiBody(&body);
    for (int link = -1; link < 1; ++link)
    {
      colliders.emplace_back(new btMultiBodyLinkCollider(&body, link));
      colliders.back()->setCollisionShape(&sphere);
      if (link < 0)
        body.setBaseCollider(colliders.back().get());
      else
        body.getLink(0).m_collider = colliders.back().get();
      world->addCollisionObject(colliders.back().get(), 1, 0);  // colliding with nothing
    }
    drive.reset(new JointDrive(world.get(), &body, 0));
  }
  ~Scene()
  {
    drive.reset();
    for (auto& collider : colliders)
      world->removeCollisionObject(collider.get());
    world->removeMultiBody(&body);
  }

  double step(double joint_rate)
  {
    body.setJointVel(0, btScalar(joint_rate));
    body.setBaseOmega(btVector3(0, 0, 0));
    world->stepSimulation(btScalar(kStep), 0, btScalar(kStep));
    return body.getJointVel(0);
  }
};

class JointDriveIn : public ::testing::TestWithParam<bool>
{
protected:
  Scene scene_{GetParam()};
};

TEST_P(JointDriveIn, RigidDriveReachesItsTarget)
{
  scene_.drive->drive(2.0, std::numeric_limits<double>::infinity(), 100.0);
  EXPECT_NEAR(scene_.step(0.5), 2.0, 1e-5);
  EXPECT_NEAR(scene_.drive->appliedImpulse(), 1.5 * kEffective, 1e-5);
}

TEST_P(JointDriveIn, SoftDriveIsTheImplicitSpringDamperLaw)
{
  // impulse = gain (target - qd_end), qd_end = qd + impulse / I: impulse = gain (target - qd) / (1 + gain / I).
  const double gain = 0.2, target = 3.0, rate = -1.0;
  scene_.drive->drive(target, gain, 100.0);
  const double impulse = gain * (target - rate) / (1 + gain / kEffective);
  EXPECT_NEAR(scene_.step(rate), rate + impulse / kEffective, 1e-5);
  EXPECT_NEAR(scene_.drive->appliedImpulse(), impulse, 1e-6);
}

TEST_P(JointDriveIn, ImpulseIsClampedToTheLimit)
{
  scene_.drive->drive(10.0, std::numeric_limits<double>::infinity(), 0.01);
  EXPECT_NEAR(scene_.step(0.0), 0.01 / kEffective, 1e-5);
  EXPECT_NEAR(scene_.drive->appliedImpulse(), 0.01, 1e-7);
}

TEST_P(JointDriveIn, BoundOnlyPushes)
{
  scene_.drive->bound(0.0, true);  // the velocity may not fall below 0
  EXPECT_NEAR(scene_.step(-1.0), 0.0, 1e-5);
  EXPECT_NEAR(scene_.step(1.0), 1.0, 1e-6);  // above the bound: untouched
  EXPECT_NEAR(scene_.drive->appliedImpulse(), 0.0, 1e-7);
  scene_.drive->bound(0.0, false);  // nor rise above 0
  EXPECT_NEAR(scene_.step(1.0), 0.0, 1e-5);
}

TEST_P(JointDriveIn, IsInTheWorldOnlyWhileEnabled)
{
  EXPECT_FALSE(scene_.drive->enabled());
  EXPECT_EQ(scene_.world->getNumMultiBodyConstraints(), 0);
  scene_.drive->drive(1.0, 5.0, 1.0);
  EXPECT_TRUE(scene_.drive->enabled());
  EXPECT_TRUE(scene_.drive->soft());
  EXPECT_EQ(scene_.world->getNumMultiBodyConstraints(), 1);
  scene_.drive->drive(1.0, 5.0, 0.0);  // no impulse allowed: off
  EXPECT_EQ(scene_.world->getNumMultiBodyConstraints(), 0);
  scene_.drive->drive(1.0, 5.0, 1.0);
  scene_.drive->disable();
  EXPECT_EQ(scene_.world->getNumMultiBodyConstraints(), 0);
  EXPECT_NEAR(scene_.step(0.5), 0.5, 1e-7);  // nothing acts
  EXPECT_EQ(scene_.drive->appliedImpulse(), 0.0);
}

INSTANTIATE_TEST_SUITE_P(Worlds, JointDriveIn, ::testing::Values(true, false),
                         [](const ::testing::TestParamInfo<bool>& info) {
                           return info.param ? "PlantWorldAndDenseSolver" : "BulletsWorldAndSolver";
                         });

}  // namespace
}  // namespace bullet_plant
