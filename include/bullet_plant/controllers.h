// ros_controllers' controller types, hosted by the plant (docs/interfaces.md section 4). Each works
// on joint handles it looks up through JointHandles and exchanges messages through its ports
// (message_ports.h; the messages in messages.h), which the ROS node and Python carry.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "bullet_plant/message_ports.h"
#include "bullet_plant/messages.h"
#include "bullet_plant/hardware_interface.h"
#include "bullet_plant/joint_layer.h"
#include "bullet_plant/pid.h"
#include "bullet_plant/registry.h"

namespace bullet_plant
{
class Param;
class Log;

// What a controller gets to initialise itself: its parameters and the robot's joint handles.
struct ControllerContext
{
  const Param& params;          // the whole parameter tree
  std::string ns;               // the controller's namespace, e.g. "/tianracer/rear_left_velocity_controller"
  JointHandles& joints;
  Log& log;
};

class Controller : public MessagePorts
{
public:
  // Reads parameters, takes handles and opens its ports; false (with the reason logged) when it
  // cannot run.
  virtual bool init(ControllerContext& context) = 0;
  virtual void starting(int64_t time_ns) {}
  virtual void update(int64_t time_ns, double period) = 0;
  virtual void stopping(int64_t time_ns) {}

  virtual const std::vector<ClaimedResources>& claimedResources() const { return claimed_; }

protected:
  std::vector<ClaimedResources> claimed_;
};

using ControllerFactory = std::function<std::unique_ptr<Controller>()>;

// The factory ROS_CONTROLLER_TYPE registers for a class: a new ControllerClass(args...) each call.
template <class ControllerClass, class... Args>
ControllerFactory controllerFactory(Args... args)
{
  return [=] { return std::unique_ptr<Controller>(new ControllerClass(args...)); };
}

// The controller types this plant offers (list_controller_types), sorted, and a factory for them:
// whatever registered itself (ROS_CONTROLLER_TYPE).
inline const std::vector<std::string>& controllerTypes()
{
  static const std::vector<std::string> names = Registry<ControllerFactory>::instance().names();
  return names;
}
// Null for an unknown type.
inline std::unique_ptr<Controller> createController(const std::string& type)
{
  const ControllerFactory* make = Registry<ControllerFactory>::instance().find(type);
  return make ? (*make)() : nullptr;
}

}  // namespace bullet_plant

// In a controller's .cpp, as pluginlib's PLUGINLIB_EXPORT_CLASS: `factory` (a ControllerFactory,
// usually controllerFactory<Class>(constructor arguments)) makes the controller type `type_name`
// ("diff_drive_controller/DiffDriveController"); `id` names the registration, unique in its file.
#define ROS_CONTROLLER_TYPE(id, type_name, factory) \
  BULLET_PLANT_REGISTER(::bullet_plant::ControllerFactory, id, factory, type_name)
