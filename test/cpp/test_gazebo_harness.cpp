// Gazebo's HarnessPlugin (libHarnessPlugin.so, include/gazebo-11/gazebo/plugins/) on the plant,
// loaded from a model's <plugin> as Gazebo loads it, with the joint, winch gains and detach of
// Gazebo's own harness world, and commanded as its documentation says: a speed in a GzString on
// ~/<model>/harness/velocity, "true" on ~/<model>/harness/detach. The box hangs where it was, goes
// down at the speed asked, holds where a speed of 0 finds it, and falls once let go. And the joints'
// axes through Gazebo's physics::Joint: a model's, and one made at run time.
#include <gtest/gtest.h>

#include <string>

#include <cmath>

#include <gazebo/msgs/msgs.hh>
#include <gazebo/physics/physics.hh>
#include <gazebo/transport/transport.hh>

#include "bullet_plant/robot.h"
#include "bullet_plant/world.h"

using namespace bullet_plant;

namespace
{
// A 10 kg box of our own at z = 2, held by a prismatic joint from the world along z (limits
// -1.5 .. 1.5 m, damping 10 N s/m), its winch and detach joint that one.
std::string harnessedBox(const std::string& joints)
{
  return R"(<sdf version='1.6'><model name='box'><pose>0 0 2 0 0 0</pose>
  <link name='link'>
    <inertial><mass>10</mass><inertia><ixx>0.4</ixx><iyy>0.4</iyy><izz>0.4</izz></inertia></inertial>
    <collision name='c'><geometry><box><size>0.5 0.5 0.5</size></box></geometry></collision>
  </link>
  <plugin name='harness' filename='libHarnessPlugin.so'>)" +
         joints + R"(
    <winch><joint>joint1</joint>
      <pos_pid><p>1000000</p><i>0</i><d>0</d><i_max>0</i_max><i_min>0</i_min><cmd_max>2000</cmd_max><cmd_min>-2000</cmd_min></pos_pid>
      <vel_pid><p>10000</p><i>0</i><d>0</d><i_max>0</i_max><i_min>0</i_min><cmd_max>10000</cmd_max><cmd_min>0</cmd_min></vel_pid>
    </winch>
    <detach>joint1</detach>
  </plugin>
</model></sdf>)";
}

const char* kJoint = R"(
    <joint name='joint1' type='prismatic'>
      <pose>0 0 0 0 0 0</pose>
      <parent>world</parent>
      <child>link</child>
      <axis><xyz>0 0 1</xyz><dynamics><damping>10</damping></dynamics>
        <limit><lower>-1.5</lower><upper>1.5</upper><effort>10000</effort></limit></axis>
    </joint>)";

void send(World& world, const std::string& what, const std::string& data)
{
  gazebo::transport::NodePtr node(new gazebo::transport::Node());
  node->Init(world.description().name);
  gazebo::msgs::GzString message;
  message.set_data(data);
  node->Advertise<gazebo::msgs::GzString>("~/box/harness/" + what)->Publish(message, true);
}

urdf::Vector3 at(World& world) { return world.robot("box")->linkPose("link").position; }

void run(World& world, double seconds) { world.step(static_cast<int>(seconds / world.timeStep())); }
}  // namespace

TEST(GazeboHarnessPlugin, TheBoxHangsGoesDownAtTheSpeedAskedHoldsAtZeroAndFallsOnceDetached)
{
  World world;
  world.spawn(harnessedBox(kJoint), "box", urdf::Pose());
  run(world, 1.0);
  EXPECT_NEAR(at(world).z, 2.0, 0.002);  // the position PID holds it (10 kg at p 1e6: 0.1 mm low)
  EXPECT_NEAR(at(world).x, 0.0, 1e-6);

  send(world, "velocity", "-0.2");
  run(world, 2.0);
  EXPECT_NEAR(at(world).z, 2.0 - 0.2 * 2.0, 0.04);

  send(world, "velocity", "0");  // holds where it is now
  const double held_at = at(world).z;
  run(world, 1.0);
  EXPECT_NEAR(at(world).z, held_at, 0.003);

  send(world, "velocity", "fast");  // Gazebo's error naming it; the winch keeps its target
  run(world, 0.5);
  EXPECT_NEAR(at(world).z, held_at, 0.003);

  send(world, "detach", "true");
  run(world, 0.3);
  const double g = 9.8;
  EXPECT_NEAR(at(world).z, held_at - 0.5 * g * 0.09, 0.01);  // free: no limit, no winch
  send(world, "detach", "true");  // a second time: a warning, nothing else
  run(world, 0.1);
}

