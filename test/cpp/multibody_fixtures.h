// Multibodies and worlds for the physics tests: random chains built with Bullet's own API, the Tianracer
// through the plant, hand-built worlds (the plant's or Bullet's), and the comparisons they share.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <btBulletDynamicsCommon.h>

#include "bullet_plant/world.h"
#include "simulation/internals.h"
#include "physics/dense_row_solver.h"
#include "physics/dynamics_world.h"

namespace bullet_plant
{
namespace test
{
inline btScalar uniform(std::mt19937& rng, double low, double high)
{
  return btScalar(std::uniform_real_distribution<double>(low, high)(rng));
}

inline btVector3 randomVector(std::mt19937& rng, double low, double high)
{
  return btVector3(uniform(rng, low, high), uniform(rng, low, high), uniform(rng, low, high));
}

inline btVector3 randomDirection(std::mt19937& rng) { return randomVector(rng, -1, 1).normalized(); }

inline btQuaternion randomRotation(std::mt19937& rng)
{
  return btQuaternion(randomDirection(rng), uniform(rng, -SIMD_PI, SIMD_PI));
}

// A chain of `links` bodies with random masses, inertias, joint axes, offsets and revolute or
// prismatic joints, at random joint positions and velocities (and base pose and twist). With
// `ball_joints`, every third link from the second hangs from a spherical joint (an SDF ball joint:
// three velocities, a quaternion position) instead.
inline std::unique_ptr<btMultiBody> randomChain(std::mt19937& rng, bool fixed_base, int links = 10,
                                                bool ball_joints = false)
{
  std::unique_ptr<btMultiBody> body(
      new btMultiBody(links, uniform(rng, 1, 3), randomVector(rng, 0.02, 0.2), fixed_base, false));
  auto ball = [&](int i) { return ball_joints && i % 3 == 1; };
  for (int i = 0; i < links; ++i)
  {
    const btScalar mass = uniform(rng, 0.3, 2);
    const btVector3 inertia = randomVector(rng, 0.005, 0.05);
    const btVector3 pivot = randomVector(rng, -0.3, 0.3), com = randomVector(rng, -0.3, 0.3);
    if (ball(i))
      body->setupSpherical(i, mass, inertia, i - 1, randomRotation(rng), pivot, com, true);
    else if (rng() % 2)
      body->setupRevolute(i, mass, inertia, i - 1, randomRotation(rng), randomDirection(rng), pivot, com, true);
    else
      body->setupPrismatic(i, mass, inertia, i - 1, randomRotation(rng), randomDirection(rng), pivot, com, true);
  }
  body->finalizeMultiDof();
  body->setMaxCoordinateVelocity(btScalar(1e6));  // never clamps what the tests compare
  body->setBasePos(randomVector(rng, -1, 1));
  body->setWorldToBaseRot(randomRotation(rng));
  if (!fixed_base)
  {
    body->setBaseVel(randomVector(rng, -1, 1));
    body->setBaseOmega(randomVector(rng, -2, 2));
  }
  for (int i = 0; i < links; ++i)
  {
    if (ball(i))
    {
      const btQuaternion q = randomRotation(rng);
      const btScalar position[4] = {q.x(), q.y(), q.z(), q.w()};
      const btVector3 velocity = randomVector(rng, -2, 2);
      body->setJointPosMultiDof(i, position);
      body->setJointVelMultiDof(i, velocity.m_floats);
      continue;
    }
    body->setJointPos(i, uniform(rng, -1, 1));
    body->setJointVel(i, uniform(rng, -2, 2));
  }
  body->setLinearDamping(btScalar(0.05));
  body->setAngularDamping(btScalar(0.05));
  return body;
}

// Gravity (as Bullet's world applies it, a force on each body) plus random forces, torques and
// joint torques.
inline void applyRandomLoads(std::mt19937& rng, btMultiBody& body)
{
  const btVector3 gravity(0, 0, btScalar(-9.81));
  body.clearForcesAndTorques();
  body.addBaseForce(gravity * body.getBaseMass() + randomVector(rng, -3, 3));
  body.addBaseTorque(randomVector(rng, -1, 1));
  for (int i = 0; i < body.getNumLinks(); ++i)
  {
    body.addLinkForce(i, gravity * body.getLink(i).m_mass + randomVector(rng, -3, 3));
    body.addLinkTorque(i, randomVector(rng, -1, 1));
    for (int d = 0; d < body.getLink(i).m_dofCount; ++d)
      body.addJointTorqueMultiDof(i, d, uniform(rng, -2, 2));
  }
}

// The link transforms every algorithm starts from (Bullet's forward kinematics of a step).
inline void updateKinematics(btMultiBody& body)
{
  btAlignedObjectArray<btQuaternion> world_to_local;
  btAlignedObjectArray<btVector3> local_origin;
  body.forwardKinematics(world_to_local, local_origin);
}

// Bullet's articulated-body pass with dt = 0: fills the caches calcAccelerationDeltasMultiDof and
// Bullet's rows read.
struct BulletScratch
{
  btAlignedObjectArray<btScalar> r;
  btAlignedObjectArray<btVector3> v;
  btAlignedObjectArray<btMatrix3x3> m;
};
inline void articulatedPass(btMultiBody& body, BulletScratch& scratch)
{
  body.computeAccelerationsArticulatedBodyAlgorithmMultiDof(0, scratch.r, scratch.v, scratch.m, false, false, false);
}

// max |a - b| / max |b|: the difference relative to the largest entry of the reference.
template <typename A, typename B>
double relativeDifference(const A& a, const B& b, int n, int first = 0)
{
  double difference = 0, scale = 0;
  for (int i = first; i < n; ++i)
  {
    difference = std::max(difference, std::abs(double(a[i]) - double(b[i])));
    scale = std::max(scale, std::abs(double(b[i])));
  }
  return scale > 0 ? difference / scale : difference;
}

// Prints a measured figure and records it in the gtest XML.
inline void report(const std::string& what, double value)
{
  ::testing::Test::RecordProperty(what, std::to_string(value));
  std::cout << what << " = " << value << std::endl;
}

// The Tianracer's URDF, from its xacro as the launch files make it.
inline std::string tianracerUrdf()
{
  const std::string command =
      "\"$(rospack find xacro)/xacro\" " TIANRACER_SOURCE_DIR "/urdf/tianracer_description.xacro";
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe)
    return "";
  std::string urdf;
  char buffer[4096];
  size_t got;
  while ((got = fread(buffer, 1, sizeof buffer, pipe)) > 0)
    urdf.append(buffer, got);
  if (pclose(pipe) != 0)
    ADD_FAILURE() << "`" << command << "` failed: is the workspace sourced (rospack finds xacro)?";
  return urdf;
}

// A multibody world built by hand: the plant's (DynamicsWorld with DenseRowSolver) or Bullet's own
// (btMultiBodyDynamicsWorld with btMultiBodyConstraintSolver), with the plant's solver settings.
struct HandBuiltWorld
{
  btDefaultCollisionConfiguration configuration;
  btCollisionDispatcher dispatcher{&configuration};
  btDbvtBroadphase broadphase;
  std::unique_ptr<btMultiBodyConstraintSolver> solver;
  std::unique_ptr<btMultiBodyDynamicsWorld> world;

  HandBuiltWorld(bool plant, const btVector3& gravity)
  {
    if (plant)
    {
      auto* dense = new DenseRowSolver;
      solver.reset(dense);
      world.reset(new DynamicsWorld(&dispatcher, &broadphase, dense, &configuration));
    }
    else
    {
      solver.reset(new btMultiBodyConstraintSolver);
      world.reset(new btMultiBodyDynamicsWorld(&dispatcher, &broadphase, solver.get(), &configuration));
    }
    world->setGravity(gravity);
    btContactSolverInfo& info = world->getSolverInfo();
    info.m_numIterations = 10;
    info.m_solverMode |= SOLVER_DISABLE_IMPLICIT_CONE_FRICTION;
    info.m_splitImpulse = false;
    info.m_timeStep = btScalar(0.001);
  }
};

inline btMultiBody& multibodyOf(Robot& robot) { return *internalsOf(robot).multibody.bullet; }

}  // namespace test
}  // namespace bullet_plant
