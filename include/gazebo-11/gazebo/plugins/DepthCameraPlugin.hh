// Gazebo 11's DepthCameraPlugin (libDepthCameraPlugin.so), which gazebo_ros_pkgs' gazebo_ros_depth_camera
// and gazebo_ros_openni_kinect link and derive from: on a DepthCameraSensor, its camera's image size,
// depth and format, its sensor set active, and each frame's image, depths and RGB points to
// OnNewImageFrame, OnNewDepthFrame and OnNewRGBPointCloud (OnNewReflectanceFrame and
// OnNewNormalsFrame never: the plant renders neither).
#pragma once

#include <string>

#include <sdf/sdf.hh>

#include "gazebo/common/Plugin.hh"
#include "gazebo/rendering/DepthCamera.hh"
#include "gazebo/sensors/DepthCameraSensor.hh"
#include "gazebo/sensors/SensorTypes.hh"
#include "gazebo/util/system.hh"

namespace gazebo
{
class GZ_PLUGIN_VISIBLE DepthCameraPlugin : public SensorPlugin
{
public:
  DepthCameraPlugin();
  virtual ~DepthCameraPlugin();
  void Load(sensors::SensorPtr _sensor, sdf::ElementPtr _sdf);
  // A derived plugin's; nothing here.
  virtual void OnNewDepthFrame(const float* _image, unsigned int _width, unsigned int _height, unsigned int _depth,
                               const std::string& _format);
  virtual void OnNewRGBPointCloud(const float* _pcd, unsigned int _width, unsigned int _height, unsigned int _depth,
                                  const std::string& _format);
  virtual void OnNewImageFrame(const unsigned char* _image, unsigned int _width, unsigned int _height,
                               unsigned int _depth, const std::string& _format);
  virtual void OnNewReflectanceFrame(const float* _reflectance, unsigned int _width, unsigned int _height,
                                     unsigned int _depth, const std::string& _format);
  virtual void OnNewNormalsFrame(const float* _normals, unsigned int _width, unsigned int _height,
                                 unsigned int _depth, const std::string& _format);

protected:
  unsigned int width = 0, height = 0, depth = 0;
  std::string format;
  sensors::DepthCameraSensorPtr parentSensor;
  rendering::DepthCameraPtr depthCamera;

private:
  event::ConnectionPtr newDepthFrameConnection, newRGBPointCloudConnection, newImageFrameConnection,
      newReflectanceFrameConnection, newNormalsFrameConnection;
};
}  // namespace gazebo
