// sensors::DepthCameraSensor: a <sensor type="depth"> as Gazebo 11's: a CameraSensor whose camera is a
// rendering::DepthCamera (each frame's image, then its depths and points to their subscribers). Its
// frames are the simulator's (DepthCameraBridge: the plant's OpenGL depth camera); what differs:
// docs/gazebo_api.md.
#pragma once

#include "gazebo/rendering/RenderTypes.hh"
#include "gazebo/sensors/CameraSensor.hh"

namespace gazebo
{
namespace sensors
{
class GZ_SENSORS_VISIBLE DepthCameraSensor : public CameraSensor
{
public:
  DepthCameraSensor();
  ~DepthCameraSensor() override;

  rendering::DepthCameraPtr DepthCamera() const;
  // The latest frame's depths; null before the first.
  const float* DepthData() const;

protected:
  rendering::CameraPtr MakeCamera() override;
  // The frame's image (CameraSensor's), then its depths and points.
  bool UpdateImpl(bool force) override;
};
}  // namespace sensors
}  // namespace gazebo
