// sensors::GpuRaySensor (gazebo/sensors/GpuRaySensor.hh).
#include "gazebo/sensors/GpuRaySensor.hh"

#include <algorithm>
#include <cmath>

#include "gazebo/common/Console.hh"
#include "gazebo/msgs/msgs.hh"

namespace gazebo
{
namespace sensors
{
GpuRaySensor::GpuRaySensor() : LaserScanSensor(IMAGE) {}

GpuRaySensor::~GpuRaySensor() = default;

void GpuRaySensor::Init()
{
  LaserScanSensor::Init();
  // Gazebo's GpuRaySensor::Init: the horizontal fan split among up to 3 cameras, the vertical one
  // centred on its half angle, the camera's vertical field padded to hold every ray.
  double hfov = std::min((AngleMax() - AngleMin()).Radian(), 2 * M_PI);
  horz_half_angle_ = (AngleMax() + AngleMin()).Radian() / 2.0;
  camera_count_ = hfov > 5.6 ? 3 : hfov > 2.8 ? 2 : 1;
  hfov /= camera_count_;
  horz_fov_ = hfov;
  double vfov = 0;
  if (VerticalRayCount() > 1)
    vfov = (VerticalAngleMax() - VerticalAngleMin()).Radian();
  else if (VerticalAngleMax() != VerticalAngleMin())
  {
    gzwarn << "Only one vertical ray but vertical min. and max. angle are not equal. Min. angle is used.\n";
    SetVerticalAngleMax(VerticalAngleMin().Radian());
  }
  if (vfov > M_PI / 2)
  {
    vfov = M_PI / 2;
    gzwarn << "Vertical FOV for GPU laser is capped at 90 degrees.\n";
  }
  vert_fov_ = vfov;
  vert_half_angle_ = (VerticalAngleMax() + VerticalAngleMin()).Radian() / 2.0;
  if (VerticalRayCount() > 1)
  {
    SetVerticalAngleMin(vert_half_angle_ - vfov / 2);
    SetVerticalAngleMax(vert_half_angle_ + vfov / 2);
  }
  double vfov_camera = vfov + 2 * std::abs(vert_half_angle_);
  vfov_camera = 2 * std::atan(std::tan(vfov_camera / 2) / std::cos(hfov / 2));
  cos_vert_fov_ = vfov_camera;
  const unsigned int horz_ranges_per_camera =
      std::max(2048U, static_cast<unsigned int>(std::max(RangeCount(), 0)) / camera_count_);
  if (VerticalRayCount() > 1)
    ray_count_ratio_ = range_count_ratio_ = std::tan(hfov / 2.0) / std::tan(vfov_camera / 2.0);
  else
    ray_count_ratio_ = horz_ranges_per_camera;
}

double GpuRaySensor::Range(int index) const
{
  if (index < 0)
  {
    gzerr << "Invalid range index[" << index << "]\n";
    return 0.0;
  }
  return ScanValue(false, static_cast<unsigned int>(index));
}

double GpuRaySensor::Retro(int /*index*/) const { return 0.0; }

int GpuRaySensor::Fiducial(unsigned int /*index*/) const { return -1; }

void GpuRaySensor::SetScanAngle(const char* axis, const char* name, double value)
{
  sdf->GetElement("ray")->GetElement("scan")->GetElement(axis)->GetElement(name)->Set(value);
  laserShape->Load(sdf);
}

void GpuRaySensor::SetAngleMin(double angle) { SetScanAngle("horizontal", "min_angle", angle); }

void GpuRaySensor::SetAngleMax(double angle) { SetScanAngle("horizontal", "max_angle", angle); }

void GpuRaySensor::SetVerticalAngleMin(double angle) { SetScanAngle("vertical", "min_angle", angle); }

void GpuRaySensor::SetVerticalAngleMax(double angle) { SetScanAngle("vertical", "max_angle", angle); }

event::ConnectionPtr GpuRaySensor::ConnectNewLaserFrame(
    std::function<void(const float*, unsigned int, unsigned int, unsigned int, const std::string&)> subscriber)
{
  return new_laser_frame_.Connect(subscriber);
}

bool GpuRaySensor::UpdateImpl(bool force)
{
  if (!LaserScanSensor::UpdateImpl(force))
    return false;
  if (new_laser_frame_.ConnectionCount() == 0)
    return true;
  // Gazebo's laser texture holds what its rays met, within the clip range; the published ranges'
  // REP 117 infinities are its ends.
  const boost::shared_ptr<const msgs::LaserScanStamped> scan = LatestScan();
  const auto& ranges = scan->scan().ranges();
  const double range_min = RangeMin(), range_max = RangeMax();
  laser_frame_.assign(static_cast<size_t>(ranges.size()) * 3, 0.0f);
  for (int i = 0; i < ranges.size(); ++i)
    laser_frame_[size_t(i) * 3] = static_cast<float>(std::clamp(ranges.Get(i), range_min, range_max));
  new_laser_frame_(laser_frame_.data(), static_cast<unsigned int>(std::max(RangeCount(), 0)),
                   static_cast<unsigned int>(std::max(VerticalRangeCount(), 0)), 3u, std::string("FLOAT32"));
  return true;
}
}  // namespace sensors
}  // namespace gazebo
