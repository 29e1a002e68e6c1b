// robot.cpp and world.cpp, what gazebo_ros's model services use: link twists, setting a link's
// state and joint positions, wrench and effort jobs with gazebo_ros's timing, time step and gravity.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "log_capture.h"
#include "bullet_plant/world.h"

using namespace bullet_plant;

namespace
{
// A 1 kg box on a revolute hinge (about z, +-1 rad) carrying a 0.5 kg arm whose tip link is fixed to it.
const char* kArmUrdf = R"(<robot name='arm'>
  <link name='base'><inertial><mass value='1'/><inertia ixx='0.01' iyy='0.01' izz='0.01' ixy='0' ixz='0' iyz='0'/></inertial>
    <collision><geometry><box size='0.2 0.2 0.2'/></geometry></collision></link>
  <link name='arm'><inertial><mass value='0.5'/><inertia ixx='0.001' iyy='0.001' izz='0.001' ixy='0' ixz='0' iyz='0'/></inertial></link>
  <link name='tip'/>
  <joint name='hinge' type='revolute'><parent link='base'/><child link='arm'/><origin xyz='0 0 0.15'/>
    <axis xyz='0 0 1'/><limit lower='-1' upper='1' effort='10' velocity='10'/></joint>
  <joint name='tip_joint' type='fixed'><parent link='arm'/><child link='tip'/><origin xyz='0.3 0 0'/></joint>
</robot>)";

// Up in the air, away from the ground plane.
urdf::Pose aloft()
{
  urdf::Pose p;
  p.position = urdf::Vector3(0, 0, 2);
  return p;
}

const char* kBoxUrdf = R"(<robot name='box'>
  <link name='box'><inertial><mass value='1'/><inertia ixx='0.01' iyy='0.01' izz='0.01' ixy='0' ixz='0' iyz='0'/></inertial>
    <collision><geometry><box size='0.2 0.2 0.2'/></geometry></collision></link></robot>)";

double norm3(const std::array<double, 3>& v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }
}  // namespace

TEST(RobotState, LinkNamesAreTheUrdfsLinks)
{
  World world;
  Robot& arm = world.spawn(kArmUrdf, "arm", urdf::Pose());
  EXPECT_EQ(arm.linkNames(), (std::vector<std::string>{"arm", "base", "tip"}));
  EXPECT_THROW(arm.linkTwist("nowhere"), std::out_of_range);
}

TEST(RobotState, SetLinkStateMovesTheRobotRigidlyAndGivesItTheTwist)
{
  World world;
  world.setGravity(urdf::Vector3(0, 0, 0));
  Robot& arm = world.spawn(kArmUrdf, "arm", aloft());
  urdf::Pose target;
  target.position = urdf::Vector3(2, 1, 0.5);
  target.rotation.setFromRPY(0, 0, M_PI / 2);
  Twist twist;
  twist.linear = {0.3, 0, 0};
  twist.angular = {0, 0, 0.5};
  arm.setLinkState("tip", target, twist);
  const urdf::Pose tip = arm.linkPose("tip"), base = arm.linkPose("base");
  EXPECT_NEAR(tip.position.x, 2, 1e-6);
  EXPECT_NEAR(tip.position.y, 1, 1e-6);
  EXPECT_NEAR(tip.position.z, 0.5, 1e-6);
  // The tip is 0.3 m along the arm's x from the hinge: turned by 90 degrees, the base is 0.3 m back along y.
  EXPECT_NEAR(base.position.x, 2, 1e-5);
  EXPECT_NEAR(base.position.y, 0.7, 1e-5);
  EXPECT_NEAR(base.position.z, 0.35, 1e-5);
  const Twist at_tip = arm.linkTwist("tip");
  EXPECT_NEAR(at_tip.linear[0], 0.3, 1e-5);
  EXPECT_NEAR(at_tip.linear[1], 0, 1e-5);
  EXPECT_NEAR(at_tip.angular[2], 0.5, 1e-6);
  // Rigid motion: the base's origin, 0.3 m from the tip, moves by omega x r besides.
  const Twist at_base = arm.linkTwist("base");
  EXPECT_NEAR(at_base.linear[0], 0.3 + 0.5 * 0.3, 1e-5);
  EXPECT_THROW(arm.setLinkState("nowhere", target, twist), std::out_of_range);
}

