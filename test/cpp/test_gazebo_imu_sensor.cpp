// Gazebo's ImuSensor over the plant's IMU, as a sensor plugin of the user's own meets it: a
// <sensor type="imu"> whose <plugin> file is found (here Gazebo's own libImuSensorPlugin.so) is a
// sensors::ImuSensor in SensorManager; at rest on the ground, yawed 0.5 rad, it measures gravity's
// reaction up, no rotation, and its orientation relative to its own at load (identity) until its
// reference is the world's (as gazebo_ros_imu_sensor sets it: REP 145); each measurement at its
// <update_rate> is a msgs::IMU on ~/MODEL/LINK/SENSOR/imu while subscribed.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <mutex>
#include <string>
#include <vector>

#include <gazebo/sensors/sensors.hh>
#include <gazebo/transport/transport.hh>

#include "bullet_plant/world.h"

using namespace bullet_plant;

namespace
{
const char* const kWorld = R"(<sdf version='1.7'><world name='imu_world'>
  <physics type='ode'><max_step_size>0.001</max_step_size></physics>
  <include><uri>model://ground_plane</uri></include>
  <model name='probe'><pose>0 0 0.1 0 0 0.5</pose><link name='base'>
    <inertial><mass>2</mass><inertia><ixx>0.01</ixx><iyy>0.01</iyy><izz>0.01</izz></inertia></inertial>
    <collision name='c'><geometry><box><size>0.2 0.2 0.2</size></box></geometry></collision>
    <sensor type='imu' name='imu'><update_rate>50</update_rate>
      <plugin name='inertial' filename='libImuSensorPlugin.so'/>
    </sensor>
  </link></model>
</world></sdf>)";

std::shared_ptr<gazebo::sensors::ImuSensor> imu()
{
  return std::dynamic_pointer_cast<gazebo::sensors::ImuSensor>(
      gazebo::sensors::SensorManager::Instance()->GetSensor("imu"));
}
}  // namespace

TEST(GazeboImuSensor, MeasuresThePlantsImuRelativeToItsReference)
{
  World world(parseWorldDescription(kWorld));
  std::shared_ptr<gazebo::sensors::ImuSensor> sensor = imu();
  ASSERT_TRUE(sensor);
  EXPECT_EQ(sensor->ScopedName(), "imu_world::probe::base::imu");
  EXPECT_EQ(sensor->Type(), "imu");
  EXPECT_EQ(sensor->Category(), gazebo::sensors::OTHER);
  EXPECT_DOUBLE_EQ(sensor->UpdateRate(), 50.0);
  std::atomic<int> updates{0};
  gazebo::event::ConnectionPtr on_update = sensor->ConnectUpdated([&] { ++updates; });
  sensor->SetActive(true);
  world.step(1000);
  EXPECT_NEAR(updates, 50, 1) << "50 Hz over 1 s";
  EXPECT_NEAR(sensor->LinearAcceleration().Z(), 9.8, 0.05) << "gravity's reaction, up";
  EXPECT_NEAR(sensor->LinearAcceleration().X(), 0.0, 0.05);
  EXPECT_NEAR(sensor->AngularVelocity().Length(), 0.0, 1e-3);
  EXPECT_NEAR(sensor->Orientation().Euler().Z(), 0.0, 1e-3) << "relative to its orientation at load";
  EXPECT_NEAR(sensor->LastMeasurementTime().Double(), world.time(), 0.021);
  EXPECT_EQ(sensor->ImuMessage().entity_name(), "probe::base");

  sensor->SetWorldToReferenceOrientation(ignition::math::Quaterniond::Identity);
  world.step(100);
  EXPECT_NEAR(sensor->Orientation().Euler().Z(), 0.5, 1e-3) << "REP 145: the world's frame";
}

TEST(GazeboImuSensor, PublishesEachMeasurementWhileSubscribed)
{
  World world(parseWorldDescription(kWorld));
  std::shared_ptr<gazebo::sensors::ImuSensor> sensor = imu();
  ASSERT_TRUE(sensor);
  EXPECT_FALSE(sensor->IsActive());
  std::mutex mutex;
  std::vector<gazebo::msgs::IMU> received;
  gazebo::transport::NodePtr node(new gazebo::transport::Node());
  node->Init("imu_world");
  const boost::function<void(ConstIMUPtr&)> keep = [&](ConstIMUPtr& message) {
    std::lock_guard<std::mutex> lock(mutex);
    received.push_back(*message);
  };
  gazebo::transport::SubscriberPtr subscriber = node->Subscribe("~/probe/base/imu/imu", keep);
  EXPECT_TRUE(sensor->IsActive()) << "its topic subscribed";
  world.step(500);
  gazebo::transport::TopicManager::Instance()->WaitForAll();
  std::lock_guard<std::mutex> lock(mutex);
  EXPECT_NEAR(static_cast<int>(received.size()), 25, 1);
  ASSERT_FALSE(received.empty());
  EXPECT_NEAR(received.back().linear_acceleration().z(), 9.8, 0.05);
  for (size_t i = 1; i < received.size(); ++i)
    EXPECT_NEAR(gazebo::msgs::Convert(received[i].stamp()).Double() - gazebo::msgs::Convert(received[i - 1].stamp()).Double(),
                0.02, 1e-9);
}

// Its <imu>'s noise models, Gazebo's: a mean of 0.2 rad/s on z's rate and -0.5 m/s^2 on z's
// acceleration (no spread, so the values are exact) on the noisy values, none on the noise-free ones.
TEST(GazeboImuSensor, AppliesItsImuElementsNoiseModels)
{
  std::string noisy = kWorld;
  const std::string plain = "<sensor type='imu' name='imu'><update_rate>50</update_rate>";
  noisy.replace(noisy.find(plain), plain.size(),
                plain + "<imu><angular_velocity><z><noise type='gaussian'><mean>0.2</mean><stddev>0</stddev></noise></z>"
                        "</angular_velocity><linear_acceleration><z><noise type='gaussian'><mean>-0.5</mean>"
                        "<stddev>0</stddev></noise></z></linear_acceleration></imu>");
  World world(parseWorldDescription(noisy));
  std::shared_ptr<gazebo::sensors::ImuSensor> sensor = imu();
  ASSERT_TRUE(sensor);
  auto rate_noise = std::dynamic_pointer_cast<gazebo::sensors::GaussianNoiseModel>(
      sensor->Noise(gazebo::sensors::IMU_ANGVEL_Z_NOISE_RADIANS_PER_S));
  ASSERT_TRUE(rate_noise);
  EXPECT_DOUBLE_EQ(rate_noise->GetMean(), 0.2);
  sensor->SetActive(true);
  world.step(500);
  EXPECT_NEAR(sensor->AngularVelocity().Z(), 0.2, 1e-3);
  EXPECT_NEAR(sensor->AngularVelocity(true).Z(), 0.0, 1e-3);
  EXPECT_NEAR(sensor->AngularVelocity().X(), 0.0, 1e-3) << "x has no noise model";
  EXPECT_NEAR(sensor->LinearAcceleration().Z(), 9.8 - 0.5, 0.05);
  EXPECT_NEAR(sensor->LinearAcceleration(true).Z(), 9.8, 0.05);
  EXPECT_NEAR(sensor->ImuMessage().angular_velocity().z(), 0.2, 1e-3) << "the message carries the noisy values";
}
