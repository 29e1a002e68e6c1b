// Gazebo's sensors that measure their link's motion (AltimeterSensor, MagnetometerSensor, GpsSensor),
// as a sensor plugin of the user's own meets them: on a box yawed a quarter turn, dropped from 10 m,
// 100 m along x in a world whose <spherical_coordinates> put its origin at 47 N 8 E, 500 m up, with
// the tests' own libtest_activate_sensor.so on each (Gazebo ships no plugin library for them). After
// 0.5 s of free fall: the altimeter 1.225 m below its reference (plus its noise's mean of 0.5 m)
// falling at 4.9 m/s; the magnetometer the world's <magnetic_field> turned into the box's frame;
// the GPS 100 m from the origin in degrees of longitude (west, as Gazebo 11's frame has it), 508.775 m
// up, falling at 4.9 m/s; each at its 50 Hz, and each measurement on its topic.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <mutex>
#include <string>
#include <vector>

#include <gazebo/sensors/sensors.hh>
#include <gazebo/transport/transport.hh>

#include "bullet_plant/world.h"

using namespace bullet_plant;

namespace
{
const char* const kWorld = R"(<sdf version='1.7'><world name='link_sensor_world'>
  <physics type='ode'><max_step_size>0.001</max_step_size></physics>
  <magnetic_field>1e-5 2e-5 -4e-5</magnetic_field>
  <spherical_coordinates><surface_model>EARTH_WGS84</surface_model>
    <latitude_deg>47</latitude_deg><longitude_deg>8</longitude_deg><elevation>500</elevation>
    <heading_deg>0</heading_deg></spherical_coordinates>
  <model name='faller'><pose>100 0 10 0 0 1.5707963267948966</pose><link name='base'>
    <inertial><mass>1</mass><inertia><ixx>0.01</ixx><iyy>0.01</iyy><izz>0.01</izz></inertia></inertial>
    <collision name='c'><geometry><box><size>0.2 0.2 0.2</size></box></geometry></collision>
    <sensor type='altimeter' name='altimeter'><update_rate>50</update_rate>
      <altimeter><vertical_position><noise type='gaussian'><mean>0.5</mean><stddev>0</stddev></noise>
        </vertical_position></altimeter>
      <plugin name='a' filename='libtest_activate_sensor.so'/></sensor>
    <sensor type='magnetometer' name='magnetometer'><update_rate>50</update_rate>
      <plugin name='m' filename='libtest_activate_sensor.so'/></sensor>
    <sensor type='gps' name='gps'><update_rate>50</update_rate>
      <plugin name='g' filename='libtest_activate_sensor.so'/></sensor>
  </link></model>
</world></sdf>)";

template <class T>
std::shared_ptr<T> sensor(const std::string& name)
{
  return std::dynamic_pointer_cast<T>(gazebo::sensors::SensorManager::Instance()->GetSensor(name));
}

class GazeboLinkSensors : public testing::Test
{
protected:
  void SetUp() override
  {
    const char* path = std::getenv("GAZEBO_PLUGIN_PATH");
    setenv("GAZEBO_PLUGIN_PATH", (std::string(TEST_PLUGIN_DIR) + ":" + (path ? path : "")).c_str(), 1);
  }
};
}  // namespace

