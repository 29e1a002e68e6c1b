// sensors::MagnetometerSensor: a <sensor type="magnetometer"> as Gazebo 11's: the world's
// <magnetic_field> in the sensor's frame, each axis with its <magnetometer>'s <x>, <y>, <z> noise,
// from its link as the simulator moves it; each measurement a msgs::Magnetometer on GetTopic().
#pragma once

#include <mutex>
#include <string>

#include <ignition/math/Vector3.hh>

#include "gazebo/msgs/MessageTypes.hh"
#include "gazebo/physics/PhysicsTypes.hh"
#include "gazebo/sensors/Sensor.hh"
#include "gazebo/transport/TransportTypes.hh"

namespace gazebo
{
namespace sensors
{
class GZ_SENSORS_VISIBLE MagnetometerSensor : public Sensor
{
public:
  MagnetometerSensor();
  ~MagnetometerSensor() override;
  void Load(const std::string& _worldName) override;
  using Sensor::Load;
  void Init() override;
  void Fini() override;
  // ~/MODEL/LINK/SENSOR, and /<topic> where it has one
  virtual std::string GetTopic() const;
  // tesla, the sensor's frame
  ignition::math::Vector3d MagneticField() const;

protected:
  bool UpdateImpl(const bool _force) override;

private:
  mutable std::mutex mutex_;
  physics::LinkPtr link_;
  msgs::Magnetometer message_;
  transport::PublisherPtr pub_;
};
}  // namespace sensors
}  // namespace gazebo
