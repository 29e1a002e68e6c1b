// sensors::GpsSensor (gazebo/sensors/GpsSensor.hh).
#include "gazebo/sensors/GpsSensor.hh"

#include "gazebo/common/SphericalCoordinates.hh"
#include "gazebo/msgs/msgs.hh"
#include "gazebo/transport/Node.hh"
#include "gazebo/transport/Publisher.hh"
#include "link_sensor.h"

namespace gazebo
{
namespace sensors
{
GpsSensor::GpsSensor() : Sensor(OTHER) {}

GpsSensor::~GpsSensor() = default;

void GpsSensor::Load(const std::string& _worldName)
{
  Sensor::Load(_worldName);
  if (!world)
    return;
  link_ = detail::linkOf(world, ParentName(), Name());
  pub_ = node->Advertise<msgs::GPS>(detail::linkSensorTopic(ParentName(), Name(), sdf), 50);
  const sdf::ElementPtr gps = sdf->GetElement("gps");
  const sdf::ElementPtr position = gps->HasElement("position_sensing") ? gps->GetElement("position_sensing") : nullptr;
  const sdf::ElementPtr velocity = gps->HasElement("velocity_sensing") ? gps->GetElement("velocity_sensing") : nullptr;
  // (Gazebo's draws the horizontal noise of latitude and longitude from two models of one element)
  detail::loadNoise(noises, GPS_POSITION_LATITUDE_NOISE_METERS, position, "horizontal");
  detail::loadNoise(noises, GPS_POSITION_LONGITUDE_NOISE_METERS, position, "horizontal");
  detail::loadNoise(noises, GPS_POSITION_ALTITUDE_NOISE_METERS, position, "vertical");
  detail::loadNoise(noises, GPS_VELOCITY_LATITUDE_NOISE_METERS, velocity, "horizontal");
  detail::loadNoise(noises, GPS_VELOCITY_LONGITUDE_NOISE_METERS, velocity, "horizontal");
  detail::loadNoise(noises, GPS_VELOCITY_ALTITUDE_NOISE_METERS, velocity, "vertical");
  std::lock_guard<std::mutex> lock(mutex_);
  message_.set_link_name(ParentName());
  message_.set_latitude_deg(0.0);
  message_.set_longitude_deg(0.0);
  message_.set_altitude(0.0);
}

void GpsSensor::Init()
{
  Sensor::Init();
  if (world)
    spherical_ = world->SphericalCoords();
}

void GpsSensor::Fini()
{
  pub_.reset();
  link_.reset();
  spherical_.reset();
  Sensor::Fini();
}

bool GpsSensor::UpdateImpl(const bool /*_force*/)
{
  std::lock_guard<std::mutex> lock(mutex_);
  if (link_ && spherical_)
  {
    // the position's noise in the world's frame, before it becomes latitude, longitude, altitude
    ignition::math::Vector3d position = (pose + link_->WorldPose()).Pos();
    position.X(detail::withNoise(noises, GPS_POSITION_LATITUDE_NOISE_METERS, position.X()));
    position.Y(detail::withNoise(noises, GPS_POSITION_LONGITUDE_NOISE_METERS, position.Y()));
    position.Z(detail::withNoise(noises, GPS_POSITION_ALTITUDE_NOISE_METERS, position.Z()));
    const ignition::math::Vector3d spherical = spherical_->SphericalFromLocal(position);
    message_.set_latitude_deg(spherical.X());
    message_.set_longitude_deg(spherical.Y());
    message_.set_altitude(spherical.Z());
    // the velocity's after it becomes east, north, up
    ignition::math::Vector3d velocity = spherical_->GlobalFromLocal(link_->WorldLinearVel(pose.Pos()));
    message_.set_velocity_east(detail::withNoise(noises, GPS_VELOCITY_LATITUDE_NOISE_METERS, velocity.X()));
    message_.set_velocity_north(detail::withNoise(noises, GPS_VELOCITY_LONGITUDE_NOISE_METERS, velocity.Y()));
    message_.set_velocity_up(detail::withNoise(noises, GPS_VELOCITY_ALTITUDE_NOISE_METERS, velocity.Z()));
  }
  lastMeasurementTime = world->SimTime();
  msgs::Set(message_.mutable_time(), lastMeasurementTime);
  if (pub_)
    pub_->Publish(message_);
  return true;
}

ignition::math::Angle GpsSensor::Longitude() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return IGN_DTOR(message_.longitude_deg());
}

ignition::math::Angle GpsSensor::Latitude() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return IGN_DTOR(message_.latitude_deg());
}

double GpsSensor::Altitude() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return message_.altitude();
}

ignition::math::Vector3d GpsSensor::VelocityENU() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return {message_.velocity_east(), message_.velocity_north(), message_.velocity_up()};
}

double GpsSensor::VelocityEast() const { return VelocityENU().X(); }

double GpsSensor::VelocityNorth() const { return VelocityENU().Y(); }

double GpsSensor::VelocityUp() const { return VelocityENU().Z(); }
}  // namespace sensors
}  // namespace gazebo
