#include "controller_topics.h"

#include "bullet_plant/controller_manager.h"

namespace bullet_plant
{
ControllerTopics::ControllerTopics(RosPlant& plant, ControllerManager& manager, ros::NodeHandle& nh)
  : manager_(manager), topics_(plant, nh, [&manager](const std::string& name) -> const MessagePorts* {
      return manager.controller(name);
    })
{
}

void ControllerTopics::refresh()
{
  std::vector<std::pair<std::string, const MessagePorts*>> controllers;
  for (const std::string& name : manager_.controllerNames())
    controllers.emplace_back(name, manager_.controller(name));
  topics_.refresh(controllers);
}

bool ControllerTopics::publishesOdometryTransform() const
{
  return manager_.anyRunning([](const Controller& c) { return c.output<TransformSample>() != nullptr; });
}

}  // namespace bullet_plant
