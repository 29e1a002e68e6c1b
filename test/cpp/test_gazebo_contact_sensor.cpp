// Gazebo's ContactSensor over the plant's contact sensor, as a sensor plugin of the user's own meets
// it: a <sensor type="contact"> on a 2 kg box resting on the ground, whose <plugin> file is found
// (here Gazebo's own libContactPlugin.so, which sets it active): its collision by scoped name, each
// measurement's contact with the ground (points on the ground, normals along z, the box's weight
// in the wrenches), the same through Contacts(collision) as physics::Contact, and msgs::Contacts on
// ~/probe/base/bumper while subscribed.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <mutex>
#include <string>
#include <vector>

#include <gazebo/physics/Collision.hh>
#include <gazebo/sensors/sensors.hh>
#include <gazebo/transport/transport.hh>

#include "bullet_plant/world.h"

using namespace bullet_plant;

namespace
{
const char* kWorld = R"(<sdf version='1.7'><world name='contact_world'>
  <physics type='ode'><max_step_size>0.001</max_step_size></physics>
  <include><uri>model://ground_plane</uri></include>
  <model name='probe'><pose>0 0 0.1 0 0 0</pose><link name='base'>
    <inertial><mass>2</mass><inertia><ixx>0.01</ixx><iyy>0.01</iyy><izz>0.01</izz></inertia></inertial>
    <collision name='shell'><geometry><box><size>0.2 0.2 0.2</size></box></geometry></collision>
    <sensor type='contact' name='bumper'><update_rate>100</update_rate>
      <contact><collision>shell</collision></contact>
      <plugin name='touch' filename='libContactPlugin.so'/>
    </sensor>
  </link></model>
</world></sdf>)";

std::shared_ptr<gazebo::sensors::ContactSensor> bumper()
{
  return std::dynamic_pointer_cast<gazebo::sensors::ContactSensor>(
      gazebo::sensors::SensorManager::Instance()->GetSensor("bumper"));
}
}  // namespace

TEST(GazeboContactSensor, ReportsTheBoxOnTheGround)
{
  World world(parseWorldDescription(kWorld));
  std::shared_ptr<gazebo::sensors::ContactSensor> sensor = bumper();
  ASSERT_TRUE(sensor);
  EXPECT_TRUE(sensor->IsActive()) << "ContactPlugin::Load sets its sensor active";
  EXPECT_EQ(sensor->Category(), gazebo::sensors::OTHER);
  ASSERT_EQ(sensor->GetCollisionCount(), 1u);
  EXPECT_EQ(sensor->GetCollisionName(0), "probe::base::shell");
  EXPECT_EQ(sensor->GetCollisionName(1), "");
  std::atomic<int> updates{0};
  gazebo::event::ConnectionPtr on_update = sensor->ConnectUpdated([&] { ++updates; });
  world.step(1000);
  EXPECT_NEAR(updates, 100, 1);

  const gazebo::msgs::Contacts contacts = sensor->Contacts();
  EXPECT_NEAR(gazebo::msgs::Convert(contacts.time()).Double(), world.time(), 0.011);
  ASSERT_EQ(contacts.contact_size(), 1);
  const gazebo::msgs::Contact& ground = contacts.contact(0);
  EXPECT_EQ(ground.collision1(), "probe::base::shell");
  EXPECT_EQ(ground.collision2(), "ground_plane::link::collision");
  EXPECT_EQ(ground.world(), "contact_world");
  ASSERT_GT(ground.position_size(), 0);
  ASSERT_EQ(ground.normal_size(), ground.position_size());
  ASSERT_EQ(ground.wrench_size(), ground.position_size());
  double weight = 0;
  for (int i = 0; i < ground.position_size(); ++i)
  {
    EXPECT_NEAR(ground.position(i).z(), 0.0, 2e-3);
    EXPECT_NEAR(std::abs(ground.normal(i).z()), 1.0, 1e-6);
    weight += ground.wrench(i).body_1_wrench().force().z();
  }
  EXPECT_NEAR(std::abs(weight), 2 * 9.8, 0.2) << "the ground holds the box up";
  EXPECT_EQ(sensor->GetCollisionContactCount("probe::base::shell"), static_cast<unsigned int>(ground.position_size()));

  const std::map<std::string, gazebo::physics::Contact> by_other = sensor->Contacts("probe::base::shell");
  ASSERT_EQ(by_other.count("ground_plane::link::collision"), 1u);
  const gazebo::physics::Contact& contact = by_other.at("ground_plane::link::collision");
  EXPECT_EQ(contact.count, ground.position_size());
  ASSERT_TRUE(contact.collision1);
  EXPECT_EQ(contact.collision1->GetScopedName(), "probe::base::shell");
  EXPECT_NEAR(contact.positions[0].Z(), 0.0, 2e-3);
}

TEST(GazeboContactSensor, PublishesOnItsTopicWhileSubscribed)
{
  World world(parseWorldDescription(kWorld));
  ASSERT_TRUE(bumper());
  std::mutex mutex;
  std::vector<gazebo::msgs::Contacts> received;
  gazebo::transport::NodePtr node(new gazebo::transport::Node());
  node->Init("contact_world");
  const boost::function<void(ConstContactsPtr&)> keep = [&](ConstContactsPtr& message) {
    std::lock_guard<std::mutex> lock(mutex);
    received.push_back(*message);
  };
  gazebo::transport::SubscriberPtr subscriber = node->Subscribe("~/probe/base/bumper", keep);
  world.step(200);
  gazebo::transport::TopicManager::Instance()->WaitForAll();
  std::lock_guard<std::mutex> lock(mutex);
  EXPECT_NEAR(static_cast<int>(received.size()), 20, 1);
  ASSERT_FALSE(received.empty());
  EXPECT_EQ(received.back().contact_size(), 1);
}
