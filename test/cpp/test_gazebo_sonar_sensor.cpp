// Gazebo's SonarSensor, as a sensor plugin of the user's own meets it (here Gazebo's own
// libSonarPlugin.so): a <sensor type="sonar"> is a sensors::SonarSensor in SensorManager, measuring
// the nearest thing in its cone, which opens from its origin along its -z axis as Gazebo's does
// (<radius> wide at <max> - <min> down the axis). A probe held 1 m above the ground has three, 0.15 m
// below its centre: one looking down sees the ground 0.85 m away, one turned to +y a wall whose face
// is 0.9 m away, one looking up nothing within its 2 m (the maximum, Gazebo's "nothing"). Each
// measurement at its <update_rate> is a msgs::SonarStamped on ~/MODEL/LINK/SENSOR/sonar and a call of
// ConnectUpdate's subscribers.
#include <gtest/gtest.h>

#include <mutex>
#include <string>
#include <vector>

#include <gazebo/sensors/sensors.hh>
#include <gazebo/transport/transport.hh>

#include "bullet_plant/world.h"

using namespace bullet_plant;

namespace
{
const char* const kWorld = R"(<sdf version='1.7'><world name='sonar_world'>
  <physics type='ode'><max_step_size>0.001</max_step_size></physics>
  <include><uri>model://ground_plane</uri></include>
  <model name='wall'><static>true</static><pose>0 1 1 0 0 0</pose>
    <link name='body'><collision name='c'><geometry><box><size>3 0.2 2</size></box></geometry></collision></link>
  </model>
  <model name='probe'>
    <link name='base'><pose>0 0 1 0 0 0</pose>
      <inertial><mass>1</mass><inertia><ixx>0.01</ixx><iyy>0.01</iyy><izz>0.01</izz></inertia></inertial>
      <collision name='c'><geometry><box><size>0.2 0.2 0.2</size></box></geometry></collision>
      <sensor name='sonar_down' type='sonar'><pose>0 0 -0.15 0 0 0</pose><always_on>1</always_on>
        <update_rate>20</update_rate>
        <sonar><min>0</min><max>2</max><radius>0.2</radius></sonar>
        <plugin name='s' filename='libSonarPlugin.so'/></sensor>
      <sensor name='sonar_side' type='sonar'><pose>0 0.15 0 1.5707963267948966 0 0</pose><always_on>1</always_on>
        <sonar><min>0</min><max>2</max><radius>0.2</radius></sonar>
        <plugin name='s' filename='libSonarPlugin.so'/></sensor>
      <sensor name='sonar_up' type='sonar'><pose>0 0 0.15 3.141592653589793 0 0</pose><always_on>1</always_on>
        <sonar><min>0</min><max>2</max><radius>0.2</radius></sonar>
        <plugin name='s' filename='libSonarPlugin.so'/></sensor>
    </link>
    <joint name='mount' type='fixed'><parent>world</parent><child>base</child></joint>
  </model>
</world></sdf>)";

std::shared_ptr<gazebo::sensors::SonarSensor> sonar(const std::string& name)
{
  return std::dynamic_pointer_cast<gazebo::sensors::SonarSensor>(
      gazebo::sensors::SensorManager::Instance()->GetSensor(name));
}
}  // namespace

TEST(GazeboSonarSensor, MeasuresTheNearestThingInItsConeAlongItsMinusZ)
{
  World world(parseWorldDescription(kWorld));
  auto down = sonar("sonar_down"), side = sonar("sonar_side"), up = sonar("sonar_up");
  ASSERT_TRUE(down && side && up);
  EXPECT_EQ(down->Type(), "sonar");
  EXPECT_EQ(down->Category(), gazebo::sensors::OTHER);
  EXPECT_EQ(down->Topic(), "~/probe/base/sonar_down/sonar");
  EXPECT_DOUBLE_EQ(down->RangeMin(), 0.0);
  EXPECT_DOUBLE_EQ(down->RangeMax(), 2.0);
  EXPECT_DOUBLE_EQ(down->Radius(), 0.2);
  EXPECT_EQ(down->Geometry(), "cone");

  std::mutex mutex;
  std::vector<gazebo::msgs::SonarStamped> published, delivered;
  gazebo::event::ConnectionPtr on_update = down->ConnectUpdate([&](gazebo::msgs::SonarStamped message) {
    std::lock_guard<std::mutex> lock(mutex);
    delivered.push_back(message);
  });
  gazebo::transport::NodePtr node(new gazebo::transport::Node());
  node->Init("sonar_world");
  const boost::function<void(ConstSonarStampedPtr&)> keep = [&](ConstSonarStampedPtr& message) {
    std::lock_guard<std::mutex> lock(mutex);
    published.push_back(*message);
  };
  gazebo::transport::SubscriberPtr subscriber = node->Subscribe(down->Topic(), keep);
  world.step(500);
  gazebo::transport::TopicManager::Instance()->WaitForAll();

  EXPECT_NEAR(down->Range(), 0.85, 0.005) << "the ground, straight down";
  EXPECT_NEAR(side->Range(), 0.9 - 0.15, 0.005) << "the wall's face at y = 0.9, the sonar at y = 0.15";
  EXPECT_DOUBLE_EQ(up->Range(), 2.0) << "nothing within its cone: its maximum";

  std::lock_guard<std::mutex> lock(mutex);
  EXPECT_NEAR(double(delivered.size()), 10.0, 1.0) << "20 Hz for 0.5 s";
  EXPECT_EQ(published.size(), delivered.size());
  ASSERT_FALSE(published.empty());
  const gazebo::msgs::Sonar& last = published.back().sonar();
  EXPECT_NEAR(last.range(), 0.85, 0.005);
  EXPECT_EQ(last.frame(), "probe::base");
  EXPECT_EQ(last.geometry(), "cone");
  ASSERT_TRUE(last.has_contact());
  EXPECT_NEAR(last.contact().z(), -0.85, 0.005) << "in the sensor's frame, down its -z";
  EXPECT_NEAR(last.world_pose().position().z(), 0.85, 1e-6);
}
