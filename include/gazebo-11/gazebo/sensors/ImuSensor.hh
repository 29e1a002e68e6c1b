// sensors::ImuSensor: a <sensor type="imu"> as Gazebo 11's: its orientation relative to a reference
// (its own at load, until SetWorldToReferenceOrientation or SetReferencePose changes it), its angular
// velocity and linear acceleration in its own frame, each axis with its <imu>'s <angular_velocity>
// and <linear_acceleration> <x>, <y>, <z> <noise> (Gazebo's noise models), each measurement a
// msgs::IMU on ~/MODEL/LINK/SENSOR/imu (or its <imu><topic>) while someone subscribes. Its
// measurements are the simulator's (ImuBridge: the plant's IMU, one simulation of each sensor,
// noise-free); what differs from Gazebo's: docs/gazebo_api.md.
#pragma once

#include <mutex>
#include <string>

#include <ignition/math/Quaternion.hh>
#include <ignition/math/Vector3.hh>

#include "gazebo/msgs/MessageTypes.hh"
#include "gazebo/sensors/Sensor.hh"
#include "gazebo/transport/TransportTypes.hh"

namespace gazebo
{
namespace sensors
{
class GZ_SENSORS_VISIBLE ImuSensor : public Sensor
{
public:
  ImuSensor();
  ~ImuSensor() override;

  // The reference (its world orientation now), its topic and its noise models.
  void Load(const std::string& worldName) override;
  using Sensor::Load;
  void Init() override;
  void Fini() override;

  // The latest measurement's message, and its parts (with their noise, or without where asked).
  msgs::IMU ImuMessage() const;
  ignition::math::Vector3d AngularVelocity(bool _noiseFree = false) const;
  ignition::math::Vector3d LinearAcceleration(bool _noiseFree = false) const;
  ignition::math::Quaterniond Orientation() const;

  // The reference orientations are measured from: its world orientation now, or one given (REP 145's
  // world frame: the identity, as gazebo_ros_imu_sensor sets it).
  void SetReferencePose();
  void SetWorldToReferenceOrientation(const ignition::math::Quaterniond& _orientation);

  // Active as set, or while its topic has a subscriber (Gazebo's rule).
  bool IsActive() const override;

protected:
  bool UpdateImpl(bool force) override;

private:
  transport::PublisherPtr imu_pub_;
  mutable std::mutex mutex_;
  msgs::IMU imu_msg_;
  ignition::math::Vector3d angular_velocity_, linear_acceleration_;  // noise-free
  ignition::math::Quaterniond world_to_reference_;
};
}  // namespace sensors
}  // namespace gazebo
