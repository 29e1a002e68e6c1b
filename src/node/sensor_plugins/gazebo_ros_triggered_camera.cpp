// gazebo_ros_triggered_camera: gazebo_ros_camera that renders only when asked. Each std_msgs/Empty
// on <cameraName>/<triggerTopicName> (default image_trigger) is one frame, rendered at the next step
// whatever the sensor's <update_rate> and published as gazebo_ros_camera publishes; triggers that
// come while a frame renders are each one more frame, as upstream counts them (its PreRender enables
// the sensor at rate 0 while the count is positive, OnNewFrame disables it and counts one down).
#include <atomic>

#include <std_msgs/Empty.h>

#include "gazebo_ros_camera.h"
#include "ros_names.h"

namespace bullet_plant
{
class GazeboRosTriggeredCamera : public GazeboRosCamera
{
public:
  void Load(Sensor& sensor) override
  {
    GazeboRosCamera::Load(sensor);
    camera_->setUpdatePeriodNs(0);  // upstream's SetUpdateRate(0) while triggered: the next step renders
    const SensorDescription& d = sensor.description();
    const std::string camera_name = d.pluginParam("cameraName");
    ros::NodeHandle camera_nh = camera_name.empty() ? nh_ : ros::NodeHandle(nh_, camera_name);
    const std::string topic = d.pluginParam("triggerTopicName", "image_trigger");
    trigger_sub_ = camera_nh.subscribe<std_msgs::Empty>(requireValidRosName(topic, owner()), 1,
                                                        [this](const std_msgs::EmptyConstPtr&) { ++triggers_; });
  }

  // The sensor runs while a triggered frame is due, whoever subscribes: OnUpdate decides.
  bool subscribed() const override { return camera_->active(); }

  void OnUpdate() override
  {
    if (camera_->active())  // active through this step: its frame started rendering
    {
      camera_->setActive(false);
      rendering_ = true;
    }
    if (takeUpdate(*camera_))
    {
      publish(camera_->latest());
      rendering_ = false;
      int pending = triggers_.load();
      while (pending > 0 && !triggers_.compare_exchange_weak(pending, pending - 1))
      {
      }
    }
    if (!rendering_ && triggers_ > 0)
      camera_->setActive(true);
  }

private:
  ros::Subscriber trigger_sub_;
  std::atomic<int> triggers_{0};  // counted by ROS's callback threads, down by the simulation's
  bool rendering_ = false;
};

GAZEBO_ROS_SENSOR_PLUGIN(GazeboRosTriggeredCamera, "libgazebo_ros_triggered_camera.so");

}  // namespace bullet_plant
