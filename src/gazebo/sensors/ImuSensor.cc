// sensors::ImuSensor (gazebo/sensors/ImuSensor.hh).
#include "gazebo/sensors/ImuSensor.hh"

#include <boost/algorithm/string/replace.hpp>

#include "gazebo/msgs/msgs.hh"
#include "gazebo/transport/Node.hh"
#include "gazebo/transport/Publisher.hh"
#include "link_sensor.h"

namespace gazebo
{
namespace sensors
{
ImuSensor::ImuSensor() : Sensor(OTHER) {}

ImuSensor::~ImuSensor() = default;

void ImuSensor::Load(const std::string& worldName)
{
  Sensor::Load(worldName);
  {
    std::lock_guard<std::mutex> lock(mutex_);
    msgs::Set(imu_msg_.mutable_orientation(), ignition::math::Quaterniond::Identity);
  }
  SetReferencePose();
  if (!world)
    return;
  // its <imu><topic>, else ~/MODEL/LINK/SENSOR/imu (Gazebo's)
  const sdf::ElementPtr imu = sdf->HasElement("imu") ? sdf->GetElement("imu") : nullptr;
  std::string topic = imu && imu->HasElement("topic") ? imu->Get<std::string>("topic") : "__default_topic__";
  if (topic == "__default_topic__")
  {
    topic = "~/" + ParentName() + "/" + Name() + "/imu";
    boost::replace_all(topic, "::", "/");
  }
  imu_pub_ = node->Advertise<msgs::IMU>(topic, 500);
  const sdf::ElementPtr rates = imu && imu->HasElement("angular_velocity") ? imu->GetElement("angular_velocity") : nullptr;
  detail::loadNoise(noises, IMU_ANGVEL_X_NOISE_RADIANS_PER_S, rates, "x");
  detail::loadNoise(noises, IMU_ANGVEL_Y_NOISE_RADIANS_PER_S, rates, "y");
  detail::loadNoise(noises, IMU_ANGVEL_Z_NOISE_RADIANS_PER_S, rates, "z");
  const sdf::ElementPtr accelerations =
      imu && imu->HasElement("linear_acceleration") ? imu->GetElement("linear_acceleration") : nullptr;
  detail::loadNoise(noises, IMU_LINACC_X_NOISE_METERS_PER_S_SQR, accelerations, "x");
  detail::loadNoise(noises, IMU_LINACC_Y_NOISE_METERS_PER_S_SQR, accelerations, "y");
  detail::loadNoise(noises, IMU_LINACC_Z_NOISE_METERS_PER_S_SQR, accelerations, "z");
}

void ImuSensor::Init() { Sensor::Init(); }

void ImuSensor::Fini()
{
  imu_pub_.reset();
  Sensor::Fini();
}

msgs::IMU ImuSensor::ImuMessage() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return imu_msg_;
}

ignition::math::Vector3d ImuSensor::AngularVelocity(bool _noiseFree) const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return _noiseFree ? angular_velocity_ : msgs::ConvertIgn(imu_msg_.angular_velocity());
}

ignition::math::Vector3d ImuSensor::LinearAcceleration(bool _noiseFree) const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return _noiseFree ? linear_acceleration_ : msgs::ConvertIgn(imu_msg_.linear_acceleration());
}

ignition::math::Quaterniond ImuSensor::Orientation() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return msgs::ConvertIgn(imu_msg_.orientation());
}

void ImuSensor::SetReferencePose()
{
  if (bridge)
    SetWorldToReferenceOrientation(bridge->worldPose().Rot());
}

void ImuSensor::SetWorldToReferenceOrientation(const ignition::math::Quaterniond& _orientation)
{
  std::lock_guard<std::mutex> lock(mutex_);
  world_to_reference_ = _orientation;
}

bool ImuSensor::IsActive() const { return Sensor::IsActive() || (imu_pub_ && imu_pub_->HasConnections()); }

bool ImuSensor::UpdateImpl(bool /*force*/)
{
  const auto* imu = dynamic_cast<const ImuBridge*>(bridge.get());
  if (!imu)
    return false;
  const common::Time stamp = imu->measurementTime();
  if (stamp == lastMeasurementTime)  // Gazebo's: no new link data, no measurement
    return false;
  const double dt = (stamp - lastMeasurementTime).Double();
  lastMeasurementTime = stamp;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    imu_msg_.set_entity_name(ParentName());
    msgs::Set(imu_msg_.mutable_stamp(), stamp);
    angular_velocity_ = imu->angularVelocity();
    linear_acceleration_ = imu->linearAcceleration();
    // each axis with its noise model, where it has one
    const auto noisy = [&](SensorNoiseType type, double value) { return detail::withNoise(noises, type, value, dt); };
    msgs::Set(imu_msg_.mutable_angular_velocity(),
              {noisy(IMU_ANGVEL_X_NOISE_RADIANS_PER_S, angular_velocity_.X()),
               noisy(IMU_ANGVEL_Y_NOISE_RADIANS_PER_S, angular_velocity_.Y()),
               noisy(IMU_ANGVEL_Z_NOISE_RADIANS_PER_S, angular_velocity_.Z())});
    msgs::Set(imu_msg_.mutable_linear_acceleration(),
              {noisy(IMU_LINACC_X_NOISE_METERS_PER_S_SQR, linear_acceleration_.X()),
               noisy(IMU_LINACC_Y_NOISE_METERS_PER_S_SQR, linear_acceleration_.Y()),
               noisy(IMU_LINACC_Z_NOISE_METERS_PER_S_SQR, linear_acceleration_.Z())});
    msgs::Set(imu_msg_.mutable_orientation(), world_to_reference_.Inverse() * imu->orientation());
  }
  if (imu_pub_ && imu_pub_->HasConnections())
  {
    std::lock_guard<std::mutex> lock(mutex_);
    imu_pub_->Publish(imu_msg_);
  }
  return true;
}
}  // namespace sensors
}  // namespace gazebo
