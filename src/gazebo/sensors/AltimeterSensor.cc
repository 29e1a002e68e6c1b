// sensors::AltimeterSensor (gazebo/sensors/AltimeterSensor.hh).
#include "gazebo/sensors/AltimeterSensor.hh"

#include "gazebo/msgs/msgs.hh"
#include "gazebo/transport/Node.hh"
#include "gazebo/transport/Publisher.hh"
#include "link_sensor.h"

namespace gazebo
{
namespace sensors
{
AltimeterSensor::AltimeterSensor() : Sensor(OTHER) {}

AltimeterSensor::~AltimeterSensor() = default;

std::string AltimeterSensor::GetTopic() const { return detail::linkSensorTopic(ParentName(), Name(), sdf); }

void AltimeterSensor::Load(const std::string& _worldName)
{
  Sensor::Load(_worldName);
  if (!world)
    return;
  link_ = detail::linkOf(world, ParentName(), Name());
  pub_ = node->Advertise<msgs::Altimeter>(GetTopic(), 50);
  // (sensor.sdf gives it, with its defaults, where the <sensor> has none)
  const sdf::ElementPtr altimeter = sdf->GetElement("altimeter");
  if (!altimeter)
    gzerr << "Missing <altimeter> element in sensor[" << Name() << "]\n";
  detail::loadNoise(noises, ALTIMETER_POSITION_NOISE_METERS, altimeter, "vertical_position");
  detail::loadNoise(noises, ALTIMETER_VELOCITY_NOISE_METERS_PER_S, altimeter, "vertical_velocity");
  std::lock_guard<std::mutex> lock(mutex_);
  message_.set_vertical_reference(link_ ? (pose + link_->WorldPose()).Pos().Z() : 0.0);
  message_.set_vertical_position(0.0);
  message_.set_vertical_velocity(0.0);
}

void AltimeterSensor::Init() { Sensor::Init(); }

void AltimeterSensor::Fini()
{
  pub_.reset();
  link_.reset();
  Sensor::Fini();
}

bool AltimeterSensor::UpdateImpl(const bool /*_force*/)
{
  std::lock_guard<std::mutex> lock(mutex_);
  if (link_)
  {
    const double height = (pose + link_->WorldPose()).Pos().Z() - message_.vertical_reference();
    message_.set_vertical_position(detail::withNoise(noises, ALTIMETER_POSITION_NOISE_METERS, height));
    message_.set_vertical_velocity(
        detail::withNoise(noises, ALTIMETER_VELOCITY_NOISE_METERS_PER_S, link_->WorldLinearVel(pose.Pos()).Z()));
  }
  lastMeasurementTime = world->SimTime();
  msgs::Set(message_.mutable_time(), lastMeasurementTime);
  if (pub_)
    pub_->Publish(message_);
  return true;
}

double AltimeterSensor::Altitude() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return message_.vertical_position();
}

double AltimeterSensor::VerticalVelocity() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return message_.vertical_velocity();
}

double AltimeterSensor::ReferenceAltitude() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return message_.vertical_reference();
}

void AltimeterSensor::SetReferenceAltitude(const double _refAlt)
{
  std::lock_guard<std::mutex> lock(mutex_);
  // the altitude follows the new reference at once, as Gazebo's
  message_.set_vertical_position(message_.vertical_position() + message_.vertical_reference() - _refAlt);
  message_.set_vertical_reference(_refAlt);
}
}  // namespace sensors
}  // namespace gazebo
