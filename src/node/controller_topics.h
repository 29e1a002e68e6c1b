// The topics of one robot's loaded controllers, as ros_controllers have them: std_msgs/Float64 on
// <controller>/command, control_msgs/JointControllerState on <controller>/state and
// sensor_msgs/JointState on joint_states. Commands are posted to the simulation thread; the rest
// runs on it.
#pragma once

#include <map>
#include <string>
#include <utility>
#include <vector>

#include <ros/ros.h>

namespace bullet_plant
{
class Controller;
class ControllerManager;
class RosPlant;

class ControllerTopics
{
public:
  ControllerTopics(RosPlant& plant, ControllerManager& manager, ros::NodeHandle& nh);
  // After a load, unload or reload: subscribers and publishers for exactly the loaded controllers.
  void refresh();
  // After a step: the joint states and controller states the controllers produced.
  void publish();

private:
  ros::Subscriber subscribeCommand(const std::string& name);

  RosPlant& plant_;
  ControllerManager& manager_;
  ros::NodeHandle nh_;
  std::vector<std::pair<std::string, Controller*>> controllers_;  // load order
  std::map<std::string, ros::Subscriber> command_subs_;
  std::map<std::string, ros::Publisher> state_pubs_;
  ros::Publisher joint_states_pub_;
};

}  // namespace bullet_plant
