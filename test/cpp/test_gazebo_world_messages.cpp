// What a plugin sends the world over Gazebo's transport, as Gazebo's factory and world_edit examples
// send it: a msgs::Factory on ~/factory adds a model (its SDF text, or its file by model:// URI) where
// its pose puts it; a msgs::Physics on ~/physics changes the gravity, the step and whether physics
// runs, and says which of its fields the plant does not take. Messages come on the transport's
// thread; the world takes them between steps.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <string>
#include <thread>

#include <gazebo/msgs/msgs.hh>
#include <gazebo/physics/physics.hh>
#include <gazebo/transport/transport.hh>

#include "bullet_plant/robot.h"
#include "bullet_plant/world.h"
#include "simulation/internals.h"

using namespace bullet_plant;

namespace
{
std::string ball(const std::string& name)
{
  return "<sdf version='1.6'><model name='" + name + "'><pose>5 5 5 0 0 0</pose><link name='link'>"
         "<inertial><mass>1</mass></inertial><collision name='c'><geometry><sphere><radius>0.2</radius>"
         "</sphere></geometry></collision></link></model></sdf>";
}

// A world with one ball and Gazebo's side of it, and a node of a plugin's.
struct Scene
{
  World world;
  gazebo::transport::NodePtr node{new gazebo::transport::Node()};
  Scene()
  {
    world.spawn(ball("first"), "first", urdf::Pose());
    internalsOf(*world.robot("first")).world->gazeboHost();  // made as a first Gazebo plugin makes it
    node->Init(world.description().name);
  }
  // Steps until `done` (at most `tries` steps 10 ms apart): the messages come on the transport's thread.
  template <class Done>
  bool stepUntil(Done done, int tries = 200)
  {
    for (int i = 0; i < tries && !done(); ++i)
    {
      world.step(1);
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return done();
  }
};
}  // namespace

TEST(GazeboWorldMessages, AFactoryMessageAddsItsSdfOrItsFileWhereItsPosePutsIt)
{
  Scene scene;
  auto factory = scene.node->Advertise<gazebo::msgs::Factory>("~/factory");
  gazebo::msgs::Factory text;
  text.set_sdf(ball("from_text"));
  gazebo::msgs::Set(text.mutable_pose(), ignition::math::Pose3d(1, -2, 0.5, 0, 0, 0));
  factory->Publish(text);
  ASSERT_TRUE(scene.stepUntil([&] { return scene.world.robot("from_text") != nullptr; }));
  EXPECT_NEAR(scene.world.robot("from_text")->linkPose("link").position.y, -2.0, 1e-3);

  // A model folder of our own on GAZEBO_MODEL_PATH, by URI, at the message's pose.
  const std::string models = testing::TempDir() + "factory_models";
  std::system(("mkdir -p " + models + "/crate").c_str());
  std::ofstream(models + "/crate/model.config")
      << "<?xml version='1.0'?><model><name>crate</name><sdf version='1.6'>model.sdf</sdf></model>";
  std::ofstream(models + "/crate/model.sdf") << ball("crate");
  setenv("GAZEBO_MODEL_PATH", models.c_str(), 1);
  gazebo::msgs::Factory file;
  file.set_sdf_filename("model://crate");
  gazebo::msgs::Set(file.mutable_pose(), ignition::math::Pose3d(-3, 4, 0.5, 0, 0, 0));
  factory->Publish(file);
  ASSERT_TRUE(scene.stepUntil([&] { return scene.world.robot("crate") != nullptr; }));
  EXPECT_NEAR(scene.world.robot("crate")->linkPose("link").position.x, -3.0, 1e-3);
  EXPECT_NEAR(scene.world.robot("crate")->linkPose("link").position.y, 4.0, 1e-3);

  testing::internal::CaptureStderr();
  gazebo::msgs::Factory clone;
  clone.set_clone_model_name("first");
  factory->Publish(clone);
  gazebo::msgs::Factory empty;
  factory->Publish(empty);
  scene.stepUntil([] { return false; }, 30);
  const std::string said = testing::internal::GetCapturedStderr();
  EXPECT_NE(said.find("clone_model_name [first]: the plant neither edits nor clones models"), std::string::npos)
      << said;
  EXPECT_NE(said.find("Unable to load sdf from factory message"), std::string::npos) << said;
}

TEST(GazeboWorldMessages, APhysicsMessageChangesGravityStepAndPhysicsAndNamesWhatItDoesNotTake)
{
  Scene scene;
  auto physics = scene.node->Advertise<gazebo::msgs::Physics>("~/physics");
  gazebo::msgs::Physics message;
  message.set_type(gazebo::msgs::Physics::ODE);
  message.set_max_step_size(0.002);
  gazebo::msgs::Set(message.mutable_gravity(), ignition::math::Vector3d(0.01, 0, 0.1));
  message.set_iters(77);
  testing::internal::CaptureStderr();
  physics->Publish(message);
  ASSERT_TRUE(scene.stepUntil([&] { return scene.world.timeStep() == 0.002; }));
  const std::string said = testing::internal::GetCapturedStderr();
  EXPECT_NEAR(scene.world.gravity().x, 0.01, 1e-6);  // Bullet keeps it in single precision
  EXPECT_NEAR(scene.world.gravity().z, 0.1, 1e-6);
  EXPECT_NEAR(gazebo::physics::get_world()->Gravity().Z(), 0.1, 1e-6);
  EXPECT_NE(said.find("iters not taken from the message"), std::string::npos) << said;

  // The ball accelerates at the new gravity (it was falling before: the second difference of three
  // heights 0.5 s apart); without physics it stays where it is.
  auto z = [&] { return scene.world.robot("first")->linkPose("link").position.z; };
  const double z0 = z();
  scene.world.step(250);
  const double z1 = z();
  scene.world.step(250);
  EXPECT_NEAR((z() - 2 * z1 + z0) / 0.25, 0.1, 0.01);
  gazebo::msgs::Physics off;
  off.set_enable_physics(false);
  physics->Publish(off);
  ASSERT_TRUE(scene.stepUntil([&] { return !gazebo::physics::get_world()->PhysicsEnabled(); }));
  const double still = z();
  scene.world.step(100);
  EXPECT_NEAR(z(), still, 1e-9);
}