TEST(GazeboHarnessPlugin, AHarnessWithoutJointsSaysSoAndTheModelRuns)
{
  World world;
  testing::internal::CaptureStderr();  // Gazebo's console: gzerr
  world.spawn(harnessedBox(""), "box", urdf::Pose());
  const std::string said = testing::internal::GetCapturedStderr();
  EXPECT_NE(said.find("No joints specified in the harness plugin"), std::string::npos) << said;
  run(world, 0.3);
  EXPECT_NEAR(at(world).z, 2.0 - 0.5 * 9.8 * 0.09, 0.01);
}

TEST(GazeboHarnessPlugin, AGazeboJointTypeThePlantDoesNotMakeHoldsFixedAndANameThatIsNoTypeIsRefused)
{
  {
    World world;
    testing::internal::CaptureStderr();
    std::string joint = kJoint;
    joint.replace(joint.find("prismatic"), 9, "gearbox");
    world.spawn(harnessedBox(joint), "box", urdf::Pose());
    run(world, 0.3);
    const std::string said = testing::internal::GetCapturedStderr();
    EXPECT_NE(said.find("Joint [joint1] of type gearbox made at run time"), std::string::npos) << said;
    EXPECT_NEAR(at(world).z, 2.0, 0.002);  // held where it was
  }
  World world;
  testing::internal::CaptureStderr();
  std::string joint = kJoint;
  joint.replace(joint.find("prismatic"), 9, "sliding");
  world.spawn(harnessedBox(joint), "box", urdf::Pose());
  run(world, 0.3);
  const std::string said = testing::internal::GetCapturedStderr();
  EXPECT_NE(said.find("Unable to create joint of type[sliding]"), std::string::npos) << said;
  EXPECT_NE(said.find("Unable to create joint[joint1]"), std::string::npos) << said;
  EXPECT_NEAR(at(world).z, 2.0 - 0.5 * 9.8 * 0.09, 0.01);
}

TEST(GazeboJointAxes, AModelsJointAndAJointMadeAtRunTimeGiveTheirAxesInTheWorld)
{
  // A model turned a quarter about z: its hinge about its own y is about the world's -x.
  World world;
  urdf::Pose turned;
  turned.position = urdf::Vector3(0, 0, 2);
  turned.rotation.setFromRPY(0, 0, M_PI / 2);
  world.spawn(R"(<sdf version='1.6'><model name='box'>
  <link name='link'><inertial><mass>10</mass><inertia><ixx>0.4</ixx><iyy>0.4</iyy><izz>0.4</izz></inertia></inertial></link>
  <link name='arm'><pose>0.5 0 0 0 0 0</pose><inertial><mass>1</mass><inertia><ixx>0.01</ixx><iyy>0.01</iyy><izz>0.01</izz></inertia></inertial></link>
  <joint name='hinge' type='revolute'><parent>link</parent><child>arm</child><axis><xyz>0 1 0</xyz></axis></joint>
  <plugin name='harness' filename='libHarnessPlugin.so'>)" + std::string(kJoint) + R"(</plugin>
</model></sdf>)",
              "box", turned);
  gazebo::physics::WorldPtr gazebo_world = gazebo::physics::get_world(world.description().name);
  ASSERT_TRUE(gazebo_world);
  gazebo::physics::ModelPtr model = gazebo_world->ModelByName("box");
  ASSERT_TRUE(model);
  gazebo::physics::JointPtr hinge = model->GetJoint("hinge");
  ASSERT_TRUE(hinge);
  EXPECT_NEAR((hinge->LocalAxis(0) - ignition::math::Vector3d(0, 1, 0)).Length(), 0.0, 1e-9);
  EXPECT_NEAR((hinge->GlobalAxis(0) - ignition::math::Vector3d(-1, 0, 0)).Length(), 0.0, 1e-6);

  // One made at run time about the link's x: the world's y, before and after it is attached.
  gazebo::physics::JointPtr made = gazebo_world->Physics()->CreateJoint("revolute", model);
  made->SetModel(model);
  made->Load(gazebo::physics::LinkPtr(), model->GetLink("arm"), ignition::math::Pose3d::Zero);
  made->SetAxis(0, ignition::math::Vector3d(1, 0, 0));
  EXPECT_NEAR((made->GlobalAxis(0) - ignition::math::Vector3d(0, 1, 0)).Length(), 0.0, 1e-6);
  made->Init();
  world.step(10);
  EXPECT_NEAR((made->GlobalAxis(0) - ignition::math::Vector3d(0, 1, 0)).Length(), 0.0, 1e-3);
  EXPECT_NEAR((made->LocalAxis(0) - ignition::math::Vector3d(1, 0, 0)).Length(), 0.0, 1e-9);
}
