// gazebo_plugins' libgazebo_ros_force.so (ROS 1 Noetic): the last geometry_msgs/Wrench on
// <topicName> applied to <bodyName> every step, force and torque in world axes (Link::AddForce,
// AddTorque). Both elements are required, as upstream (docs/model_plugins.md).
#include <cmath>

#include "bullet_plant/log.h"
#include "bullet_plant/model_plugin.h"
#include "bullet_plant/messages.h"

namespace bullet_plant
{
namespace
{
class GazeboRosForce : public ModelPlugin
{
public:
  bool Load(const ModelPluginDescription& d, ModelPluginContext& context, int64_t) override
  {
    context_ = &context;
    if (!requireElements(d, context, {"bodyName", "topicName"}, "name the link to push and the Wrench topic"))
      return false;
    link_ = d.text("bodyName", "");
    if (!requireLink(d, context, "bodyName", link_))
      return false;
    subscribe<WrenchCommand>(d.text("topicName", ""), [this](const WrenchCommand& w) {
      if (!std::isfinite(w.force.x + w.force.y + w.force.z + w.torque.x + w.torque.y + w.torque.z))
        return false;  // Gazebo would push the link to NaN: the plant keeps the last wrench
      wrench_ = w;
      return true;
    });
    return true;
  }

  // Upstream keeps the wrench over a reset; so does the plant.
  void OnUpdate(int64_t) override { context_->addLinkWrench(link_, wrench_.force, wrench_.torque); }

private:
  ModelPluginContext* context_ = nullptr;
  std::string link_;
  WrenchCommand wrench_;
};
}  // namespace

GAZEBO_ROS_MODEL_PLUGIN(GazeboRosForce, modelPluginFile(), "libgazebo_ros_force.so");

}  // namespace bullet_plant
