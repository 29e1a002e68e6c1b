// The six controller manager services of one robot (controller_manager_msgs, docs/interfaces.md
// sections 1 and 2) under <namespace>/controller_manager/. Each call runs on the simulation thread
// and the callers are served one at a time, as the real manager does.
#pragma once

#include <functional>
#include <mutex>
#include <vector>

#include <controller_manager_msgs/ListControllerTypes.h>
#include <controller_manager_msgs/ListControllers.h>
#include <controller_manager_msgs/LoadController.h>
#include <controller_manager_msgs/ReloadControllerLibraries.h>
#include <controller_manager_msgs/SwitchController.h>
#include <controller_manager_msgs/UnloadController.h>
#include <ros/ros.h>

namespace bullet_plant
{
class ControllerManager;
class ControllerTopics;
class RosPlant;

class ControllerManagerServices
{
public:
  // `topics` is refreshed after every load, unload and reload.
  ControllerManagerServices(RosPlant& plant, ControllerManager& manager, ControllerTopics& topics, ros::NodeHandle& nh);

private:
  using Load = controller_manager_msgs::LoadController;
  using Unload = controller_manager_msgs::UnloadController;
  using Switch = controller_manager_msgs::SwitchController;
  using List = controller_manager_msgs::ListControllers;
  using ListTypes = controller_manager_msgs::ListControllerTypes;
  using Reload = controller_manager_msgs::ReloadControllerLibraries;

  bool load(Load::Request& req, Load::Response& res);
  bool unload(Unload::Request& req, Unload::Response& res);
  bool switchControllers(Switch::Request& req, Switch::Response& res);
  bool list(List::Request& req, List::Response& res);
  bool listTypes(ListTypes::Request& req, ListTypes::Response& res);
  bool reload(Reload::Request& req, Reload::Response& res);
  // A load, unload or reload on the simulation thread, the topics refreshed to match.
  bool changeControllers(const std::function<bool()>& change);

  RosPlant& plant_;
  ControllerManager& manager_;
  ControllerTopics& topics_;
  ros::NodeHandle nh_;  // the robot namespace's: controllers live under it
  std::mutex mutex_;  // one call at a time
  std::vector<ros::ServiceServer> services_;
};

}  // namespace bullet_plant
