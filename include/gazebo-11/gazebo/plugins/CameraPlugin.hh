// Gazebo 11's CameraPlugin (libCameraPlugin.so), which gazebo_ros_pkgs' gazebo_ros_camera links and
// derives from: on a CameraSensor, its camera's image size, depth and format, its sensor set
// active, and OnNewFrame called with each frame.
#pragma once

#include <string>

#include <sdf/sdf.hh>

#include "gazebo/common/Plugin.hh"
#include "gazebo/rendering/Camera.hh"
#include "gazebo/sensors/CameraSensor.hh"
#include "gazebo/sensors/SensorTypes.hh"
#include "gazebo/util/system.hh"

namespace gazebo
{
class GZ_PLUGIN_VISIBLE CameraPlugin : public SensorPlugin
{
public:
  CameraPlugin();
  virtual ~CameraPlugin();
  virtual void Load(sensors::SensorPtr _sensor, sdf::ElementPtr _sdf);
  // After each frame (a derived plugin's; nothing here).
  virtual void OnNewFrame(const unsigned char* _image, unsigned int _width, unsigned int _height, unsigned int _depth,
                          const std::string& _format);

protected:
  unsigned int width = 0, height = 0, depth = 0;
  std::string format;
  sensors::CameraSensorPtr parentSensor;
  rendering::CameraPtr camera;

private:
  event::ConnectionPtr newFrameConnection;
};
}  // namespace gazebo
