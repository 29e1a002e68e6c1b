// sensors::CameraSensor: a <sensor type="camera"> as Gazebo 11's: its rendering::Camera (image size,
// format, field of view, lens distortion from its <camera> element; each frame to
// ConnectNewImageFrame's subscribers), and each frame published as msgs::ImageStamped on
// ~/MODEL/LINK/SENSOR/image while someone subscribes. Its frames are the simulator's (CameraBridge:
// the plant's OpenGL camera, one simulation of each sensor); what differs: docs/gazebo_api.md.
#pragma once

#include <string>

#include "gazebo/msgs/MessageTypes.hh"
#include "gazebo/rendering/RenderTypes.hh"
#include "gazebo/sensors/Sensor.hh"
#include "gazebo/transport/TransportTypes.hh"

namespace gazebo
{
namespace sensors
{
class GZ_SENSORS_VISIBLE CameraSensor : public Sensor
{
public:
  CameraSensor();
  ~CameraSensor() override;

  // Its topic; its camera from the <camera> element.
  void Load(const std::string& worldName) override;
  using Sensor::Load;
  void Init() override;
  void Fini() override;
  // ~/MODEL/LINK/SENSOR/image
  std::string Topic() const override;

  rendering::CameraPtr Camera() const { return camera; }
  unsigned int ImageWidth() const;
  unsigned int ImageHeight() const;
  // The latest frame, in its format's bytes; null before the first.
  const unsigned char* ImageData() const;

  // Active as set, or while its topic has a subscriber (Gazebo's rule).
  bool IsActive() const override;

protected:
  // Not Gazebo's: its camera (a DepthCameraSensor's is a DepthCamera), made in Init.
  virtual rendering::CameraPtr MakeCamera();
  // The simulator's latest frame to the camera (its subscribers) and the topic.
  bool UpdateImpl(bool force) override;
  rendering::CameraPtr camera;

private:
  transport::PublisherPtr image_pub_;
};
}  // namespace sensors
}  // namespace gazebo
