// The simulation's events (gazebo/common/Events.hh): one of each for the process, as in Gazebo.
#include "gazebo/common/Events.hh"

namespace gazebo
{
namespace event
{
EventT<void(bool)> Events::pause;
EventT<void()> Events::step;
EventT<void()> Events::stop;
EventT<void(std::string)> Events::worldCreated;
EventT<void(std::string)> Events::deleteEntity;
EventT<void(const common::UpdateInfo&)> Events::worldUpdateBegin;
EventT<void()> Events::worldUpdateEnd;
EventT<void(const common::UpdateInfo&)> Events::beforePhysicsUpdate;
EventT<void()> Events::worldReset;
EventT<void()> Events::timeReset;
EventT<void()> Events::preRender;
EventT<void()> Events::preRenderEnded;
EventT<void()> Events::render;
EventT<void()> Events::postRender;
}  // namespace event
}  // namespace gazebo
