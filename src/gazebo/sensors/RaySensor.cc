// sensors::RaySensor (gazebo/sensors/RaySensor.hh).
#include "gazebo/sensors/RaySensor.hh"

#include "gazebo/common/Console.hh"

namespace gazebo
{
namespace sensors
{
RaySensor::RaySensor() : LaserScanSensor(RAY) {}

RaySensor::~RaySensor() = default;

double RaySensor::Range(unsigned int index) const { return ScanValue(false, index); }

double RaySensor::Retro(unsigned int index) const { return ScanValue(true, index); }

int RaySensor::Fiducial(unsigned int index) const
{
  // Gazebo's: the range's index mapped onto the rays'
  const int range_count = RangeCount(), ray_count = RayCount();
  const int vertical = (static_cast<int>(index) / range_count) * VerticalRayCount() / VerticalRangeCount();
  const int horizontal = (static_cast<int>(index) % range_count) * ray_count / range_count;
  const int ray = vertical * ray_count + horizontal;
  if (ray >= ray_count * VerticalRayCount())
  {
    gzerr << "Invalid fiducial index[" << index << "]\n";
    return 0;
  }
  return laserShape->GetFiducial(static_cast<unsigned int>(ray));
}

bool RaySensor::UpdateImpl(bool force)
{
  if (!LaserScanSensor::UpdateImpl(force))
    return false;
  laserShape->Update();
  return true;
}
}  // namespace sensors
}  // namespace gazebo
