// Gazebo 11's GpuRayPlugin (gazebo/plugins/GpuRayPlugin.hh).
#include "gazebo/plugins/GpuRayPlugin.hh"

#include "gazebo/common/Console.hh"

namespace gazebo
{
GZ_REGISTER_SENSOR_PLUGIN(GpuRayPlugin)

GpuRayPlugin::GpuRayPlugin() = default;

GpuRayPlugin::~GpuRayPlugin() { newLaserFrameConnection.reset(); }

void GpuRayPlugin::Load(sensors::SensorPtr _sensor, sdf::ElementPtr /*_sdf*/)
{
  parentSensor = std::dynamic_pointer_cast<sensors::GpuRaySensor>(_sensor);
  if (!parentSensor)
  {
    gzerr << "GpuRayPlugin not attached to a GpuLaser sensor\n";
    return;
  }
  width = static_cast<unsigned int>(parentSensor->RangeCount());
  height = static_cast<unsigned int>(parentSensor->VerticalRangeCount());
  newLaserFrameConnection = parentSensor->ConnectNewLaserFrame(
      [this](const float* image, unsigned int w, unsigned int h, unsigned int depth, const std::string& format) {
        OnNewLaserFrame(image, w, h, depth, format);
      });
  parentSensor->SetActive(true);
}

void GpuRayPlugin::OnNewLaserFrame(const float* /*_image*/, unsigned int /*_width*/, unsigned int /*_height*/,
                                   unsigned int /*_depth*/, const std::string& /*_format*/)
{
}
}  // namespace gazebo
