// Gazebo 11's CameraPlugin (gazebo/plugins/CameraPlugin.hh).
#include "gazebo/plugins/CameraPlugin.hh"

#include "gazebo/common/Console.hh"
#include "gazebo/common/Exception.hh"

namespace gazebo
{
GZ_REGISTER_SENSOR_PLUGIN(CameraPlugin)

CameraPlugin::CameraPlugin() = default;

CameraPlugin::~CameraPlugin()
{
  newFrameConnection.reset();
  parentSensor.reset();
  camera.reset();
}

void CameraPlugin::Load(sensors::SensorPtr _sensor, sdf::ElementPtr /*_sdf*/)
{
  if (!_sensor)
    gzerr << "Invalid sensor pointer.\n";
  parentSensor = std::dynamic_pointer_cast<sensors::CameraSensor>(_sensor);
  if (!parentSensor)
  {
    // Gazebo's goes on to dereference the null sensor; here the plugin stops, as its error says.
    gzerr << "CameraPlugin requires a CameraSensor.\n";
    gzthrow("CameraPlugin not attached to a camera sensor");
  }
  camera = parentSensor->Camera();
  width = camera->ImageWidth();
  height = camera->ImageHeight();
  depth = camera->ImageDepth();
  format = camera->ImageFormat();
  newFrameConnection = camera->ConnectNewImageFrame(
      [this](const unsigned char* image, unsigned int w, unsigned int h, unsigned int d, const std::string& f) {
        OnNewFrame(image, w, h, d, f);
      });
  parentSensor->SetActive(true);
}

void CameraPlugin::OnNewFrame(const unsigned char* /*_image*/, unsigned int /*_width*/, unsigned int /*_height*/,
                              unsigned int /*_depth*/, const std::string& /*_format*/)
{
}
}  // namespace gazebo
