// sensors::GpuRaySensor: a <sensor type="gpu_ray"> as Gazebo 11's: its counts, angles and ranges from
// its <ray> element, each scan published as msgs::LaserScanStamped on ~/MODEL/LINK/SENSOR/scan while
// someone subscribes, each scan as a laser frame to ConnectNewLaserFrame's subscribers, and the
// geometry of the cameras Gazebo would render it with (CameraCount, HorzFOV ...). Its scans are the
// simulator's (the plant casts a gpu_ray lidar's rays as a ray one's: one simulation of each sensor),
// so there is no rendering::GpuLaser (LaserCamera is absent); what differs: docs/gazebo_api.md.
#pragma once

#include <functional>
#include <string>

#include "gazebo/common/Event.hh"
#include "gazebo/sensors/LaserScanSensor.hh"

namespace gazebo
{
namespace sensors
{
class GZ_SENSORS_VISIBLE GpuRaySensor : public LaserScanSensor
{
public:
  GpuRaySensor();
  ~GpuRaySensor() override;

  // The scan's camera geometry, from the <ray> element as Gazebo's Init derives it.
  void Init() override;

  // The latest scan's range `index` (row after row; +inf for nothing within range), as published.
  double Range(int index) const;
  // As Gazebo's GpuRaySensor: 0 and -1 for every ray.
  double Retro(int index) const;
  int Fiducial(unsigned int index) const;

  // The <ray> element's angles, set (before Init, as Gazebo's take effect at its laser's set-up).
  void SetAngleMin(double angle);
  void SetAngleMax(double angle);
  void SetVerticalAngleMin(double angle);
  void SetVerticalAngleMax(double angle);

  // The cameras Gazebo renders the scan with: 1 to 3 of them side by side for the horizontal fan,
  // each HorzFOV wide; what Gazebo stores as CosHorzFOV and CosVertFOV (the fields of view, the
  // vertical one padded to the camera's, not cosines) kept as Gazebo's.
  unsigned int CameraCount() const { return camera_count_; }
  bool IsHorizontal() const { return true; }
  double RayCountRatio() const { return ray_count_ratio_; }
  double RangeCountRatio() const { return range_count_ratio_; }
  double HorzFOV() const { return horz_fov_; }
  double CosHorzFOV() const { return horz_fov_; }
  double VertFOV() const { return vert_fov_; }
  double CosVertFOV() const { return cos_vert_fov_; }
  double HorzHalfAngle() const { return horz_half_angle_; }
  double VertHalfAngle() const { return vert_half_angle_; }

  // After each scan: its ranges as Gazebo's laser frame, RangeCount wide and VerticalRangeCount
  // high, 3 floats a ray (range between RangeMin and RangeMax, intensity 0, 0).
  event::ConnectionPtr ConnectNewLaserFrame(
      std::function<void(const float*, unsigned int, unsigned int, unsigned int, const std::string&)> subscriber);

protected:
  bool UpdateImpl(bool force) override;

private:
  // Element `name` of the <ray><scan>'s `axis` ("horizontal", "vertical") set to `value`, read again.
  void SetScanAngle(const char* axis, const char* name, double value);
  event::EventT<void(const float*, unsigned int, unsigned int, unsigned int, const std::string&)> new_laser_frame_;
  std::vector<float> laser_frame_;
  unsigned int camera_count_ = 1;
  double ray_count_ratio_ = 0, range_count_ratio_ = 0;
  double horz_fov_ = 0, vert_fov_ = 0, cos_vert_fov_ = 0, horz_half_angle_ = 0, vert_half_angle_ = 0;
};
}  // namespace sensors
}  // namespace gazebo
