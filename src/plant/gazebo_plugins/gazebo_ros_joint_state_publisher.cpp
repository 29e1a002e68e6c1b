// gazebo_plugins' libgazebo_ros_joint_state_publisher.so (ROS 1 Noetic): sensor_msgs/JointState on
// joint_states in its namespace at updateRate, the name, position and velocity of each joint in the
// comma-separated <jointName>, driven or not. Parameters and defaults are upstream's
// (docs/model_plugins.md).
#include <algorithm>
#include <sstream>

#include "bullet_plant/log.h"
#include "bullet_plant/model_plugin.h"
#include "bullet_plant/rate_gate.h"

namespace bullet_plant
{
namespace
{
class GazeboRosJointStatePublisher : public ModelPlugin
{
public:
  bool Load(const ModelPluginDescription& d, ModelPluginContext& context, int64_t time_ns) override
  {
    context_ = &context;
    const std::string what = pluginLabel(d);
    std::string names = d.text("jointName", "");
    names.erase(std::remove(names.begin(), names.end(), ' '), names.end());
    std::stringstream list(names);
    for (std::string joint; std::getline(list, joint, ',');)
    {
      double position, velocity;
      // Gazebo has no joint by that name (URDF fixed joints are merged away) and upstream's publish
      // would dereference null: the plant leaves the joint out, said once.
      if (!context.jointState(joint, position, velocity))
        context.log().error(what + " <jointName> names '" + joint + "', which is no movable joint of '" +
                            context.modelName() + "'; it is left out of joint_states");
      else
        joint_names_.push_back(joint);
    }
    if (joint_names_.empty())
    {
      context.log().error(what + " has no joint to publish: give <jointName> a comma-separated list of the model's "
                                 "movable joints; the plugin is not loaded");
      return false;
    }
    const double update_rate = d.number("updateRate", 100.0);
    update_gate_.setPeriodNs(periodNsOfRate(update_rate));
    port_ = &advertise<JointStateSample>("joint_states");
    Reset(time_ns);
    return true;
  }

  void Reset(int64_t time_ns) override { update_gate_.restart(time_ns); }

  void OnUpdate(int64_t time_ns) override
  {
    if (!update_gate_.due(time_ns))
      return;
    JointStateSample s;
    s.stamp_ns = time_ns;
    s.name = joint_names_;
    s.position.resize(joint_names_.size());
    s.velocity.resize(joint_names_.size());
    for (size_t i = 0; i < joint_names_.size(); ++i)
      context_->jointState(joint_names_[i], s.position[i], s.velocity[i]);
    port_->publish(s);
  }

private:
  ModelPluginContext* context_ = nullptr;
  std::vector<std::string> joint_names_;
  CatchUpRateGate update_gate_;  // updateRate
  OutputPort<JointStateSample>* port_ = nullptr;
};
}  // namespace

GAZEBO_ROS_MODEL_PLUGIN(GazeboRosJointStatePublisher, modelPluginFile(PluginNaming::ModelNamespace),
                        "libgazebo_ros_joint_state_publisher.so");

}  // namespace bullet_plant
