// divergence_recovery.cpp's recovery from a diverged physics step: the state goes back to the last
// finite one, the error is said once per simulated second with a count, and after
// kRecoveriesBeforeDisabling recoveries within a second the robot leaves the physics with one error
// while the world runs on.
// No URDF the plant accepts diverges any more, so the divergence is injected: a NaN base velocity
// before each step. And Robot::contactNormals, the robot's contacts with anything else.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "log_capture.h"
#include "bullet_plant/world.h"
#include "simulation/internals.h"

using namespace bullet_plant;

namespace
{
const std::string kBox = "<robot name='box'><link name='box'><inertial><mass value='1'/>"
                         "<inertia ixx='0.01' iyy='0.01' izz='0.01' ixy='0' ixz='0' iyz='0'/></inertial>"
                         "<collision><geometry><box size='0.2 0.2 0.2'/></geometry></collision></link></robot>";

bool finite(const urdf::Pose& p)
{
  for (double v : {p.position.x, p.position.y, p.position.z, p.rotation.x, p.rotation.y, p.rotation.z, p.rotation.w})
    if (!std::isfinite(v))
      return false;
  return true;
}
}  // namespace

TEST(RobotRecovery, ADivergingRobotIsSaidOncePerSecondThenDisabledWhileTheWorldRunsOn)
{
  World world;
  LogCapture said(world.log(), LogLevel::Error);
  const std::vector<std::string>& errors = said.messages;
  Robot& good = world.spawn(kBox, "good", poseFromXyzRpy(0, 1, 0.1, 0, 0, 0));
  Robot& bad = world.spawn(kBox, "bad", poseFromXyzRpy(0, -1, 0.1, 0, 0, 0));
  const btScalar nan = std::numeric_limits<btScalar>::quiet_NaN();
  for (int i = 0; i < 10000; ++i)
  {
    if (!bad.disabled())
      internalsOf(bad).multibody.bullet->setBaseVel(btVector3(nan, 0, 0));
    world.step(1);
  }
  ASSERT_EQ(errors.size(), 2u);
  EXPECT_NE(errors[0].find("robot 'bad': the physics produced a non-finite state"), std::string::npos) << errors[0];
  EXPECT_NE(errors[1].find("robot 'bad' is disabled"), std::string::npos) << errors[1];
  EXPECT_NE(errors[1].find("delete_model"), std::string::npos) << errors[1];
  EXPECT_TRUE(bad.disabled());
  EXPECT_EQ(bad.recoveries(), Robot::kRecoveriesBeforeDisabling);
  EXPECT_TRUE(finite(bad.basePose()));
  EXPECT_FALSE(good.disabled());
  EXPECT_EQ(good.recoveries(), 0);
  EXPECT_NEAR(good.basePose().position.y, 1.0, 1e-3) << "the other robot rests where it was";
  EXPECT_NEAR(good.basePose().position.z, 0.1, 1e-3);
  world.resetWorld();
  world.step(10);
  EXPECT_TRUE(world.remove("bad"));
  world.step(10);
  EXPECT_GT(world.steps(), 10000u);
}

TEST(RobotRecovery, RecoveriesFarApartAreEachSaidAndNeverDisable)
{
  World world;
  int errors = 0;
  world.log().setSink([&](LogLevel level, const std::string&) { errors += level == LogLevel::Error; });
  Robot& robot = world.spawn(kBox, "box", poseFromXyzRpy(0, 0, 0.1, 0, 0, 0));
  for (int second = 0; second < 3; ++second)
  {
    internalsOf(robot).multibody.bullet->setBaseVel(btVector3(std::numeric_limits<btScalar>::infinity(), 0, 0));
    world.step(1000);
  }
  EXPECT_EQ(errors, 3);
  EXPECT_EQ(robot.recoveries(), 3);
  EXPECT_FALSE(robot.disabled());
  EXPECT_TRUE(finite(robot.basePose()));
}

// Robot::contactNormals: its contacts with the ground and with another robot, each normal pointing
// into the robot asked, none for a robot touching nothing.
TEST(RobotContacts, NormalsPointIntoTheRobotFromTheGroundAndFromAnotherRobot)
{
  World world;
  Robot& left = world.spawn(kBox, "left", poseFromXyzRpy(0, 0, 0.1, 0, 0, 0));
  Robot& right = world.spawn(kBox, "right", poseFromXyzRpy(0.199, 0, 0.1, 0, 0, 0));  // 1 mm into left
  Robot& aloft = world.spawn(kBox, "aloft", poseFromXyzRpy(5, 0, 3, 0, 0, 0));
  world.step(1);
  const auto count = [](const std::vector<urdf::Vector3>& normals, double x, double z) {
    return std::count_if(normals.begin(), normals.end(), [&](const urdf::Vector3& n) {
      return std::abs(n.x - x) < 1e-3 && std::abs(n.y) < 1e-3 && std::abs(n.z - z) < 1e-3;
    });
  };
  const std::vector<urdf::Vector3> on_left = left.contactNormals(), on_right = right.contactNormals();
  EXPECT_GT(count(on_left, 0, 1), 0) << "the ground pushes up";
  EXPECT_GT(count(on_left, -1, 0), 0) << "right pushes left towards -x";
  EXPECT_GT(count(on_right, 1, 0), 0) << "and left pushes right towards +x";
  EXPECT_EQ(count(on_left, 0, 1) + count(on_left, -1, 0), long(on_left.size())) << "nothing else";
  EXPECT_TRUE(aloft.contactNormals().empty());
}
