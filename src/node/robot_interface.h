// One robot's ROS side, composed of one part per concern: odometry, its sensors' gazebo_ros plugins
// (one file each, sensor_plugins/sensor_plugin.h), its model plugins' topics (port_topics.h), the e-stop and, when
// the URDF has a gazebo_ros_control block, the controller topics and the controller manager services.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include <ros/ros.h>

#include "controller_manager_services.h"
#include "controller_topics.h"
#include "odometry_publisher.h"
#include "ros_plant.h"
#include "sensor_plugins/sensor_plugin.h"

namespace bullet_plant
{
class Robot;

class RobotInterface : public ModelPlugins
{
public:
  // On the simulation thread (it advertises and subscribes in the robot's control namespace).
  RobotInterface(RosPlant& plant, Robot& robot);
  // Turns each sensor on while someone subscribes to one of its plugin's topics, off otherwise.
  void updateSubscriptions() override;
  // After each step, on the simulation thread: the plugins publish.
  void OnUpdate(int64_t time_ns) override;

private:
  ros::NodeHandle nh_;
  std::unique_ptr<OdometryPublisher> odometry_;  // the plant's ground truth, unless a plugin publishes odometry
  struct LoadedPlugin
  {
    Sensor* sensor;
    std::unique_ptr<SensorPlugin> plugin;
  };
  Robot& robot_;
  std::vector<LoadedPlugin> sensor_plugins_;
  ros::Subscriber estop_sub_;
  // gazebo_plugins' model plugins (diff_drive, ...): each one's ports in its own namespace.
  std::vector<std::unique_ptr<PortTopics>> model_plugin_topics_;
  bool plugin_odometry_ = false;  // a model plugin publishes the robot's odometry: the plant's stays off
  std::unique_ptr<ControllerTopics> controller_topics_;  // these two: null without a controller manager
  std::unique_ptr<ControllerManagerServices> manager_services_;
};

}  // namespace bullet_plant
