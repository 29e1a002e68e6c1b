// gazebo_ros_imu_sensor (inside <sensor type="imu">) and gazebo_ros_imu (a model plugin): the
// IMU's sensor_msgs/Imu on their topic in their namespace. The two differ in parameters, defaults,
// namespace and reference orientation, all of which the plant's Imu reads from the <plugin> block
// (docs/interfaces.md section 11); on ROS they publish alike.
#include <sensor_msgs/Imu.h>

#include "msg_conversions.h"
#include "ros_names.h"
#include "sensor_plugin.h"

namespace bullet_plant
{
class GazeboRosImu : public SensorPlugin
{
public:
  void Load(Sensor& sensor) override
  {
    imu_ = &sensorAs<Imu>(sensor, "gazebo_ros_imu");
    frame_id_ = pluginFrameId(sensor.description(), "");  // neither IMU plugin takes a tf_prefix
    imu_pub_ = CountedPublisher::advertise<sensor_msgs::Imu>(
        nodeHandle(sensor), requireValidRosName(pluginTopic(sensor.description()), "sensor '" + sensor.name() + "' topic"),
        10);
  }

  bool subscribed() const override { return imu_pub_.subscribed(); }

  void OnUpdate() override
  {
    if (takeUpdate(*imu_) && imu_->hasReading())
      outbox().publish(imu_pub_.publisher(), toMsg(imu_->latest(), frame_id_));
  }

private:
  Imu* imu_ = nullptr;
  std::string frame_id_;
  CountedPublisher imu_pub_;
};

GAZEBO_ROS_SENSOR_PLUGIN(GazeboRosImu, "libgazebo_ros_imu_sensor.so", "libgazebo_ros_imu.so");

}  // namespace bullet_plant
