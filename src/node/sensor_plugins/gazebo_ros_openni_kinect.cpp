// gazebo_ros_openni_kinect: the camera's image and info, plus a 32FC1 depth image with its
// CameraInfo and an organized PointCloud2, NaN outside (pointCloudCutoff, pointCloudCutoffMax);
// gazebo_ros_depth_camera: the same with no far cutoff and the cloud as one row (Noetic's, whose
// PointCloud2Modifier::resize flattens it) (docs/interfaces.md section 11). The depth image's
// CameraInfo is the image's (upstream publishes camera_info_manager's one info on both); the
// points' colours are the image's bytes as upstream reads them (frame_messages.h cloudColour).
#include <limits>

#include "gazebo_ros_camera.h"
#include "ros_names.h"

namespace bullet_plant
{
class GazeboRosOpenniKinect : public GazeboRosCamera
{
public:
  void Load(Sensor& sensor) override
  {
    GazeboRosCamera::Load(sensor);
    // The depths come from a <sensor type="depth">; on a plain camera it is gazebo_ros_camera.
    if (!camera_->depthSensor())
    {
      ROS_WARN("sensor '%s': gazebo_ros_openni_kinect needs <sensor type=\"depth\">; it publishes the image only",
               sensor.name().c_str());
      return;
    }
    const SensorDescription& d = sensor.description();
    depth_pub_ = CountedPublisher::advertise<sensor_msgs::Image>(
        nh_, requireValidRosName(pluginTopic(d, PluginTopic::DepthImage), owner()), 2);
    depth_info_pub_ = CountedPublisher::advertise<sensor_msgs::CameraInfo>(
        nh_, requireValidRosName(pluginTopic(d, PluginTopic::DepthCameraInfo), owner()), 2);
    points_pub_ = CountedPublisher::advertise<sensor_msgs::PointCloud2>(
        nh_, requireValidRosName(pluginTopic(d, PluginTopic::Points), owner()), 2);
    cutoff_ = DepthCutoff{camera_->pointCloudCutoff(), camera_->pointCloudCutoffMax()};
  }

  bool subscribed() const override
  {
    return GazeboRosCamera::subscribed() || depth_pub_.subscribed() || depth_info_pub_.subscribed() ||
           points_pub_.subscribed();
  }

protected:
  DepthCutoff cutoff_;
  bool organized_cloud_ = true;

private:
  void publishFrame(const CameraFrame& frame, const std_msgs::Header& header) override
  {
    if (!camera_->depthSensor())
      return;
    depth_pub_.publisher().publish(DepthImageOf{frame, header, cutoff_});
    depth_info_pub_.publisher().publish(cameraInfo(frame, header));
    points_pub_.publisher().publish(PointCloudOf{frame, header, cutoff_, organized_cloud_, &encoding_});
  }

  CountedPublisher depth_pub_, depth_info_pub_, points_pub_;
};

class GazeboRosDepthCamera : public GazeboRosOpenniKinect
{
public:
  void Load(Sensor& sensor) override
  {
    GazeboRosOpenniKinect::Load(sensor);
    cutoff_.far = std::numeric_limits<double>::infinity();  // Noetic's depth camera reads no pointCloudCutoffMax
    organized_cloud_ = false;
  }
};

GAZEBO_ROS_SENSOR_PLUGIN(GazeboRosOpenniKinect, "libgazebo_ros_openni_kinect.so");
GAZEBO_ROS_SENSOR_PLUGIN(GazeboRosDepthCamera, "libgazebo_ros_depth_camera.so");

}  // namespace bullet_plant
