// DynamicsWorld (physics/dynamics_world.cpp) against Bullet's own btMultiBodyDynamicsWorld with
// btMultiBodyConstraintSolver: the same scene stepped in both. In the air the step is the forward
// dynamics (the joint-space form against Bullet's articulated-body pass) and the chain's contacts
// with itself (rows of Bullet's own, which need Bullet's articulated-body pass: the world must run
// it); on the ground it adds contact rows (the dense solver's), a JointDrive row and a
// btMultiBodyJointMotor row (Bullet's).
// Float tolerance as in test_multibody_dynamics.cpp; the iterations add the solver's rounding.
#include <gtest/gtest.h>

#include <BulletCollision/CollisionShapes/btBoxShape.h>
#include <BulletCollision/CollisionShapes/btSphereShape.h>
#include <BulletCollision/CollisionShapes/btStaticPlaneShape.h>
#include <BulletDynamics/Featherstone/btMultiBodyJointMotor.h>
#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>

#include "multibody_fixtures.h"
#include "physics/joint_drive.h"

namespace bullet_plant
{
namespace
{
using namespace test;

// A random chain (spheres on its bodies) over the ground plane, in the plant's world or in
// Bullet's, with the plant's solver settings.
struct Scene : HandBuiltWorld
{
  btStaticPlaneShape plane{btVector3(0, 0, 1), 0};
  btCollisionObject ground;
  btSphereShape sphere{btScalar(0.1)};
  std::unique_ptr<btMultiBody> body;
  std::vector<std::unique_ptr<btMultiBodyLinkCollider>> colliders;
  std::unique_ptr<JointDrive> drive;
  std::unique_ptr<btMultiBodyJointMotor> motor;

  Scene(bool plant, bool fixed_base, bool on_ground, unsigned seed)
    : HandBuiltWorld(plant, btVector3(0, 0, btScalar(-9.81)))
  {
    std::mt19937 rng(seed);
    body = randomChain(rng, fixed_base, 6);
    updateKinematics(*body);
    if (on_ground)  // the lowest sphere 5 mm into the ground
    {
      btScalar lowest = body->getBasePos().z();
      for (int i = 0; i < body->getNumLinks(); ++i)
        lowest = std::min(lowest, body->getLink(i).m_cachedWorldTransform.getOrigin().z());
      body->setBasePos(body->getBasePos() + btVector3(0, 0, sphere.getRadius() - btScalar(0.005) - lowest));
    }
    else
      body->setBasePos(body->getBasePos() + btVector3(0, 0, 10));
    updateKinematics(*body);
    world->addMultiBody(body.get());
    for (int link = -1; link < body->getNumLinks(); ++link)
    {
      colliders.emplace_back(new btMultiBodyLinkCollider(body.get(), link));
      btMultiBodyLinkCollider& collider = *colliders.back();
      collider.setCollisionShape(&sphere);
      collider.setWorldTransform(link < 0 ? body->getBaseWorldTransform()
                                          : body->getLink(link).m_cachedWorldTransform);
      if (link < 0)
        body->setBaseCollider(&collider);
      else
        body->getLink(link).m_collider = &collider;
      world->addCollisionObject(&collider, btBroadphaseProxy::DefaultFilter, btBroadphaseProxy::AllFilter);
    }
    ground.setCollisionShape(&plane);
    world->addCollisionObject(&ground, btBroadphaseProxy::StaticFilter,
                              btBroadphaseProxy::AllFilter ^ btBroadphaseProxy::StaticFilter);
    if (on_ground)
    {
      drive.reset(new JointDrive(world.get(), body.get(), 0));
      drive->drive(1.0, 5.0, 0.01);
      motor.reset(new btMultiBodyJointMotor(body.get(), 1, btScalar(-0.5), btScalar(0.01)));
      world->addMultiBodyConstraint(motor.get());
    }
  }

  ~Scene()
  {
    if (motor)
      world->removeMultiBodyConstraint(motor.get());
    drive.reset();
    world->removeCollisionObject(&ground);
    for (auto& collider : colliders)
      world->removeCollisionObject(collider.get());
    world->removeMultiBody(body.get());
  }

