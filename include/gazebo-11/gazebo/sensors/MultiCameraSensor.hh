// sensors::MultiCameraSensor: a <sensor type="multicamera"> as Gazebo 11's: a rendering::Camera for
// each of its <camera> elements (named by the element's name, at the sensor's pose composed with
// the camera's), each one's frames to its ConnectNewImageFrame subscribers, and all of a moment's
// frames published as one msgs::ImagesStamped on ~/MODEL/LINK/SENSOR/images while someone subscribes.
// Its frames are the simulator's (MultiCameraBridge: the plant's OpenGL camera of each <camera>);
// what differs: docs/gazebo_api.md.
#pragma once

#include <string>
#include <vector>

#include "gazebo/msgs/MessageTypes.hh"
#include "gazebo/rendering/RenderTypes.hh"
#include "gazebo/sensors/Sensor.hh"
#include "gazebo/transport/TransportTypes.hh"

namespace gazebo
{
namespace sensors
{
class GZ_SENSORS_VISIBLE MultiCameraSensor : public Sensor
{
public:
  MultiCameraSensor();
  ~MultiCameraSensor() override;

  // Its topic; its cameras from the <camera> elements.
  void Load(const std::string& worldName) override;
  using Sensor::Load;
  void Init() override;
  void Fini() override;
  // ~/MODEL/LINK/SENSOR/images, or its <topic>
  std::string Topic() const override;

  unsigned int CameraCount() const;
  // Null, with Gazebo's error, for an index past the last.
  rendering::CameraPtr Camera(unsigned int _index) const;
  unsigned int ImageWidth(unsigned int _index) const;
  unsigned int ImageHeight(unsigned int _index) const;
  // The camera's latest frame, in its format's bytes; null before the first.
  const unsigned char* ImageData(unsigned int _index);

  // Active as set, or while its topic has a subscriber (Gazebo's rule).
  bool IsActive() const override;

protected:
  // Each camera's latest frame to its subscribers, then all of them to the topic; only once every
  // camera has rendered (the simulator renders them at the same steps).
  bool UpdateImpl(bool force) override;

private:
  std::vector<rendering::CameraPtr> cameras_;
  msgs::ImagesStamped message_;
  transport::PublisherPtr images_pub_;
};
}  // namespace sensors
}  // namespace gazebo