TEST(RobotState, JointPositionsAreHeldToTheLimitsWithAWarning)
{
  World world;
  LogCapture said(world.log(), LogLevel::Warn);
  const std::vector<std::string>& warnings = said.messages;
  Robot& arm = world.spawn(kArmUrdf, "arm", urdf::Pose());
  arm.setJointPositions({{"hinge", 0.5}});
  double q, qd, effort;
  ASSERT_TRUE(arm.jointState("hinge", q, qd, effort));
  EXPECT_NEAR(q, 0.5, 1e-6);
  EXPECT_NEAR(arm.linkPose("tip").position.y, 0.3 * std::sin(0.5), 1e-5);
  arm.setJointPositions({{"hinge", 7}});
  arm.jointState("hinge", q, qd, effort);
  EXPECT_NEAR(q, 1, 1e-6);
  bool warned = false;
  for (const std::string& m : warnings)
    warned |= m.find("position 7 of joint 'hinge' of 'arm' is outside its URDF limits") != std::string::npos;
  EXPECT_TRUE(warned);
  EXPECT_THROW(arm.setJointPositions({{"tip_joint", 0.1}}), std::out_of_range);
  world.resetSimulation();
  arm.jointState("hinge", q, qd, effort);
  EXPECT_NEAR(q, 0, 1e-6);  // back to the spawn positions
}

TEST(RobotState, AWrenchActsFromItsStartForItsDurationThenIsDropped)
{
  World world;
  world.setGravity(urdf::Vector3(0, 0, 0));
  Robot& box = world.spawn(kBoxUrdf, "box", aloft());
  // 1.5 N on 1 kg for 0.1 s (steps at 50 .. 149 ms) from t = 0.05 s: 0.15 m/s, then coasting.
  box.applyLinkWrench("box", urdf::Vector3(1.5, 0, 0), urdf::Vector3(0, 0, 0), 50000000, 99000000);
  world.step(50);
  EXPECT_NEAR(box.linkTwist("box").linear[0], 0, 1e-9);
  world.step(100);
  EXPECT_NEAR(box.linkTwist("box").linear[0], 0.15, 1e-4);
  world.step(100);
  EXPECT_NEAR(box.linkTwist("box").linear[0], 0.15, 1e-4);
  // A negative duration: until cleared. A torque turns it.
  box.applyLinkWrench("box", urdf::Vector3(-1.5, 0, 0), urdf::Vector3(0, 0, 0.01), world.timeNs(), -1);
  world.step(100);
  EXPECT_NEAR(box.linkTwist("box").linear[0], 0.0, 1e-4);
  EXPECT_NEAR(box.linkTwist("box").angular[2], 0.1, 1e-3);  // 0.01 N m on 0.01 kg m^2 for 0.1 s
  box.clearLinkWrenches("box");
  world.step(100);
  EXPECT_NEAR(box.linkTwist("box").linear[0], 0.0, 1e-4);
  EXPECT_THROW(box.applyLinkWrench("nowhere", urdf::Vector3(), urdf::Vector3(), 0, -1), std::out_of_range);
}

TEST(RobotState, AJointEffortTurnsTheJointUntilCleared)
{
  World world;
  world.setGravity(urdf::Vector3(0, 0, 0));
  Robot& arm = world.spawn(kArmUrdf, "arm", aloft());
  arm.applyJointEffort("hinge", 0.05, 0, -1);
  world.step(100);
  double q, qd, effort;
  arm.jointState("hinge", q, qd, effort);
  EXPECT_GT(qd, 0.05);
  arm.clearJointEfforts("hinge");
  arm.setJointPositions({{"hinge", 0}});
  world.step(100);
  arm.jointState("hinge", q, qd, effort);
  EXPECT_NEAR(qd, 0, 1e-6);
  EXPECT_THROW(arm.applyJointEffort("nowhere", 1, 0, -1), std::out_of_range);
}

TEST(WorldPhysics, TimeStepAndGravityChangeFromTheNextStep)
{
  World world;
  Robot& arm = world.spawn(kArmUrdf, "arm", urdf::Pose());
  EXPECT_NEAR(world.gravity().z, -9.8, 1e-6);
  world.setTimeStep(0.002);
  world.step(10);
  EXPECT_EQ(world.timeNs(), 20000000);
  world.setGravity(urdf::Vector3(0, 0, 0));
  arm.setLinkState("base", arm.linkPose("base"), Twist());
  world.step(100);
  EXPECT_NEAR(norm3(arm.linkTwist("base").linear), 0, 1e-6);
  EXPECT_THROW(world.setTimeStep(0), std::invalid_argument);
  EXPECT_THROW(world.setTimeStep(1), std::invalid_argument);
  EXPECT_EQ(world.timeStep(), 0.002);
  EXPECT_EQ(world.timeStepNs(), 2000000);
}
