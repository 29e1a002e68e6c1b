// sensors::AltimeterSensor: a <sensor type="altimeter"> as Gazebo 11's: its height above its
// reference (where it was when loaded) and its vertical speed, each with its <altimeter>'s
// <vertical_position> and <vertical_velocity> noise, from its link as the simulator moves it;
// each measurement a msgs::Altimeter on GetTopic(). What differs: docs/gazebo_api.md.
#pragma once

#include <mutex>
#include <string>

#include "gazebo/msgs/MessageTypes.hh"
#include "gazebo/physics/PhysicsTypes.hh"
#include "gazebo/sensors/Sensor.hh"
#include "gazebo/transport/TransportTypes.hh"

namespace gazebo
{
namespace sensors
{
class GZ_SENSORS_VISIBLE AltimeterSensor : public Sensor
{
public:
  AltimeterSensor();
  ~AltimeterSensor() override;
  // Its link, its noise models, its reference; its topic advertised.
  void Load(const std::string& _worldName) override;
  using Sensor::Load;
  void Init() override;
  void Fini() override;
  // ~/MODEL/LINK/SENSOR, and /<topic> where it has one
  virtual std::string GetTopic() const;
  // m above the reference; m/s up
  double Altitude() const;
  double VerticalVelocity() const;
  double ReferenceAltitude() const;
  void SetReferenceAltitude(const double _refAlt);

protected:
  bool UpdateImpl(const bool _force) override;

private:
  mutable std::mutex mutex_;
  physics::LinkPtr link_;
  msgs::Altimeter message_;
  transport::PublisherPtr pub_;
};
}  // namespace sensors
}  // namespace gazebo
