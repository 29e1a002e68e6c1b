// Gazebo's WheelSlipPlugin (libWheelSlipPlugin.so, include/gazebo-11/gazebo/plugins/) on the plant,
// and the physics under it: ODE's force-dependent slip on a contact's friction rows. A rig of our
// own: a 0.1 m sphere wheel on a spin joint (about y) under a carriage that is free to move up and
// down (a prismatic joint along z) on a slider that runs along x against a damper of d N s/m. The
// wheel is driven at w = 10 rad/s (r w = 1 m/s) and carries the rig's weight N. Without slip the
// rig rolls at r w (friction holds up to mu N = 2 N: the damper needs d v). With the plugin's
// longitudinal compliance c (wheel_normal_force N), ODE's slip2 is r w / N * c, so the contact
// slides at (r w - v) = slip2 * d v: the rig goes at v = r w / (1 + c d r w / N), with d = N / (1 m/s)
// half of r w at c = 1 and two thirds at c = 0.5; the lateral compliance leaves it alone. (The
// Gazebo side of the world is made with its first Gazebo plugin: each world here has the plugin.)
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include <gazebo/msgs/msgs.hh>
#include <gazebo/physics/physics.hh>
#include <gazebo/physics/ode/ODESurfaceParams.hh>
#include <gazebo/transport/transport.hh>

#include "bullet_plant/robot.h"
#include "bullet_plant/world.h"
#include "bullet_plant/world_description.h"

using namespace bullet_plant;

namespace
{
constexpr double kWeight = 10.0 * 9.8;  // N on the wheel: carriage 8 kg, wheel 2 kg

std::string rig(const std::string& plugin)
{
  return R"(<sdf version='1.6'><world name='default'>
  <gravity>0 0 -9.8</gravity>
  <model name='ground'><static>true</static><link name='link'>
    <collision name='c'><geometry><plane><normal>0 0 1</normal><size>100 100</size></plane></geometry>
      <surface><friction><ode><mu>2</mu><mu2>2</mu2></ode></friction></surface></collision></link></model>
  <model name='rig'>
    <link name='slider'><pose>0 0 0.1 0 0 0</pose>
      <inertial><mass>0.5</mass><inertia><ixx>0.01</ixx><iyy>0.01</iyy><izz>0.01</izz></inertia></inertial></link>
    <link name='carriage'><pose>0 0 0.1 0 0 0</pose>
      <inertial><mass>8</mass><inertia><ixx>0.1</ixx><iyy>0.1</iyy><izz>0.1</izz></inertia></inertial></link>
    <link name='wheel'><pose>0 0 0.1 0 0 0</pose>
      <inertial><mass>2</mass><inertia><ixx>0.008</ixx><iyy>0.008</iyy><izz>0.008</izz></inertia></inertial>
      <collision name='tire'><geometry><sphere><radius>0.1</radius></sphere></geometry>
        <surface><friction><ode><mu>2</mu><mu2>2</mu2><fdir1>0 1 0</fdir1></ode></friction></surface></collision></link>
    <joint name='run' type='prismatic'><parent>world</parent><child>slider</child>
      <axis><xyz>1 0 0</xyz><dynamics><damping>98</damping></dynamics></axis></joint>
    <joint name='bounce' type='prismatic'><parent>slider</parent><child>carriage</child>
      <axis><xyz>0 0 1</xyz></axis></joint>
    <joint name='spin' type='revolute'><parent>carriage</parent><child>wheel</child>
      <axis><xyz>0 1 0</xyz></axis></joint>
    )" + plugin + R"(
  </model>
</world></sdf>)";
}

std::string wheelSlip(double lateral, double longitudinal)
{
  return "<plugin name='wheel_slip' filename='libWheelSlipPlugin.so'><wheel link_name='wheel'>"
         "<slip_compliance_lateral>" + std::to_string(lateral) + "</slip_compliance_lateral>"
         "<slip_compliance_longitudinal>" + std::to_string(longitudinal) + "</slip_compliance_longitudinal>"
         "<wheel_normal_force>" + std::to_string(kWeight) + "</wheel_normal_force></wheel></plugin>";
}

// The rig's speed along x after 3 s with the wheel driven at 10 rad/s.
double rigSpeed(World& world)
{
  const gazebo::physics::JointPtr spin = gazebo::physics::get_world()->ModelByName("rig")->GetJoint("spin");
  spin->SetParam("fmax", 0, 100.0);
  spin->SetParam("vel", 0, 10.0);
  world.step(static_cast<int>(3.0 / world.timeStep()));
  const double speed = gazebo::physics::get_world()->ModelByName("rig")->GetLink("slider")->WorldLinearVel().X();
  testing::Test::RecordProperty("rig_speed", std::to_string(speed));  // in --gtest_output=xml's report
  return speed;
}
}  // namespace

