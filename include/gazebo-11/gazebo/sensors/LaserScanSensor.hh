// Not Gazebo's class: what its RaySensor and GpuRaySensor share here, where both are the simulator's
// one lidar (RayBridge) seen through a <ray> element. Gazebo's two are separate classes over
// different engines (physics rays, a rendered depth texture) with the same scan parameters and the
// same message; here they differ only in what a plugin reads besides the message (a RaySensor's
// LaserShape, a GpuRaySensor's laser frames) and in their category. Plugins use RaySensor and
// GpuRaySensor; a dynamic_pointer_cast to either tells them apart as on Gazebo.
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
class GZ_SENSORS_VISIBLE LaserScanSensor : public Sensor
{
public:
  ~LaserScanSensor() override;

  // The <ray> element's scan, and the scan topic advertised.
  void Load(const std::string& worldName) override;
  using Sensor::Load;
  void Init() override;
  void Fini() override;
  // ~/MODEL/LINK/SENSOR/scan, as both of Gazebo's.
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

  // The latest scan's ranges (row after row; +inf for nothing within range), as published.
  void Ranges(std::vector<double>& ranges) const;

  // Active as set, or while its scan topic has a subscriber (Gazebo's rule for both).
  bool IsActive() const override;

protected:
  explicit LaserScanSensor(SensorCategory category);
  // The simulator's latest scan into the shape and the message; published where subscribed.
  bool UpdateImpl(bool force) override;
  // Value `index` of the latest scan's ranges (or intensities), with Gazebo's warning before the
  // first scan and its error past the end (0 for both).
  double ScanValue(bool intensities, unsigned int index) const;
  // The latest scan's message (held, it is not filled again).
  boost::shared_ptr<const msgs::LaserScanStamped> LatestScan() const;
  // The scan parameters of its <ray> element, and the latest scan's ranges as measured.
  physics::MultiRayShapePtr laserShape;

private:
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
