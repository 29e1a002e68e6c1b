// sensors::GpsSensor: a <sensor type="gps"> as Gazebo 11's: its position as latitude, longitude and
// altitude on the world's <spherical_coordinates> (World::SphericalCoords) and its velocity east,
// north and up, with its <gps>'s <position_sensing> and <velocity_sensing> noise (horizontal,
// vertical), from its link as the simulator moves it; each measurement a msgs::GPS on
// ~/MODEL/LINK/SENSOR (and /<topic> where it has one).
#pragma once

#include <mutex>
#include <string>

#include <ignition/math/Angle.hh>
#include <ignition/math/Vector3.hh>

#include "gazebo/common/CommonTypes.hh"
#include "gazebo/msgs/MessageTypes.hh"
#include "gazebo/physics/PhysicsTypes.hh"
#include "gazebo/sensors/Sensor.hh"
#include "gazebo/transport/TransportTypes.hh"

namespace gazebo
{
namespace sensors
{
class GZ_SENSORS_VISIBLE GpsSensor : public Sensor
{
public:
  GpsSensor();
  ~GpsSensor() override;
  void Load(const std::string& _worldName) override;
  using Sensor::Load;
  void Init() override;
  void Fini() override;
  ignition::math::Angle Longitude() const;
  ignition::math::Angle Latitude() const;
  double Altitude() const;
  // east, north, up (m/s)
  ignition::math::Vector3d VelocityENU() const;
  double VelocityEast() const;
  double VelocityNorth() const;
  double VelocityUp() const;

protected:
  bool UpdateImpl(const bool _force) override;

private:
  mutable std::mutex mutex_;
  physics::LinkPtr link_;
  common::SphericalCoordinatesPtr spherical_;
  msgs::GPS message_;
  transport::PublisherPtr pub_;
};
}  // namespace sensors
}  // namespace gazebo
