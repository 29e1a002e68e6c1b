#include "controller_manager_services.h"

#include "bullet_plant/controller_manager.h"
#include "controller_topics.h"
#include "ros_plant.h"

namespace bullet_plant
{
namespace
{
controller_manager_msgs::ControllerState controllerStateMessage(const ControllerInfo& info)
{
  controller_manager_msgs::ControllerState state;
  state.name = info.name;
  state.state = controllerStateName(info.state);
  state.type = info.type;
  for (const ClaimedResources& c : info.claimed_resources)
  {
    controller_manager_msgs::HardwareInterfaceResources r;
    r.hardware_interface = c.hardware_interface;
    r.resources = c.resources;
    state.claimed_resources.push_back(r);
  }
  return state;
}
}  // namespace

ControllerManagerServices::ControllerManagerServices(RosPlant& plant, ControllerManager& manager,
                                                     ControllerTopics& topics, ros::NodeHandle& nh)
  : plant_(plant), manager_(manager), topics_(topics), nh_(nh)
{
  services_.push_back(nh.advertiseService("controller_manager/load_controller", &ControllerManagerServices::load, this));
  services_.push_back(
      nh.advertiseService("controller_manager/unload_controller", &ControllerManagerServices::unload, this));
  services_.push_back(
      nh.advertiseService("controller_manager/switch_controller", &ControllerManagerServices::switchControllers, this));
  services_.push_back(nh.advertiseService("controller_manager/list_controllers", &ControllerManagerServices::list, this));
  services_.push_back(
      nh.advertiseService("controller_manager/list_controller_types", &ControllerManagerServices::listTypes, this));
  services_.push_back(
      nh.advertiseService("controller_manager/reload_controller_libraries", &ControllerManagerServices::reload, this));
}

bool ControllerManagerServices::changeControllers(const std::function<bool()>& change)
{
  return plant_.onSimThread<bool>([&] {
    bool ok = change();
    topics_.refresh();
    return ok;
  });
}

bool ControllerManagerServices::load(Load::Request& req, Load::Response& res)
{
  std::lock_guard<std::mutex> lock(mutex_);
  // As ros_control: a name ROS refuses as a namespace (`a b`, `../x`, `~x`) fails the load with
  // the reason, not the service; every topic of a loaded controller is then a valid name too.
  ros::NodeHandle controller_nh;
  try
  {
    controller_nh = ros::NodeHandle(nh_, req.name);
  }
  catch (const std::exception& e)
  {
    ROS_ERROR("Exception thrown while constructing nodehandle for controller with name '%s':\n%s", req.name.c_str(),
              e.what());
    res.ok = false;
    return true;
  }
  plant_.copyParams(controller_nh.getNamespace());
  // Where ros_controllers read the URDF a controller may need (ackermann_steering_controller's geometry).
  plant_.copyParams(manager_.ns() + "/robot_description");
  res.ok = changeControllers([&] { return manager_.loadController(req.name); });
  return true;
}

bool ControllerManagerServices::unload(Unload::Request& req, Unload::Response& res)
{
  std::lock_guard<std::mutex> lock(mutex_);
  res.ok = changeControllers([&] { return manager_.unloadController(req.name); });
  return true;
}

bool ControllerManagerServices::switchControllers(Switch::Request& req, Switch::Response& res)
{
  std::lock_guard<std::mutex> lock(mutex_);
  res.ok = plant_.onSimThread<bool>([&] {
    return manager_.switchController(req.start_controllers, req.stop_controllers, req.strictness, req.start_asap,
                                     req.timeout);
  });
  // The switch happens in the control loop (at once while paused): wait for it, as the real
  // service does, but never past the caller's timeout or ROS shutdown.
  ros::WallTime start = ros::WallTime::now();
  while (res.ok && ros::ok() && plant_.onSimThread<bool>([&] { return manager_.switchPending(); }))
  {
    if (req.timeout > 0 && (ros::WallTime::now() - start).toSec() > req.timeout)
    {
      ROS_ERROR("Timed out while waiting for the controller switch to be applied");
      res.ok = false;
      break;
    }
    ros::WallDuration(0.0005).sleep();
  }
  return true;
}

bool ControllerManagerServices::list(List::Request&, List::Response& res)
{
  std::lock_guard<std::mutex> lock(mutex_);
  std::vector<ControllerInfo> infos =
      plant_.onSimThread<std::vector<ControllerInfo>>([&] { return manager_.listControllers(); });
  for (const ControllerInfo& info : infos)
    res.controller.push_back(controllerStateMessage(info));
  return true;
}

bool ControllerManagerServices::listTypes(ListTypes::Request&, ListTypes::Response& res)
{
  res.types = manager_.listControllerTypes();
  res.base_classes.assign(res.types.size(), "controller_interface::ControllerBase");
  return true;
}

bool ControllerManagerServices::reload(Reload::Request& req, Reload::Response& res)
{
  std::lock_guard<std::mutex> lock(mutex_);
  res.ok = changeControllers([&] { return manager_.reloadControllerLibraries(req.force_kill); });
  return true;
}

}  // namespace bullet_plant