TEST_F(GazeboLinkSensors, MeasureTheirFallingLinkAtTheirRate)
{
  World plant(parseWorldDescription(kWorld));
  auto altimeter = sensor<gazebo::sensors::AltimeterSensor>("altimeter");
  auto magnetometer = sensor<gazebo::sensors::MagnetometerSensor>("magnetometer");
  auto gps = sensor<gazebo::sensors::GpsSensor>("gps");
  ASSERT_TRUE(altimeter && magnetometer && gps);
  EXPECT_EQ(altimeter->Category(), gazebo::sensors::OTHER);
  EXPECT_EQ(altimeter->GetTopic(), "~/faller/base/altimeter");
  EXPECT_DOUBLE_EQ(altimeter->ReferenceAltitude(), 10.0) << "where it was when loaded";
  auto noise = std::dynamic_pointer_cast<gazebo::sensors::GaussianNoiseModel>(
      altimeter->Noise(gazebo::sensors::ALTIMETER_POSITION_NOISE_METERS));
  ASSERT_TRUE(noise);
  EXPECT_DOUBLE_EQ(noise->GetMean(), 0.5);

  std::mutex mutex;
  int updates = 0;
  gazebo::event::ConnectionPtr counted = gps->ConnectUpdated([&] {
    std::lock_guard<std::mutex> lock(mutex);
    ++updates;
  });
  std::vector<gazebo::msgs::GPS> fixes;
  std::vector<gazebo::msgs::Altimeter> heights;
  gazebo::transport::NodePtr node(new gazebo::transport::Node());
  node->Init("link_sensor_world");
  const boost::function<void(ConstGPSPtr&)> keep_fix = [&](ConstGPSPtr& m) {
    std::lock_guard<std::mutex> lock(mutex);
    fixes.push_back(*m);
  };
  const boost::function<void(ConstAltimeterPtr&)> keep_height = [&](ConstAltimeterPtr& m) {
    std::lock_guard<std::mutex> lock(mutex);
    heights.push_back(*m);
  };
  gazebo::transport::SubscriberPtr fix_sub = node->Subscribe("~/faller/base/gps", keep_fix);
  gazebo::transport::SubscriberPtr height_sub = node->Subscribe(altimeter->GetTopic(), keep_height);
  plant.step(500);
  gazebo::transport::TopicManager::Instance()->WaitForAll();
  std::lock_guard<std::mutex> lock(mutex);

  // free fall for 0.5 s (the last measurement at 0.5 s): 1.225 m down at 4.9 m/s
  const double fall = 0.5 * 9.8 * 0.25, speed = 9.8 * 0.5;
  EXPECT_NEAR(altimeter->Altitude(), -fall + 0.5, 0.02) << "its noise's mean of 0.5 m added";
  EXPECT_NEAR(altimeter->VerticalVelocity(), -speed, 0.02);
  EXPECT_NEAR(altimeter->LastMeasurementTime().Double(), 0.5, 1e-9);

  // the field (1, 2, -4) e-5 T in a frame turned a quarter turn about z: (2, -1, -4) e-5
  const ignition::math::Vector3d field = magnetometer->MagneticField();
  EXPECT_NEAR(field.X(), 2e-5, 1e-9);
  EXPECT_NEAR(field.Y(), -1e-5, 1e-9);
  EXPECT_NEAR(field.Z(), -4e-5, 1e-9);

  // 100 m along x at 47 N, ~509 m up: 100 / ((N + h) cos 47) rad of longitude, N the WGS84 prime
  // vertical radius there; west, as Gazebo 11 has it: at heading 0 its world's x points west and y south (a heading of
  // 180 degrees makes them east and north, as the SDF spec means)
  const double a = 6378137.0, f = 1 / 298.257223563, e2 = f * (2 - f), lat = 47 * M_PI / 180;
  const double prime_vertical = a / std::sqrt(1 - e2 * std::sin(lat) * std::sin(lat));
  const double h = 500 + 10 - 0.5 * 9.8 * 0.25;
  EXPECT_NEAR(gps->Longitude().Degree(), 8 - 100 / ((prime_vertical + h) * std::cos(lat)) * 180 / M_PI, 1e-8);
  EXPECT_NEAR(gps->Latitude().Degree(), 47, 1e-7);
  EXPECT_NEAR(gps->Altitude(), 500 + 10 - fall, 0.02);
  EXPECT_NEAR(gps->VelocityUp(), -speed, 0.02);
  EXPECT_NEAR(gps->VelocityEast(), 0.0, 1e-6);
  EXPECT_NEAR(gps->VelocityNorth(), 0.0, 1e-6);

  // 50 Hz for 0.5 s, each measurement on its topic
  EXPECT_GE(updates, 25);
  EXPECT_LE(updates, 26);
  EXPECT_EQ(fixes.size(), size_t(updates));
  ASSERT_FALSE(fixes.empty());
  EXPECT_EQ(fixes.back().link_name(), "faller::base");
  EXPECT_DOUBLE_EQ(fixes.back().altitude(), gps->Altitude());
  ASSERT_FALSE(heights.empty());
  EXPECT_DOUBLE_EQ(heights.back().vertical_reference(), 10.0);
}

TEST_F(GazeboLinkSensors, SetReferenceAltitudeMovesTheAltitudeWithIt)
{
  World plant(parseWorldDescription(kWorld));
  auto altimeter = sensor<gazebo::sensors::AltimeterSensor>("altimeter");
  ASSERT_TRUE(altimeter);
  plant.step(100);
  const double before = altimeter->Altitude();
  altimeter->SetReferenceAltitude(0.0);
  EXPECT_DOUBLE_EQ(altimeter->ReferenceAltitude(), 0.0);
  EXPECT_NEAR(altimeter->Altitude(), before + 10.0, 1e-9);
}
