// joint_layer.cpp: gazebo_ros_control's joint handles (the error a position loop sees, refused
// commands) and what writeSim/readSim do with them on a real world: URDF limits on efforts and
// velocity commands, the e-stop, position limits.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "bullet_plant/world.h"

using namespace bullet_plant;

namespace
{
JointHandle handle(JointType type, bool limited)
{
  JointLimits limits;
  limits.has_position = limited;
  limits.lower = -0.6;
  limits.upper = 0.6;
  return JointHandle("joint", type, JointInterface::Effort, limits);
}

// Two arms on a fixed base turning about z (no gravity torque): one on a velocity handle, one on an
// effort handle, each with I = 0.01 kg m^2 about its axis, effort limit 0.5 N m, velocity limit 2 rad/s,
// position limits +-1 rad. They have no collision shapes: Bullet solves constraint rows (motors,
// limits) per simulation island, and only colliders make islands, so the plant gives such a robot a
// shapeless collider.
const char* kArms = R"(<robot name="arms">
  <link name="world"/>
  <link name="velocity_arm"><inertial><mass value="1"/>
    <inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <link name="effort_arm"><inertial><mass value="1"/>
    <inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <joint name="velocity_joint" type="revolute"><parent link="world"/><child link="velocity_arm"/>
    <axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="0.5" velocity="2"/></joint>
  <joint name="effort_joint" type="revolute"><parent link="world"/><child link="effort_arm"/>
    <origin xyz="1 0 0"/><axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="0.5" velocity="2"/></joint>
  <transmission name="t1"><type>transmission_interface/SimpleTransmission</type>
    <joint name="velocity_joint"><hardwareInterface>hardware_interface/VelocityJointInterface</hardwareInterface></joint>
    <actuator name="a1"/></transmission>
  <transmission name="t2"><type>transmission_interface/SimpleTransmission</type>
    <joint name="effort_joint"><hardwareInterface>hardware_interface/EffortJointInterface</hardwareInterface></joint>
    <actuator name="a2"/></transmission>
</robot>)";

struct Arms : ::testing::Test
{
  World world;
  Robot* robot = nullptr;
  void SetUp() override
  {
    world.log().setSink([](LogLevel, const std::string&) {});
    robot = &world.spawn(kArms, "arms", poseFromXyzRpy(0, 0, 0.5, 0, 0, 0));
  }
  double velocity(const std::string& joint)
  {
    double q, qd, effort;
    robot->jointState(joint, q, qd, effort);
    return qd;
  }
};
}  // namespace

TEST(JointHandle, PositionErrorTakesTheShortWayWithinTheLimits)
{
  const JointHandle revolute = handle(JointType::Revolute, true);
  EXPECT_NEAR(revolute.positionError(0.5, -0.5), 1.0, 1e-12);
  // Continuous: wrapped to (-pi, pi].
  const JointHandle continuous = handle(JointType::Continuous, false);
  EXPECT_NEAR(continuous.positionError(3.0, -3.0), 6.0 - 2 * M_PI, 1e-12);
  // Revolute without limits: wrapped too.
  EXPECT_NEAR(handle(JointType::Revolute, false).positionError(3.0, -3.0), 6.0 - 2 * M_PI, 1e-12);
  // Prismatic: plain difference.
  EXPECT_DOUBLE_EQ(handle(JointType::Prismatic, false).positionError(3.0, -3.0), 6.0);
}

TEST(JointHandle, NonFiniteCommandsAndLawsAreRefusedAndCounted)
{
  JointHandle h = handle(JointType::Revolute, true);
  EXPECT_TRUE(h.setCommand(0.25));
  EXPECT_FALSE(h.setCommand(std::numeric_limits<double>::quiet_NaN()));
  EXPECT_FALSE(h.setCommand(std::numeric_limits<double>::infinity()));
  EXPECT_DOUBLE_EQ(h.command(), 0.25) << "the previous command stays";
  EffortLaw law;
  law.stiffness = std::numeric_limits<double>::infinity();
  h.setEffortLaw(law);
  EXPECT_EQ(h.rejectedCommands(), 3);
}

TEST_F(Arms, VelocityCommandsAreHeldToTheUrdfVelocityLimit)
{
  robot->handle("velocity_joint")->setCommand(10.0);
  world.step(100);
  EXPECT_NEAR(velocity("velocity_joint"), 2.0, 1e-3);
  EXPECT_NEAR(robot->handle("velocity_joint")->velocity(), 2.0, 1e-3) << "readSim fills the handle";
}

TEST_F(Arms, EffortsAreHeldToTheUrdfEffortLimit)
{
  robot->handle("effort_joint")->setCommand(10.0);
  world.step(100);  // 0.1 s at 0.5 N m on 0.01 kg m^2: 5 rad/s, 0.25 rad
  EXPECT_NEAR(velocity("effort_joint"), 5.0, 0.05);
  EXPECT_NEAR(robot->handle("effort_joint")->effort(), 0.5, 1e-9);
}

TEST_F(Arms, EStopZeroesEffortsAndVelocityCommands)
{
  robot->handle("velocity_joint")->setCommand(1.0);
  robot->handle("effort_joint")->setCommand(0.1);
  world.step(100);
  robot->setEStop(true);
  const double coasting = velocity("effort_joint");
  world.step(100);
  EXPECT_NEAR(velocity("velocity_joint"), 0.0, 1e-3) << "the motor holds the joint at 0 rad/s";
  EXPECT_NEAR(velocity("effort_joint"), coasting, 1e-3) << "no effort: the arm coasts";
  EXPECT_DOUBLE_EQ(robot->handle("effort_joint")->effort(), 0.0);
}

TEST_F(Arms, JointsStayWithinTheirPositionLimits)
{
  robot->handle("velocity_joint")->setCommand(2.0);
  robot->handle("effort_joint")->setCommand(-0.5);
  double highest = -1e9, lowest = 1e9;
  for (int i = 0; i < 2000; ++i)
  {
    world.step();
    highest = std::max(highest, robot->handle("velocity_joint")->position());
    lowest = std::min(lowest, robot->handle("effort_joint")->position());
  }
  EXPECT_LT(highest, 1.0 + 2e-3);
  EXPECT_NEAR(robot->handle("velocity_joint")->position(), 1.0, 2e-3);
  EXPECT_GT(lowest, -1.0 - 2e-2) << "an effort joint hits its limit at speed";
  EXPECT_NEAR(robot->handle("effort_joint")->position(), -1.0, 2e-3);
}
