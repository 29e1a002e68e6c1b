// gazebo_ros_p3d: the ground truth of <bodyName> as nav_msgs/Odometry on <topicName>, relative to
// <frameName> (docs/interfaces.md section 11). Unlike the laser and camera plugins it reads
// tf_prefix from its own namespace, without searching up.
#include <nav_msgs/Odometry.h>

#include "msg_conversions.h"
#include "ros_names.h"
#include "sensor_plugin.h"

namespace bullet_plant
{
class GazeboRosP3d : public SensorPlugin
{
public:
  void Load(Sensor& sensor) override
  {
    odometry_ = &sensorAs<GroundTruthOdometry>(sensor, "gazebo_ros_p3d");
    ros::NodeHandle nh = nodeHandle(sensor);
    std::string prefix;
    nh.getParam("tf_prefix", prefix);
    frame_id_ = pluginFrameId(sensor.description(), prefix);
    child_frame_id_ = pluginChildFrameId(sensor.description());
    odometry_pub_ = CountedPublisher::advertise<nav_msgs::Odometry>(
        nh, requireValidRosName(pluginTopic(sensor.description()), "plugin '" + sensor.name() + "' topicName"), 10);
  }

  bool subscribed() const override { return odometry_pub_.subscribed(); }

  void OnUpdate() override
  {
    if (takeUpdate(*odometry_) && odometry_->hasReading())
      outbox().publish(odometry_pub_.publisher(), toMsg(odometry_->latest(), frame_id_, child_frame_id_));
  }

private:
  GroundTruthOdometry* odometry_ = nullptr;
  std::string frame_id_, child_frame_id_;
  CountedPublisher odometry_pub_;
};

GAZEBO_ROS_SENSOR_PLUGIN(GazeboRosP3d, "libgazebo_ros_p3d.so");

}  // namespace bullet_plant
