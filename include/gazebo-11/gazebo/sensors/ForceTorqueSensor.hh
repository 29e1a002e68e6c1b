// sensors::ForceTorqueSensor: a <sensor type="force_torque"> in a <joint>, as Gazebo 11's: its
// joint's wrench (physics::Joint::GetForceTorque) in the frame its <force_torque><frame> names
// (child, the default; parent; or sensor) and the direction <measure_direction> names
// (child_to_parent, the default, or parent_to_child), each measurement a msgs::WrenchStamped on
// Topic() and to ConnectUpdate's subscribers. Its parent is the joint (MODEL::JOINT). What differs:
// docs/gazebo_api.md.
#pragma once

#include <functional>
#include <mutex>
#include <string>

#include <ignition/math/Matrix3.hh>
#include <ignition/math/Vector3.hh>

#include "gazebo/common/Event.hh"
#include "gazebo/msgs/MessageTypes.hh"
#include "gazebo/physics/PhysicsTypes.hh"
#include "gazebo/sensors/Sensor.hh"
#include "gazebo/transport/TransportTypes.hh"

namespace gazebo
{
namespace sensors
{
class GZ_SENSORS_VISIBLE ForceTorqueSensor : public Sensor
{
public:
  ForceTorqueSensor();
  ~ForceTorqueSensor() override;
  // Its joint found in the world by its parent's name (Gazebo's error where that is no joint), its
  // wrench topic advertised.
  void Load(const std::string& _worldName) override;
  // Its <force_torque> frame and measure direction (an unknown value warned about and the default
  // taken, as Gazebo's).
  void Load(const std::string& _worldName, sdf::ElementPtr _sdf) override;
  // Its joint provides feedback from now on.
  void Init() override;
  // ~/MODEL/JOINT/SENSOR/wrench
  std::string Topic() const override;
  // The last measurement's, in its frame (N, N m).
  ignition::math::Vector3d Torque() const;
  ignition::math::Vector3d Force() const;
  physics::JointPtr Joint() const;
  // Set active, or its topic has a subscriber.
  bool IsActive() const override;
  // Each measurement, after it is taken.
  event::ConnectionPtr ConnectUpdate(std::function<void(msgs::WrenchStamped)> _subscriber);

protected:
  bool UpdateImpl(const bool _force) override;
  void Fini() override;

private:
  enum class MeasureFrame
  {
    PARENT_LINK,
    CHILD_LINK,
    SENSOR
  };
  mutable std::mutex mutex_;
  physics::JointPtr joint_;
  MeasureFrame frame_ = MeasureFrame::CHILD_LINK;
  bool parent_to_child_ = false;
  // From the child link's axes to the sensor's (frame "sensor").
  ignition::math::Matrix3d rotation_sensor_child_ = ignition::math::Matrix3d::Identity;
  msgs::WrenchStamped message_;
  transport::PublisherPtr pub_;
  event::EventT<void(msgs::WrenchStamped)> update_;
};
}  // namespace sensors
}  // namespace gazebo
