#include "gazebo_ros_camera.h"

#include "ros_names.h"

namespace bullet_plant
{
void GazeboRosCamera::Load(Sensor& sensor)
{
  camera_ = &sensorAs<Camera>(sensor, "gazebo_ros_camera");
  nh_ = nodeHandle(sensor);
  const SensorDescription& d = sensor.description();
  const std::string camera_name = d.pluginParam("cameraName");
  frame_id_ = pluginFrameId(d, searchedTfPrefix(sensor, camera_name.empty() ? nh_ : ros::NodeHandle(nh_, camera_name)));
  image_pub_ = nh_.advertise<sensor_msgs::Image>(requireValidRosName(pluginTopic(d), owner()), 2);
  info_pub_ = nh_.advertise<sensor_msgs::CameraInfo>(requireValidRosName(pluginTopic(d, PluginTopic::CameraInfo), owner()), 2);
  hack_baseline_ = d.pluginNumber("hackBaseline", 0.0);
}

bool GazeboRosCamera::subscribed() const
{
  return image_pub_.getNumSubscribers() + info_pub_.getNumSubscribers() > 0;
}

void GazeboRosCamera::OnUpdate()
{
  if (!takeUpdate(*camera_))
    return;
  publish(camera_->latest());
}

void GazeboRosCamera::publish(const CameraFrame& frame)
{
  // Images are serialized from the frame as roscpp sends them, only for topics with subscribers
  // (frame_messages.h).
  const std_msgs::Header header = frameHeader(frame, frame_id_);
  image_pub_.publish(RgbImageOf{frame, header});
  info_pub_.publish(cameraInfo(frame, header));
  publishFrame(frame, header);
}

sensor_msgs::CameraInfo GazeboRosCamera::cameraInfo(const CameraFrame& f, const std_msgs::Header& header) const
{
  sensor_msgs::CameraInfo info;
  info.header = header;
  info.width = f.width;
  info.height = f.height;
  info.distortion_model = "plumb_bob";
  info.D.assign(5, 0.0);
  info.K = {f.fx, 0, f.cx, 0, f.fy, f.cy, 0, 0, 1};
  info.R = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  info.P = {f.fx, 0, f.cx, -f.fx * hack_baseline_, 0, f.fy, f.cy, 0, 0, 0, 1, 0};
  return info;
}

GAZEBO_ROS_SENSOR_PLUGIN(GazeboRosCamera, "libgazebo_ros_camera.so");

}  // namespace bullet_plant