  std::vector<btScalar> velocities() const
  {
    return std::vector<btScalar>(body->getVelocityVector(), body->getVelocityVector() + body->getNumDofs() + 6);
  }
};

// The velocity change of one step in the plant's world against Bullet's, relative to its largest
// entry.
double stepDifference(bool fixed_base, bool on_ground, unsigned seed)
{
  Scene plant(true, fixed_base, on_ground, seed), bullet(false, fixed_base, on_ground, seed);
  const std::vector<btScalar> before = plant.velocities();
  plant.world->stepSimulation(btScalar(0.001), 0, btScalar(0.001));
  bullet.world->stepSimulation(btScalar(0.001), 0, btScalar(0.001));
  std::vector<btScalar> a = plant.velocities(), b = bullet.velocities();
  for (size_t i = 0; i < a.size(); ++i)
  {
    a[i] -= before[i];
    b[i] -= before[i];
  }
  if (on_ground)
  {
    int points = 0;
    for (int m = 0; m < plant.world->getDispatcher()->getNumManifolds(); ++m)
      points += plant.world->getDispatcher()->getManifoldByIndexInternal(m)->getNumContacts();
    EXPECT_GT(points, 0) << "seed " << seed;
  }
  return relativeDifference(a, b, int(a.size()));
}

TEST(DynamicsWorld, StepInTheAirMatchesBulletsWorld)
{
  for (bool fixed_base : {false, true})
  {
    double worst = 0;
    for (unsigned seed = 1; seed <= 10; ++seed)
      worst = std::max(worst, stepDifference(fixed_base, false, seed));
    report(std::string(fixed_base ? "fixed" : "free") + "-base chain in the air, velocity relative difference", worst);
    EXPECT_LT(worst, 1e-4);
  }
}

TEST(DynamicsWorld, StepOnTheGroundWithDrivesMatchesBulletsWorldAndSolver)
{
  for (bool fixed_base : {false, true})
  {
    double worst = 0;
    for (unsigned seed = 1; seed <= 10; ++seed)
      worst = std::max(worst, stepDifference(fixed_base, true, seed));
    report(std::string(fixed_base ? "fixed" : "free") + "-base chain on the ground, velocity relative difference",
           worst);
    EXPECT_LT(worst, 1e-4);
  }
}

// A world's static object gets its box once, as it is added, the box Bullet's own update gives it;
// moving objects (a multibody's links, fixed base or not) get theirs at every step, as in Bullet.
TEST(DynamicsWorld, AStaticObjectsBoxIsMadeOnceAsBulletMakesItAndMovingOnesAtEveryStep)
{
  btBoxShape box(btVector3(1, 2, 3));
  std::vector<btVector3> boxes[2];  // the plant's world's, Bullet's: the static box, then the chain's base
  for (bool plant : {true, false})
  {
    Scene scene(plant, /*fixed_base=*/true, /*on_ground=*/false, 3);
    btCollisionObject wall;
    wall.setCollisionShape(&box);
    wall.setWorldTransform(btTransform(btQuaternion(btVector3(0, 0, 1), btScalar(0.3)), btVector3(4, 5, 6)));
    scene.world->addCollisionObject(&wall, btBroadphaseProxy::StaticFilter,
                                    btBroadphaseProxy::AllFilter ^ btBroadphaseProxy::StaticFilter);
    scene.world->stepSimulation(btScalar(0.001), 0, btScalar(0.001));
    boxes[plant ? 0 : 1] = {wall.getBroadphaseHandle()->m_aabbMin, wall.getBroadphaseHandle()->m_aabbMax};

    // The fixed-base chain set elsewhere: its base's box follows in both worlds at the next step.
    scene.body->setBasePos(scene.body->getBasePos() + btVector3(7, 0, 0));
    updateKinematics(*scene.body);
    scene.body->getBaseCollider()->setWorldTransform(scene.body->getBaseWorldTransform());
    scene.world->stepSimulation(btScalar(0.001), 0, btScalar(0.001));
    EXPECT_NEAR(scene.body->getBaseCollider()->getBroadphaseHandle()->m_aabbMin.x(),
                scene.body->getBasePos().x() - scene.sphere.getRadius() - gContactBreakingThreshold, 1e-4)
        << (plant ? "the plant's world" : "Bullet's world");
    scene.world->removeCollisionObject(&wall);
  }
  for (int k = 0; k < 2; ++k)
    for (int axis = 0; axis < 3; ++axis)
      EXPECT_EQ(boxes[0][k][axis], boxes[1][k][axis]) << (k ? "max" : "min") << " along axis " << axis;
}

}  // namespace
}  // namespace bullet_plant
