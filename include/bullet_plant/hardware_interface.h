// What controllers see of a robot: hardware_interface's role in ros_control (docs/interfaces.md
// section 5). A controller looks its joints up by name and reports what it claims; it never sees the
// robot, the world or the physics behind the handles.
#pragma once

#include <string>
#include <vector>

#include "bullet_plant/joint_layer.h"

namespace bullet_plant
{
// hardware_interface's name for the read-only joint state handles (what joint_state_controller claims).
constexpr const char* kJointStateInterface = "hardware_interface::JointStateInterface";

// The joints of one robot that have a transmission (RobotHW with its JointStateInterface and
// JointCommandInterfaces): every handle carries the joint's state, and its interface() says which
// command interface it belongs to.
class JointHandles
{
public:
  virtual ~JointHandles() = default;
  // The handle of the named joint, null when no transmission gives it one (getHandle).
  virtual JointHandle* handle(const std::string& joint) = 0;
  // Every handle, in transmission order.
  virtual std::vector<JointHandle>& handles() = 0;

protected:
  JointHandles() = default;
  JointHandles(const JointHandles&) = default;
  JointHandles& operator=(const JointHandles&) = default;
};

// What a controller claims on one hardware interface (hardware_interface::InterfaceResources), as
// list_controllers reports it.
struct ClaimedResources
{
  std::string hardware_interface;  // e.g. "hardware_interface::VelocityJointInterface"
  std::vector<std::string> resources;
};

}  // namespace bullet_plant
