// The rendering classes' names and handle types, as Gazebo 11 declares them (std::shared_ptr
// handles): what camera sensors and their plugins name.
#pragma once

#include <memory>

namespace gazebo
{
namespace rendering
{
class Camera;
class DepthCamera;
class Distortion;
typedef std::shared_ptr<Camera> CameraPtr;
typedef std::shared_ptr<DepthCamera> DepthCameraPtr;
typedef std::shared_ptr<Distortion> DistortionPtr;
}  // namespace rendering
}  // namespace gazebo
