// sensors::MagnetometerSensor (gazebo/sensors/MagnetometerSensor.hh).
#include "gazebo/sensors/MagnetometerSensor.hh"

#include "gazebo/msgs/msgs.hh"
#include "gazebo/transport/Node.hh"
#include "gazebo/transport/Publisher.hh"
#include "link_sensor.h"

namespace gazebo
{
namespace sensors
{
MagnetometerSensor::MagnetometerSensor() : Sensor(OTHER) {}

MagnetometerSensor::~MagnetometerSensor() = default;

std::string MagnetometerSensor::GetTopic() const { return detail::linkSensorTopic(ParentName(), Name(), sdf); }

void MagnetometerSensor::Load(const std::string& _worldName)
{
  Sensor::Load(_worldName);
  if (!world)
    return;
  link_ = detail::linkOf(world, ParentName(), Name());
  pub_ = node->Advertise<msgs::Magnetometer>(GetTopic(), 50);
  // (sensor.sdf gives it, with its defaults, where the <sensor> has none)
  const sdf::ElementPtr magnetometer = sdf->GetElement("magnetometer");
  if (!magnetometer)
    gzerr << "Missing <magnetometer> element in sensor[" << Name() << "]\n";
  detail::loadNoise(noises, MAGNETOMETER_X_NOISE_TESLA, magnetometer, "x");
  detail::loadNoise(noises, MAGNETOMETER_Y_NOISE_TESLA, magnetometer, "y");
  detail::loadNoise(noises, MAGNETOMETER_Z_NOISE_TESLA, magnetometer, "z");
  std::lock_guard<std::mutex> lock(mutex_);
  msgs::Set(message_.mutable_field_tesla(), ignition::math::Vector3d::Zero);
}

void MagnetometerSensor::Init() { Sensor::Init(); }

void MagnetometerSensor::Fini()
{
  pub_.reset();
  link_.reset();
  Sensor::Fini();
}

bool MagnetometerSensor::UpdateImpl(const bool /*_force*/)
{
  std::lock_guard<std::mutex> lock(mutex_);
  if (link_)
  {
    // the world's field in the sensor's frame, then each axis's noise
    const ignition::math::Pose3d sensor = pose + link_->WorldPose();
    ignition::math::Vector3d field = sensor.Rot().Inverse().RotateVector(world->MagneticField());
    field.X(detail::withNoise(noises, MAGNETOMETER_X_NOISE_TESLA, field.X()));
    field.Y(detail::withNoise(noises, MAGNETOMETER_Y_NOISE_TESLA, field.Y()));
    field.Z(detail::withNoise(noises, MAGNETOMETER_Z_NOISE_TESLA, field.Z()));
    msgs::Set(message_.mutable_field_tesla(), field);
  }
  lastMeasurementTime = world->SimTime();
  msgs::Set(message_.mutable_time(), lastMeasurementTime);
  if (pub_)
    pub_->Publish(message_);
  return true;
}

ignition::math::Vector3d MagnetometerSensor::MagneticField() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return msgs::ConvertIgn(message_.field_tesla());
}
}  // namespace sensors
}  // namespace gazebo
