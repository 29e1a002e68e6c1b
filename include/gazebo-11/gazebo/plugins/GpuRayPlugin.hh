// Gazebo 11's GpuRayPlugin (libGpuRayPlugin.so), the sensor plugin gazebo_ros_pkgs' gazebo_ros_gpu_laser
// derives from: on a GpuRaySensor (anything else: Gazebo's error, and nothing more), its sensor set
// active and OnNewLaserFrame called with each scan's laser frame.
#pragma once

#include <string>

#include <sdf/sdf.hh>

#include "gazebo/common/Plugin.hh"
#include "gazebo/sensors/GpuRaySensor.hh"
#include "gazebo/sensors/SensorTypes.hh"
#include "gazebo/util/system.hh"

namespace gazebo
{
class GZ_PLUGIN_VISIBLE GpuRayPlugin : public SensorPlugin
{
public:
  GpuRayPlugin();
  virtual ~GpuRayPlugin();
  void Load(sensors::SensorPtr _sensor, sdf::ElementPtr _sdf);
  // After each scan (a derived plugin's; nothing here): RangeCount x VerticalRangeCount rays, 3
  // floats each (GpuRaySensor::ConnectNewLaserFrame).
  virtual void OnNewLaserFrame(const float* _image, unsigned int _width, unsigned int _height, unsigned int _depth,
                               const std::string& _format);

protected:
  unsigned int width = 0, height = 0;
  sensors::GpuRaySensorPtr parentSensor;

private:
  event::ConnectionPtr newLaserFrameConnection;
};
}  // namespace gazebo
