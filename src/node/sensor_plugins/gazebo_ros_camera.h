// gazebo_ros_camera: a camera's sensor_msgs/Image (rgb8) on <imageTopicName> and its CameraInfo on
// <cameraInfoTopicName>, both under <cameraName>, frame tf::resolve(tf_prefix, <frameName>); the
// tf_prefix parameter is searched from the camera's namespace (docs/interfaces.md section 11).
// <hackBaseline> (0) puts -fx * baseline into P[3] (a stereo pair's right camera).
// gazebo_ros_openni_kinect and gazebo_ros_multicamera extend it, as upstream's build on
// GazeboRosCameraUtils.
#pragma once

#include <sensor_msgs/CameraInfo.h>

#include "frame_messages.h"
#include "sensor_plugin.h"

namespace bullet_plant
{
class GazeboRosCamera : public SensorPlugin
{
public:
  void Load(Sensor& sensor) override;
  bool subscribed() const override;
  void OnUpdate() override;

protected:
  // The frame's image and info, then publishFrame's topics.
  void publish(const CameraFrame& frame);
  // After the image and its info, with the same frame (the depth plugin's extra topics).
  virtual void publishFrame(const CameraFrame& frame, const std_msgs::Header& header) {}
  sensor_msgs::CameraInfo cameraInfo(const CameraFrame& f, const std_msgs::Header& header) const;
  std::string owner() const { return "sensor '" + camera_->name() + "' topic"; }

  Camera* camera_ = nullptr;
  ros::NodeHandle nh_;
  std::string frame_id_;
  double hack_baseline_ = 0.0;  // m

private:
  ros::Publisher image_pub_, info_pub_;
};

}  // namespace bullet_plant
