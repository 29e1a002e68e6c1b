// sensors::RaySensor: a <sensor type="ray"> as Gazebo 11's: its rays (LaserShape), its counts,
// angles and ranges from its <ray> element, and each scan published as msgs::LaserScanStamped on
// ~/MODEL/LINK/SENSOR/scan while someone subscribes. Its scans are the simulator's (RayBridge: the
// plant's lidar, one simulation of each sensor); what differs from Gazebo's: docs/gazebo_api.md.
#pragma once

#include "gazebo/sensors/LaserScanSensor.hh"

namespace gazebo
{
namespace sensors
{
class GZ_SENSORS_VISIBLE RaySensor : public LaserScanSensor
{
public:
  RaySensor();
  ~RaySensor() override;

  // The latest scan's range `index` (row after row; +inf for nothing within range), as published.
  double Range(unsigned int index) const;
  // The intensity of range `index`: 0 (the plant's rays see no <laser_retro>).
  double Retro(unsigned int index) const;
  // The fiducial id the ray of range `index` hit: -1 (none).
  int Fiducial(unsigned int index) const;
  physics::MultiRayShapePtr LaserShape() const { return laserShape; }

protected:
  // A scan, then the shape's new-scans event (RayPlugin's OnNewLaserScans).
  bool UpdateImpl(bool force) override;
};
}  // namespace sensors
}  // namespace gazebo
