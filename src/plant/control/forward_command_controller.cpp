// forward_command_controller's types: {position,velocity,effort}_controllers/Joint*Controller forward
// a std_msgs/Float64 to one joint, and JointGroup*Controller a Float64MultiArray to several.
#include "control/controller_support.h"

namespace bullet_plant
{
namespace
{
class ForwardCommandController : public CommandedController
{
public:
  explicit ForwardCommandController(JointInterface iface) : interface_(iface) {}

  bool init(ControllerContext& c) override
  {
    std::string joint;
    handle_ = claimJoint(c, interface_, joint, claimed_);
    return handle_ != nullptr;
  }

  void starting(int64_t) override
  {
    // position_controllers start where the joint is; the others from 0
    command_ = interface_ == JointInterface::Position ? handle_->position() : 0.0;
  }

  void update(int64_t, double) override { handle_->setCommand(command_); }

private:
  JointInterface interface_;
  JointHandle* handle_ = nullptr;
};

// position_controllers/, velocity_controllers/ and effort_controllers/JointGroup*Controller that
// forward each value to its joint: they start from the joints' positions (position) or from 0.
class ForwardGroupController : public JointGroupController
{
public:
  explicit ForwardGroupController(JointInterface iface) : interface_(iface) {}

  bool init(ControllerContext& c) override { return claimJoints(c, interface_); }

  void starting(int64_t) override
  {
    for (size_t k = 0; k < handles_.size(); ++k)
      commands_[k] = interface_ == JointInterface::Position ? handles_[k]->position() : 0.0;
  }

  void update(int64_t, double) override
  {
    for (size_t k = 0; k < handles_.size(); ++k)
      handles_[k]->setCommand(commands_[k]);
  }

private:
  JointInterface interface_;
};
}  // namespace

ROS_CONTROLLER_TYPE(effort_effort, "effort_controllers/JointEffortController",
                    controllerFactory<ForwardCommandController>(JointInterface::Effort));
ROS_CONTROLLER_TYPE(effort_group_effort, "effort_controllers/JointGroupEffortController",
                    controllerFactory<ForwardGroupController>(JointInterface::Effort));
ROS_CONTROLLER_TYPE(position_position, "position_controllers/JointPositionController",
                    controllerFactory<ForwardCommandController>(JointInterface::Position));
ROS_CONTROLLER_TYPE(position_group_position, "position_controllers/JointGroupPositionController",
                    controllerFactory<ForwardGroupController>(JointInterface::Position));
ROS_CONTROLLER_TYPE(velocity_velocity, "velocity_controllers/JointVelocityController",
                    controllerFactory<ForwardCommandController>(JointInterface::Velocity));
ROS_CONTROLLER_TYPE(velocity_group_velocity, "velocity_controllers/JointGroupVelocityController",
                    controllerFactory<ForwardGroupController>(JointInterface::Velocity));

}  // namespace bullet_plant
