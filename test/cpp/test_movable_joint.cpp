// positionWithinLimits: a joint position outside the URDF limits is held to them, said once per call
// with the joint, the robot and the value; continuous joints and positions within pass unchanged.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "log_capture.h"
#include "physics/movable_joint.h"

using namespace bullet_plant;

namespace
{
MovableJoint hingeWithLimits(double lower, double upper)
{
  MovableJoint j;
  j.name = "steer";
  j.limits.has_position = true;
  j.limits.lower = lower;
  j.limits.upper = upper;
  return j;
}

}  // namespace

TEST(MovableJoint, PositionWithinLimitsPassesUnchangedAndSilently)
{
  WarningsCapture said;
  const MovableJoint j = hingeWithLimits(-0.5, 0.5);
  EXPECT_EQ(positionWithinLimits(j, 0.25, said.log, "car", "position"), 0.25);
  EXPECT_EQ(positionWithinLimits(j, 0.5, said.log, "car", "position"), 0.5);
  EXPECT_TRUE(said.warnings.empty());
}

TEST(MovableJoint, PositionOutsideIsHeldToTheNearerLimitNamingJointRobotAndValue)
{
  WarningsCapture said;
  const MovableJoint j = hingeWithLimits(-0.5, 0.5);
  EXPECT_EQ(positionWithinLimits(j, 2.0, said.log, "car", "initial position"), 0.5);
  EXPECT_EQ(positionWithinLimits(j, -7.0, said.log, "car", "position"), -0.5);
  ASSERT_EQ(said.warnings.size(), 2u);
  EXPECT_NE(said.warnings[0].find("initial position 2 of joint 'steer' of 'car'"), std::string::npos) << said.warnings[0];
  EXPECT_NE(said.warnings[0].find("[-0.5, 0.5]; it starts at 0.5"), std::string::npos) << said.warnings[0];
}

TEST(MovableJoint, AJointWithoutPositionLimitsTakesAnyPosition)
{
  WarningsCapture said;
  MovableJoint wheel;
  wheel.name = "wheel";
  EXPECT_EQ(positionWithinLimits(wheel, 1e6, said.log, "car", "position"), 1e6);
  EXPECT_TRUE(said.warnings.empty());
}
