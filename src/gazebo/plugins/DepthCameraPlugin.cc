// Gazebo 11's DepthCameraPlugin (gazebo/plugins/DepthCameraPlugin.hh).
#include "gazebo/plugins/DepthCameraPlugin.hh"

#include "gazebo/common/Console.hh"
#include "gazebo/common/Exception.hh"

namespace gazebo
{
GZ_REGISTER_SENSOR_PLUGIN(DepthCameraPlugin)

DepthCameraPlugin::DepthCameraPlugin() = default;

DepthCameraPlugin::~DepthCameraPlugin()
{
  newDepthFrameConnection.reset();
  newRGBPointCloudConnection.reset();
  newImageFrameConnection.reset();
  newReflectanceFrameConnection.reset();
  newNormalsFrameConnection.reset();
  parentSensor.reset();
  depthCamera.reset();
}

void DepthCameraPlugin::Load(sensors::SensorPtr _sensor, sdf::ElementPtr /*_sdf*/)
{
  parentSensor = std::dynamic_pointer_cast<sensors::DepthCameraSensor>(_sensor);
  if (!parentSensor)
  {
    // Gazebo's dereferences the null sensor before its error; here the plugin stops with it.
    gzerr << "DepthCameraPlugin not attached to a depthCamera sensor\n";
    gzthrow("DepthCameraPlugin not attached to a depthCamera sensor");
  }
  depthCamera = parentSensor->DepthCamera();
  width = depthCamera->ImageWidth();
  height = depthCamera->ImageHeight();
  depth = depthCamera->ImageDepth();
  format = depthCamera->ImageFormat();
  // (lambdas: Gazebo's headers bring boost's placeholders _1 ... into the global namespace, as Gazebo's do)
  newDepthFrameConnection = depthCamera->ConnectNewDepthFrame(
      [this](const float* f, unsigned int w, unsigned int h, unsigned int d, const std::string& s) {
        OnNewDepthFrame(f, w, h, d, s);
      });
  newRGBPointCloudConnection = depthCamera->ConnectNewRGBPointCloud(
      [this](const float* f, unsigned int w, unsigned int h, unsigned int d, const std::string& s) {
        OnNewRGBPointCloud(f, w, h, d, s);
      });
  newImageFrameConnection = depthCamera->ConnectNewImageFrame(
      [this](const unsigned char* f, unsigned int w, unsigned int h, unsigned int d, const std::string& s) {
        OnNewImageFrame(f, w, h, d, s);
      });
  newReflectanceFrameConnection = depthCamera->ConnectNewReflectanceFrame(
      [this](const float* f, unsigned int w, unsigned int h, unsigned int d, const std::string& s) {
        OnNewReflectanceFrame(f, w, h, d, s);
      });
  newNormalsFrameConnection = depthCamera->ConnectNewNormalsPointCloud(
      [this](const float* f, unsigned int w, unsigned int h, unsigned int d, const std::string& s) {
        OnNewNormalsFrame(f, w, h, d, s);
      });
  parentSensor->SetActive(true);
}

void DepthCameraPlugin::OnNewDepthFrame(const float*, unsigned int, unsigned int, unsigned int, const std::string&) {}

void DepthCameraPlugin::OnNewRGBPointCloud(const float*, unsigned int, unsigned int, unsigned int, const std::string&)
{
}

void DepthCameraPlugin::OnNewImageFrame(const unsigned char*, unsigned int, unsigned int, unsigned int,
                                        const std::string&)
{
}

void DepthCameraPlugin::OnNewReflectanceFrame(const float*, unsigned int, unsigned int, unsigned int,
                                              const std::string&)
{
}

void DepthCameraPlugin::OnNewNormalsFrame(const float*, unsigned int, unsigned int, unsigned int, const std::string&)
{
}
}  // namespace gazebo
