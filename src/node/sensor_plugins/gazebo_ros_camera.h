// gazebo_ros_camera: a camera's sensor_msgs/Image on <imageTopicName> and its CameraInfo on
// <cameraInfoTopicName>, both under <cameraName>, frame tf::resolve(tf_prefix, <frameName>); the
// tf_prefix parameter is searched from the camera's namespace (docs/interfaces.md section 11).
// What gazebo_ros_camera_utils (noetic-devel) makes of the <sensor> and the <plugin> block:
// - the image in the <image><format>'s encoding (image_encoding.h), upstream's error and bgr8 for
//   a format it does not know;
// - CameraInfo: K = [f 0 Cx; 0 f Cy; 0 0 1] and P = [f 0 Cx -f*hackBaseline; 0 f Cy 0; 0 0 1 0],
//   R the identity, f = <focalLength> or, when 0 (its default), width / (2 tan(hfov / 2)) (a given
//   one that differs is warned about, as upstream); <Cx>, <Cy> or, when 0, (width + 1) / 2 and
//   (height + 1) / 2 (upstream's); D = [distortionK1 K2 T1 T2 K3] (plumb_bob), or with
//   <autoDistortion> the sensor's <distortion> [k1 k2 p1 p2 k3]; <CxPrime> is read and, as upstream,
//   used nowhere;
// - <borderCrop> (true) is the sensor's Distortion::SetCrop: whether a barrel lens is cropped.
// The info is worked out once at Load, as upstream's Init fills camera_info_manager once.
// upstream's set_hfov and set_update_rate subscriptions are commented out in noetic-devel's
// LoadThread: nothing subscribes to them here either.
// gazebo_ros_openni_kinect, gazebo_ros_multicamera and gazebo_ros_triggered_camera extend it, as
// upstream's build on GazeboRosCameraUtils.
#pragma once

#include <sensor_msgs/CameraInfo.h>

#include "bullet_plant/image_encoding.h"
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
  // The info worked out at Load (cameraInfoOf) with the frame's stamp and frame id.
  sensor_msgs::CameraInfo cameraInfo(const CameraFrame& f, const std_msgs::Header& header) const;
  std::string owner() const { return "sensor '" + camera_->name() + "' topic"; }
  // CameraInfo's K, P, R and D as gazebo_ros_camera_utils' Init computes them (the header aside);
  // hack_baseline_ must be final.
  void computeCameraInfo();

  Camera* camera_ = nullptr;
  ros::NodeHandle nh_;
  std::string frame_id_;
  double hack_baseline_ = 0.0;  // m
  bool zero_baseline_ = false;  // set before Load: hackBaseline is 0 whatever is given (multicamera's left)
  ImageEncoding encoding_;
  sensor_msgs::CameraInfo info_;  // all but the header

private:
  CountedPublisher image_pub_, info_pub_;
};

// The CameraInfo fields upstream fills (width, height, plumb_bob D, K, R, P) for a camera of the
// description's size and field of view and the plugin block's Cx, Cy, focalLength, distortion
// parameters and autoDistortion; `warnings` gets what upstream warns about (a focal length that
// disagrees with the field of view) and what the plant took instead of a value that is not finite.
sensor_msgs::CameraInfo cameraInfoOf(const SensorDescription& d, double hack_baseline, std::vector<std::string>& warnings);

}  // namespace bullet_plant
