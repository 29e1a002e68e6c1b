// Gazebo's ElevatorPlugin (libElevatorPlugin.so, include/gazebo-11/gazebo/plugins/) on the plant,
// loaded from a model's <plugin> as Gazebo loads it, commanded as Gazebo's tutorial commands it: a
// floor number in a GzString on ~/elevator (here from this process's own transport node, as a
// user's plugin would send it). The car rises to floor x <floor_height>, the door opens there, waits
// <door_wait_time> and closes; a command while busy is ignored; a model without the joints it names
// runs with the plugin disabled.
#include <gtest/gtest.h>

#include <string>

#include <gazebo/msgs/msgs.hh>
#include <gazebo/transport/transport.hh>

#include "bullet_plant/robot.h"
#include "bullet_plant/world.h"

using namespace bullet_plant;

namespace
{
// An elevator of our own: a fixed shaft, a car on a prismatic lift joint (up to 7 m), a door
// sliding 1 m on the car.
std::string elevatorModel(const std::string& plugin_body)
{
  return R"(<sdf version='1.6'><model name='elevator'>
  <link name='shaft'><inertial><mass>1000</mass></inertial></link>
  <joint name='shaft_fixed' type='fixed'><parent>world</parent><child>shaft</child></joint>
  <link name='car'>
    <inertial><mass>200</mass><inertia><ixx>50</ixx><iyy>50</iyy><izz>50</izz></inertia></inertial>
    <collision name='floor'><pose>0 0 0.05 0 0 0</pose><geometry><box><size>2 2 0.1</size></box></geometry></collision>
  </link>
  <joint name='lift' type='prismatic'><parent>shaft</parent><child>car</child>
    <axis><xyz>0 0 1</xyz><limit><lower>0</lower><upper>7</upper></limit></axis></joint>
  <link name='door'><pose>1 0 1 0 0 0</pose>
    <inertial><mass>10</mass><inertia><ixx>1</ixx><iyy>1</iyy><izz>1</izz></inertia></inertial>
  </link>
  <joint name='door_slide' type='prismatic'><parent>car</parent><child>door</child>
    <axis><xyz>0 1 0</xyz><limit><lower>0</lower><upper>1</upper></limit></axis></joint>
  <plugin name='elevator' filename='libElevatorPlugin.so'>)" +
         plugin_body + R"(</plugin>
</model></sdf>)";
}

double position(World& world, const std::string& joint)
{
  double p = 0, v = 0, e = 0;
  EXPECT_TRUE(world.robot("elevator")->jointState(joint, p, v, e)) << joint;
  return p;
}

void send(const std::string& topic, const std::string& floor)
{
  gazebo::transport::NodePtr node(new gazebo::transport::Node());
  node->Init();
  gazebo::msgs::GzString message;
  message.set_data(floor);
  gazebo::transport::PublisherPtr publisher = node->Advertise<gazebo::msgs::GzString>(topic);
  publisher->Publish(message, true);  // the plugin has it when this returns
}

// Steps until `done` or `seconds` of simulated time: whether it came.
template <typename Done>
bool stepUntil(World& world, double seconds, Done done)
{
  const int steps = static_cast<int>(seconds / world.timeStep());
  for (int i = 0; i < steps; ++i)
  {
    world.step();
    if (done())
      return true;
  }
  return false;
}
}  // namespace

TEST(GazeboElevatorPlugin, AFloorOnItsTopicTakesTheCarThereOpensTheDoorAndClosesItAfterTheWait)
{
  World world;
  world.spawn(elevatorModel("<lift_joint>lift</lift_joint><door_joint>door_slide</door_joint>"
                            "<floor_height>3</floor_height><door_wait_time>2</door_wait_time>"),
              "elevator", urdf::Pose());
  world.step(100);
  EXPECT_NEAR(position(world, "lift"), 0.0, 0.15);
  EXPECT_NEAR(position(world, "door_slide"), 0.0, 0.05);

  send("/gazebo/" + world.description().name + "/elevator", "2");
  ASSERT_TRUE(stepUntil(world, 30.0, [&] { return position(world, "lift") > 6.0 - 0.15; }))
      << "the car at " << position(world, "lift");
  // The door opens once the car is at its floor, and closes after waiting there.
  ASSERT_TRUE(stepUntil(world, 20.0, [&] { return position(world, "door_slide") > 0.95; }))
      << "the door at " << position(world, "door_slide");
  EXPECT_NEAR(position(world, "lift"), 6.0, 0.15);
  const double opened_at = world.time();
  ASSERT_TRUE(stepUntil(world, 20.0, [&] { return position(world, "door_slide") < 0.05; }));
  EXPECT_GT(world.time() - opened_at, 2.0);  // held open at least <door_wait_time>
  EXPECT_NEAR(position(world, "lift"), 6.0, 0.15);
}

TEST(GazeboElevatorPlugin, ACommandWhileBusyIsIgnoredAndAnotherTopicIsHonoured)
{
  World world;
  world.spawn(elevatorModel("<lift_joint>lift</lift_joint><door_joint>door_slide</door_joint>"
                            "<floor_height>2</floor_height><door_wait_time>0.5</door_wait_time>"
                            "<topic>~/lobby/call</topic>"),
              "elevator", urdf::Pose());
  world.step(10);
  const std::string topic = "/gazebo/" + world.description().name + "/lobby/call";
  send(topic, "1");
  world.step(10);
  send(topic, "3");  // busy: ignored
  ASSERT_TRUE(stepUntil(world, 30.0, [&] { return position(world, "lift") > 2.0 - 0.15; }));
  world.step(static_cast<int>(10.0 / world.timeStep()));
  EXPECT_NEAR(position(world, "lift"), 2.0, 0.15);
  send(topic, "not a floor");  // an error naming the message; the elevator stays
  world.step(100);
  EXPECT_NEAR(position(world, "lift"), 2.0, 0.15);
}

TEST(GazeboElevatorPlugin, AMissingJointDisablesThePluginAndTheModelRuns)
{
  World world;
  testing::internal::CaptureStderr();  // Gazebo's console: gzerr
  world.spawn(elevatorModel("<lift_joint>no_such_joint</lift_joint><door_joint>door_slide</door_joint>"), "elevator",
              urdf::Pose());
  const std::string said = testing::internal::GetCapturedStderr();
  EXPECT_NE(said.find("Unable to find lift joint[no_such_joint]"), std::string::npos) << said;
  world.step(100);
  EXPECT_NEAR(position(world, "lift"), 0.0, 0.15);
}
