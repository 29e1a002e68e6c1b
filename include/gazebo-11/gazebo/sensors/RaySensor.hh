// sensors::RaySensor: a <sensor type="ray"> as Gazebo 11's: its rays (LaserShape), its counts,
// angles and ranges from its <ray> element, and each scan published as msgs::LaserScanStamped on
// ~/MODEL/LINK/SENSOR/scan while someone subscribes. Its scans are the simulator's (RayBridge: the
// plant's lidar, one simulation of each sensor); what differs from Gazebo's: docs/gazebo_api.md.
#pragma once

#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include <ignition/math/Angle.hh>

#include "gazebo/msgs/MessageTypes.hh"
#include "gazebo/physics/MultiRayShape.hh"
#include "gazebo/sensors/Sensor.hh"
#include "gazebo/transport/TransportTypes.hh"

namespace gazebo
{
namespace sensors
{
class GZ_SENSORS_VISIBLE RaySensor : public Sensor
{
public:
  RaySensor();
  ~RaySensor() override;

  void Load(const std::string& worldName) override;
  using Sensor::Load;
  void Init() override;
  void Fini() override;
  std::string Topic() const override;

  ignition::math::Angle AngleMin() const;
  ignition::math::Angle AngleMax() const;
  double AngleResolution() const;
  double RangeMin() const;
  double RangeMax() const;
  double RangeResolution() const;
  int RayCount() const;
  int RangeCount() const;
  int VerticalRayCount() const;
  int VerticalRangeCount() const;
  ignition::math::Angle VerticalAngleMin() const;
  ignition::math::Angle VerticalAngleMax() const;
  double VerticalAngleResolution() const;

  // The latest scan's range `index` (row after row; +inf for nothing within range), as published.
  double Range(unsigned int index) const;
  void Ranges(std::vector<double>& ranges) const;
  double Retro(unsigned int index) const;
  int Fiducial(unsigned int index) const;
  physics::MultiRayShapePtr LaserShape() const { return laser_shape_; }

  // Active as set, or while its scan topic has a subscriber (Gazebo's rule).
  bool IsActive() const override;

protected:
  // The simulator's latest scan into the shape and the message; published where subscribed.
  bool UpdateImpl(bool force) override;

private:
  physics::MultiRayShapePtr laser_shape_;
  transport::PublisherPtr scan_pub_;
  // The last scan's message (Range and Ranges read it; a plugin may from its own thread), and those
  // before it, which a scan fills again once nobody holds them (their subscribers done with them): a
  // scan is published as it is made, without a copy, and mostly without an allocation.
  mutable std::mutex mutex_;
  boost::shared_ptr<msgs::LaserScanStamped> laser_msg_;
  std::vector<boost::shared_ptr<msgs::LaserScanStamped>> spare_msgs_;
};
}  // namespace sensors
}  // namespace gazebo
