#include "bullet_plant/sensors.h"

#include <cmath>

namespace bullet_plant
{
Sensor::Sensor(const SensorDescription& d) : description_(d)
{
  period_ns_ = d.update_rate > 0 ? static_cast<int64_t>(std::llround(1e9 / d.update_rate)) : 0;
}

std::string Sensor::frameId() const
{
  return description_.pluginParam("frameName", description_.link);
}

bool Sensor::due(int64_t time_ns)
{
  if (last_update_ns_ >= 0 && time_ns - last_update_ns_ < period_ns_ && time_ns >= last_update_ns_)
    return false;
  last_update_ns_ = time_ns;
  ++updates_;
  return true;
}

Lidar::Lidar(const SensorDescription& d) : Sensor(d) {}

Camera::Camera(const SensorDescription& d) : Sensor(d) {}

namespace
{
std::string joinTopic(const std::string& camera, const std::string& topic)
{
  if (!topic.empty() && topic[0] == '/')
    return topic;
  return camera.empty() ? topic : camera + "/" + topic;
}
}  // namespace

std::string Camera::topic() const
{
  return joinTopic(description_.pluginParam("cameraName", name()),
                   description_.pluginParam("imageTopicName", depthSensor() ? "rgb/image_raw" : "image_raw"));
}

std::string Camera::cameraInfoTopic() const
{
  return joinTopic(description_.pluginParam("cameraName", name()),
                   description_.pluginParam("cameraInfoTopicName", depthSensor() ? "rgb/camera_info" : "camera_info"));
}

std::string Camera::depthTopic() const
{
  return joinTopic(description_.pluginParam("cameraName", name()),
                   description_.pluginParam("depthImageTopicName", "depth/image_raw"));
}

std::string Camera::depthCameraInfoTopic() const
{
  return joinTopic(description_.pluginParam("cameraName", name()),
                   description_.pluginParam("depthImageCameraInfoTopicName", "depth/camera_info"));
}

std::string Camera::pointsTopic() const
{
  return joinTopic(description_.pluginParam("cameraName", name()),
                   description_.pluginParam("pointCloudTopicName", "depth/points"));
}

void Camera::intrinsics(double& fx, double& fy, double& cx, double& cy) const
{
  const int w = description_.image_width, h = description_.image_height;
  fx = fy = w / (2.0 * std::tan(description_.horizontal_fov / 2.0));
  cx = (w - 1) / 2.0;
  cy = (h - 1) / 2.0;
}

}  // namespace bullet_plant
