// The wheel contact (physics/wheel_contact.cpp): a cylinder lying on a plane touches it at one
// point in the middle of its tread; anything else keeps Bullet's general convex-plane test.
#include <gtest/gtest.h>

#include <memory>

#include <BulletCollision/CollisionShapes/btCylinderShape.h>
#include <BulletCollision/CollisionShapes/btStaticPlaneShape.h>
#include <btBulletCollisionCommon.h>

#include "physics/wheel_contact.h"

namespace bullet_plant
{
namespace
{
constexpr btScalar kRadius = btScalar(0.032), kHalfWidth = btScalar(0.0125);

// A Tianracer wheel (axis along its local y) and the ground plane z = 0.
struct Scene
{
  btDefaultCollisionConfiguration configuration;
  btCollisionDispatcher dispatcher{&configuration};
  btDbvtBroadphase broadphase;
  btCollisionWorld world{&dispatcher, &broadphase, &configuration};
  btCylinderShape cylinder{btVector3(kRadius, kHalfWidth, kRadius)};
  btStaticPlaneShape plane{btVector3(0, 0, 1), 0};
  btCollisionObject wheel, ground;

  Scene(bool wheel_contact, const btTransform& pose, bool ground_first = false)
  {
    if (wheel_contact)
      registerWheelContact(dispatcher);
    wheel.setCollisionShape(&cylinder);
    wheel.setWorldTransform(pose);
    ground.setCollisionShape(&plane);
    if (ground_first)
      world.addCollisionObject(&ground);
    world.addCollisionObject(&wheel);
    if (!ground_first)
      world.addCollisionObject(&ground);
    world.performDiscreteCollisionDetection();
  }
  ~Scene()
  {
    world.removeCollisionObject(&wheel);
    world.removeCollisionObject(&ground);
  }

  std::vector<btManifoldPoint*> points()
  {
    std::vector<btManifoldPoint*> out;
    for (int m = 0; m < dispatcher.getNumManifolds(); ++m)
    {
      btPersistentManifold* manifold = dispatcher.getManifoldByIndexInternal(m);
      for (int k = 0; k < manifold->getNumContacts(); ++k)
        out.push_back(&manifold->getContactPoint(k));
    }
    return out;
  }
};

// The wheel 1 mm into the ground at (0.3, -0.2), its axis turned by `yaw` about z and rolled by `roll` about it.
btTransform lyingWheel(btScalar yaw, btScalar roll)
{
  btQuaternion rotation(btVector3(0, 0, 1), yaw);
  rotation *= btQuaternion(btVector3(0, 1, 0), roll);
  return btTransform(rotation, btVector3(btScalar(0.3), btScalar(-0.2), kRadius - btScalar(0.001)));
}

void expectOnePointMidTread(Scene& scene)
{
  const std::vector<btManifoldPoint*> points = scene.points();
  ASSERT_EQ(points.size(), 1u);
  const btManifoldPoint& p = *points[0];
  EXPECT_NEAR(p.getDistance(), -0.001, 1e-6);
  for (const btVector3& at : {p.getPositionWorldOnA(), p.getPositionWorldOnB()})
  {
    EXPECT_NEAR(at.x(), 0.3, 1e-6);
    EXPECT_NEAR(at.y(), -0.2, 1e-6);
  }
  EXPECT_NEAR(std::abs(p.m_normalWorldOnB.z()), 1.0, 1e-6);
}

TEST(WheelContact, LyingCylinderTouchesAtOnePointInTheMiddleOfItsTread)
{
  for (bool ground_first : {false, true})
    for (btScalar yaw : {btScalar(0), btScalar(0.7)})
      for (btScalar roll : {btScalar(0), btScalar(1.3)})
      {
        SCOPED_TRACE(testing::Message() << "ground first " << ground_first << ", yaw " << yaw << ", roll " << roll);
        Scene scene(true, lyingWheel(yaw, roll), ground_first);
        expectOnePointMidTread(scene);
      }
}

TEST(WheelContact, BulletsGeneralTestFindsAnEdgeOfTheTread)
{
  // What the wheel contact replaces: the general test's points lie near the tread's edges.
  Scene scene(false, lyingWheel(0, 0));
  const std::vector<btManifoldPoint*> points = scene.points();
  ASSERT_GE(points.size(), 1u);
  for (const btManifoldPoint* p : points)
    EXPECT_GT(std::abs(p->getPositionWorldOnA().y() + 0.2), 0.8 * kHalfWidth);
}

TEST(WheelContact, KeepsImpulsesForWarmStartingAndLetsGoAboveTheGround)
{
  Scene scene(true, lyingWheel(0, 0));
  ASSERT_EQ(scene.points().size(), 1u);
  btManifoldPoint& point = *scene.points()[0];
  point.m_appliedImpulse = 5;
  point.m_appliedImpulseLateral1 = -2;
  scene.wheel.setWorldTransform(lyingWheel(0, btScalar(0.1)));  // rolled on: a fresh point
  scene.world.performDiscreteCollisionDetection();
  ASSERT_EQ(scene.points().size(), 1u);
  EXPECT_EQ(scene.points()[0]->m_appliedImpulse, 5);
  EXPECT_EQ(scene.points()[0]->m_appliedImpulseLateral1, -2);
  btTransform lifted = lyingWheel(0, 0);
  lifted.getOrigin().setZ(kRadius + btScalar(0.01));  // beyond the contact breaking threshold
  scene.wheel.setWorldTransform(lifted);
  scene.world.performDiscreteCollisionDetection();
  EXPECT_EQ(scene.points().size(), 0u);
}

TEST(WheelContact, StandingOrTiltedCylinderKeepsBulletsGeneralTest)
{
  for (btScalar tilt : {btScalar(SIMD_HALF_PI), btScalar(1.0)})  // on a cap; axis 57 degrees up
  {
    SCOPED_TRACE(testing::Message() << "tilt " << tilt);
    btTransform pose(btQuaternion(btVector3(1, 0, 0), tilt), btVector3(0, 0, 0));
    btVector3 lowest = pose.getBasis() * btVector3(0, -kHalfWidth, 0);  // near the bottom cap's centre
    pose.getOrigin() = btVector3(btScalar(0.3), btScalar(-0.2), -lowest.z() - btScalar(0.001));
    Scene wheel(true, pose), general(false, pose);
    const std::vector<btManifoldPoint*> a = wheel.points(), b = general.points();
    ASSERT_EQ(a.size(), b.size());
    EXPECT_GE(a.size(), 1u);
    for (size_t k = 0; k < a.size(); ++k)
      EXPECT_LT((a[k]->getPositionWorldOnA() - b[k]->getPositionWorldOnA()).length(), 1e-6);
  }
}

}  // namespace
}  // namespace bullet_plant
