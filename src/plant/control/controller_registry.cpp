// The controller types this plant offers, by ros_controllers' names: list_controller_types and the
// factory load_controller uses. A new type is its own file and one line here.
#include <functional>

#include "bullet_plant/controllers.h"

namespace bullet_plant
{
// One per type, each defined in its family's file.
std::unique_ptr<Controller> makeAckermannSteeringController();
std::unique_ptr<Controller> makeDiffDriveController();
std::unique_ptr<Controller> makeEffortGroupPositionController();
std::unique_ptr<Controller> makeEffortPidController(bool position);
std::unique_ptr<Controller> makeForwardCommandController(JointInterface iface);
std::unique_ptr<Controller> makeForwardGroupController(JointInterface iface);
std::unique_ptr<Controller> makeGripperActionController(JointInterface iface);
std::unique_ptr<Controller> makeJointStateController();
std::unique_ptr<Controller> makeJointTrajectoryController(JointInterface iface);
std::unique_ptr<Controller> makeMecanumDriveController();

namespace
{
struct ControllerType
{
  const char* name;
  std::function<std::unique_ptr<Controller>()> make;
};

const std::vector<ControllerType>& registry()
{
  static const std::vector<ControllerType> types = {
      {"ackermann_steering_controller/AckermannSteeringController",
       makeAckermannSteeringController},
      {"diff_drive_controller/DiffDriveController",
       makeDiffDriveController},
      {"effort_controllers/GripperActionController",
       [] { return makeGripperActionController(JointInterface::Effort); }},
      {"effort_controllers/JointEffortController",
       [] { return makeForwardCommandController(JointInterface::Effort); }},
      {"effort_controllers/JointGroupEffortController",
       [] { return makeForwardGroupController(JointInterface::Effort); }},
      {"effort_controllers/JointGroupPositionController",
       makeEffortGroupPositionController},
      {"effort_controllers/JointPositionController",
       [] { return makeEffortPidController(true); }},
      {"effort_controllers/JointTrajectoryController",
       [] { return makeJointTrajectoryController(JointInterface::Effort); }},
      {"effort_controllers/JointVelocityController",
       [] { return makeEffortPidController(false); }},
      {"joint_state_controller/JointStateController",
       makeJointStateController},
      {"mecanum_drive_controller/MecanumDriveController",
       makeMecanumDriveController},
      {"position_controllers/GripperActionController",
       [] { return makeGripperActionController(JointInterface::Position); }},
      {"position_controllers/JointGroupPositionController",
       [] { return makeForwardGroupController(JointInterface::Position); }},
      {"position_controllers/JointPositionController",
       [] { return makeForwardCommandController(JointInterface::Position); }},
      {"position_controllers/JointTrajectoryController",
       [] { return makeJointTrajectoryController(JointInterface::Position); }},
      {"velocity_controllers/JointGroupVelocityController",
       [] { return makeForwardGroupController(JointInterface::Velocity); }},
      {"velocity_controllers/JointTrajectoryController",
       [] { return makeJointTrajectoryController(JointInterface::Velocity); }},
      {"velocity_controllers/JointVelocityController",
       [] { return makeForwardCommandController(JointInterface::Velocity); }},
  };
  return types;
}
}  // namespace

const std::vector<std::string>& controllerTypes()
{
  static const std::vector<std::string> names = [] {
    std::vector<std::string> out;
    for (const ControllerType& t : registry())
      out.push_back(t.name);
    return out;
  }();
  return names;
}

std::unique_ptr<Controller> createController(const std::string& type)
{
  for (const ControllerType& t : registry())
    if (type == t.name)
      return t.make();
  return nullptr;
}

}  // namespace bullet_plant
