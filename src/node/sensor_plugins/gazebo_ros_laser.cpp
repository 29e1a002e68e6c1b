// gazebo_ros_laser and gazebo_ros_gpu_laser: a ray sensor's sensor_msgs/LaserScan on <topicName>
// (default "/world", sic), frame tf::resolve(tf_prefix, <frameName>) (docs/interfaces.md section 11).
#include <sensor_msgs/LaserScan.h>

#include "msg_conversions.h"
#include "ros_names.h"
#include "sensor_plugin.h"

namespace bullet_plant
{
class GazeboRosLaser : public SensorPlugin
{
public:
  void Load(Sensor& sensor) override
  {
    lidar_ = &sensorAs<Lidar>(sensor, "gazebo_ros_laser");
    ros::NodeHandle nh = nodeHandle(sensor);
    frame_id_ = pluginFrameId(sensor.description(), searchedTfPrefix(nh));
    scan_pub_ = CountedPublisher::advertise<sensor_msgs::LaserScan>(
        nh, requireValidRosName(pluginTopic(sensor.description()), "sensor '" + sensor.name() + "' topic"), 5);
  }

  bool subscribed() const override { return scan_pub_.subscribed(); }

  void OnUpdate() override
  {
    if (takeUpdate(*lidar_))
      outbox().publish(scan_pub_.publisher(), toMsg(lidar_->latest(), frame_id_));
  }

private:
  Lidar* lidar_ = nullptr;
  std::string frame_id_;
  CountedPublisher scan_pub_;
};

GAZEBO_ROS_SENSOR_PLUGIN(GazeboRosLaser, "libgazebo_ros_laser.so", "libgazebo_ros_gpu_laser.so");

}  // namespace bullet_plant