TEST(GazeboWheelSlipPlugin, WithoutSlipTheRigRollsAtTheWheelsSpeed)
{
  World world(parseWorldDescription(rig(wheelSlip(0, 0))));
  EXPECT_NEAR(rigSpeed(world), 1.0, 0.02);
}

TEST(GazeboWheelSlipPlugin, TheLongitudinalComplianceSlowsTheRigAsOdesSlipSays)
{
  {
    World world(parseWorldDescription(rig(wheelSlip(0, 1))));
    EXPECT_NEAR(rigSpeed(world), 0.5, 0.03);
  }
  World world(parseWorldDescription(rig(wheelSlip(0, 0.5))));
  EXPECT_NEAR(rigSpeed(world), 1.0 / 1.5, 0.03);
}

TEST(GazeboWheelSlipPlugin, TheLateralComplianceLeavesTheRollingAlone)
{
  World world(parseWorldDescription(rig(wheelSlip(1, 0))));
  EXPECT_NEAR(rigSpeed(world), 1.0, 0.02);
}

TEST(GazeboWheelSlipPlugin, TheComplianceChangesOverGazebosTransportAndTheSlipsArePublished)
{
  World world(parseWorldDescription(rig(wheelSlip(0, 0))));
  EXPECT_NEAR(rigSpeed(world), 1.0, 0.02);
  gazebo::transport::NodePtr node(new gazebo::transport::Node());
  node->Init("default");
  ignition::math::Vector3d slip;
  int published = 0;
  const boost::function<void(const boost::shared_ptr<const gazebo::msgs::Vector3d>&)> received =
      [&](const boost::shared_ptr<const gazebo::msgs::Vector3d>& m) {
        slip = gazebo::msgs::ConvertIgn(*m);
        ++published;
      };
  auto subscriber = node->Subscribe("~/rig/wheel_slip/wheel", received);
  gazebo::msgs::GzString compliance;
  compliance.set_data("1");
  node->Advertise<gazebo::msgs::GzString>("~/rig/wheel_slip/longitudinal_compliance")->Publish(compliance, true);
  EXPECT_NEAR(rigSpeed(world), 0.5, 0.03);
  EXPECT_GT(published, 100);
  EXPECT_NEAR(slip.Z(), 1.0, 0.01);                // r w
  EXPECT_NEAR(slip.X(), 0.5 - 1.0, 0.03);          // the rolling way: v - r w
  EXPECT_NEAR(slip.Y(), 0.0, 0.01);
}

TEST(GazeboWheelSlipPlugin, AWheelTheModelLacksOrWithoutANormalForceIsGazebosErrorAndTheRigRuns)
{
  testing::internal::CaptureStderr();
  World world(parseWorldDescription(rig(
      "<plugin name='s' filename='libWheelSlipPlugin.so'><wheel link_name='axle'/>"
      "<wheel link_name='wheel'><slip_compliance_longitudinal>1</slip_compliance_longitudinal></wheel></plugin>")));
  const std::string said = testing::internal::GetCapturedStderr();
  EXPECT_NE(said.find("Could not find link named [axle] in model [rig]"), std::string::npos) << said;
  EXPECT_NE(said.find("Found wheel normal force [0], which is not positive"), std::string::npos) << said;
  EXPECT_NE(said.find("No ODE links and surfaces found, plugin is disabled"), std::string::npos) << said;
  EXPECT_NEAR(rigSpeed(world), 1.0, 0.02);
}

TEST(GazeboWheelSlipPlugin, ANegativeSlipFromAPluginIsRefusedWithoutHarm)
{
  // A plugin of no wheel (disabled) makes the Gazebo side; the test writes the surface itself.
  World world(parseWorldDescription(rig("<plugin name='s' filename='libWheelSlipPlugin.so'/>")));
  const auto surface = boost::dynamic_pointer_cast<gazebo::physics::ODESurfaceParams>(
      gazebo::physics::get_world()->ModelByName("rig")->GetLink("wheel")->GetCollision("tire")->GetSurface());
  ASSERT_TRUE(surface);
  EXPECT_DOUBLE_EQ(surface->FrictionPyramid()->MuPrimary(), 2.0);
  EXPECT_EQ(surface->FrictionPyramid()->direction1, ignition::math::Vector3d(0, 1, 0));
  testing::internal::CaptureStderr();
  surface->slip2 = -1.0;
  EXPECT_NEAR(rigSpeed(world), 1.0, 0.02);
  const std::string said = testing::internal::GetCapturedStderr();
  EXPECT_NE(said.find("is not taken; the surface keeps what it had"), std::string::npos) << said;
}
