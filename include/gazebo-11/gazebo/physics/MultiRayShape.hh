// physics::MultiRayShape: a ray sensor's rays as RaySensor::LaserShape() gives them to plugins
// (gazebo_ros_range, gazebo_ros_block_laser read GetRange and GetRetro; RayPlugin connects to
// ConnectNewLaserScans). Its <ray> element's counts, angles and ranges are the sensor's; its ranges
// are those of the sensor's latest scan, cast by the simulator (the plant's lidar: one simulation
// of each sensor), so it casts nothing itself and has no RayShape of its own (docs/gazebo_api.md).
#pragma once

#include <functional>
#include <vector>

#include <ignition/math/Angle.hh>
#include <sdf/sdf.hh>

#include "gazebo/common/Event.hh"
#include "gazebo/physics/Shape.hh"

namespace gazebo
{
namespace physics
{
class GZ_PHYSICS_VISIBLE MultiRayShape : public Shape
{
public:
  explicit MultiRayShape(CollisionPtr parent);
  ~MultiRayShape() override;

  // The <sensor> (or its <ray>) element: SDF's defaults for what it does not give.
  void Load(sdf::ElementPtr sensor);
  void Init() {}

  // Ray `index` (row after row), as Gazebo's: its length to what it hit, GetMaxRange where it hit
  // nothing, GetMinRange for a hit nearer than that; 0 with an error for an index out of range.
  double GetRange(unsigned int index);
  // Retro-reflectance and fiducial id of what ray `index` hit: the plant gives none (0 and -1).
  double GetRetro(unsigned int index);
  int GetFiducial(unsigned int index);

  double GetMinRange() const { return range_min_; }
  double GetMaxRange() const { return range_max_; }
  double GetResRange() const { return range_resolution_; }
  int GetSampleCount() const { return samples_; }
  double GetScanResolution() const { return resolution_; }
  ignition::math::Angle MinAngle() const { return min_angle_; }
  ignition::math::Angle MaxAngle() const { return max_angle_; }
  int GetVerticalSampleCount() const { return vertical_samples_; }
  double GetVerticalScanResolution() const { return vertical_resolution_; }
  ignition::math::Angle VerticalMinAngle() const { return vertical_min_angle_; }
  ignition::math::Angle VerticalMaxAngle() const { return vertical_max_angle_; }
  unsigned int RayCount() const { return static_cast<unsigned int>(samples_ * vertical_samples_); }

  // Gazebo's casts the rays, then signals new scans; here the sensor has handed the scan over
  // (SetRanges) and this signals it.
  void Update();
  template <typename T>
  event::ConnectionPtr ConnectNewLaserScans(T subscriber)
  {
    return new_laser_scans_.Connect(subscriber);
  }
  void DisconnectNewLaserScans(event::ConnectionPtr& connection) { connection.reset(); }

  // Not Gazebo's: the scan its sensor measured, row after row (RayBridge::ranges: +inf for no hit,
  // -inf nearer than the minimum), kept as measured; and that scan.
  void SetRanges(const std::vector<float>& ranges) { ranges_ = ranges; }
  const std::vector<float>& Ranges() const { return ranges_; }

protected:
  event::EventT<void()> new_laser_scans_;

private:
  std::vector<float> ranges_;
  int samples_ = 1, vertical_samples_ = 1;
  double resolution_ = 1, vertical_resolution_ = 1;
  ignition::math::Angle min_angle_, max_angle_, vertical_min_angle_, vertical_max_angle_;
  double range_min_ = 0, range_max_ = 0, range_resolution_ = 0;
};
}  // namespace physics
}  // namespace gazebo
