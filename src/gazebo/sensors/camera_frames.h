// What CameraSensor and MultiCameraSensor share over the simulator's cameras: the lens crop a plugin
// set handed to the simulator's camera (it renders with it from the next frame), and a msgs::Image's
// description of a camera's frames. Private to the library.
#pragma once

#include "gazebo/common/Image.hh"
#include "gazebo/msgs/msgs.hh"
#include "gazebo/rendering/Camera.hh"
#include "gazebo/sensors/SensorBridge.hh"

namespace gazebo
{
namespace sensors
{
namespace detail
{
// (gazebo_ros_camera_utils' <borderCrop> sets it through Distortion::SetCrop)
inline void handLensCrop(const rendering::Camera& camera, CameraBridge& frames)
{
  if (const rendering::DistortionPtr lens = camera.LensDistortion())
    frames.setDistortionCrop(lens->Crop());
}

// width, height, common::Image's pixel format number, step
inline void describeFrames(const rendering::Camera& camera, msgs::Image& image)
{
  image.set_width(camera.ImageWidth());
  image.set_height(camera.ImageHeight());
  image.set_pixel_format(common::Image::ConvertPixelFormat(camera.ImageFormat()));
  image.set_step(camera.ImageWidth() * camera.ImageDepth());
}
}  // namespace detail
}  // namespace sensors
}  // namespace gazebo
