// gazebo_plugins' libgazebo_ros_f3d.so (ROS 1 Noetic): every step, the force and torque added so far
// to <bodyName> (Link::WorldForce, WorldTorque: what plugins and apply_body_wrench put there before
// it, world axes; not gravity or contacts, as ODE's accumulators read at world update begin) as
// geometry_msgs/WrenchStamped on <topicName>, frame <frameName> ("world"). <bodyName> and
// <topicName> are required, as upstream (docs/model_plugins.md).
#include "bullet_plant/model_plugin.h"
#include "bullet_plant/messages.h"
#include "bullet_plant/plugin_names.h"

namespace bullet_plant
{
namespace
{
class GazeboRosF3d : public ModelPlugin
{
public:
  bool Load(const ModelPluginDescription& d, ModelPluginContext& context, int64_t) override
  {
    context_ = &context;
    if (!requireElements(d, context, {"bodyName", "topicName"}, "name the link and the WrenchStamped topic"))
      return false;
    link_ = d.text("bodyName", "");
    if (!requireLink(d, context, "bodyName", link_))
      return false;
    wrench_.frame_id = resolveTfFrame(context.tfPrefix(d), d.text("frameName", "world"));
    port_ = &advertise<WrenchStampedSample>(d.text("topicName", ""));
    return true;
  }

  void OnUpdate(int64_t time_ns) override
  {
    wrench_.stamp_ns = time_ns;
    context_->addedLinkWrench(link_, wrench_.force, wrench_.torque);
    port_->publish(wrench_);
  }

private:
  ModelPluginContext* context_ = nullptr;
  std::string link_;
  WrenchStampedSample wrench_;
  OutputPort<WrenchStampedSample>* port_ = nullptr;
};
}  // namespace

GAZEBO_ROS_MODEL_PLUGIN(GazeboRosF3d, modelPluginFile(), "libgazebo_ros_f3d.so");

}  // namespace bullet_plant
