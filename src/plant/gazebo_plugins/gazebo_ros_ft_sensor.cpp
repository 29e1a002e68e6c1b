// gazebo_plugins' libgazebo_ros_ft_sensor.so (ROS 1 Noetic): the wrench a joint's child passes to
// it (Joint::GetForceTorque(0): body2Force and body2Torque, with Gazebo's sign: a joint holding a
// load up reads its weight, pointing down; in the child link's frame, the torque about the joint) as geometry_msgs/WrenchStamped on <topicName>, frame the child link's name, at
// <updateRate> (0: every step), each component plus <gaussianNoise>. <jointName> and <topicName>
// are required, as upstream (docs/model_plugins.md).
#include "bullet_plant/gaussian_kernel.h"
#include "bullet_plant/log.h"
#include "bullet_plant/model_plugin.h"
#include "bullet_plant/messages.h"

namespace bullet_plant
{
namespace
{
class GazeboRosFtSensor : public ModelPlugin
{
public:
  bool Load(const ModelPluginDescription& d, ModelPluginContext& context, int64_t time_ns) override
  {
    context_ = &context;
    if (!requireElements(d, context, {"jointName", "topicName"}, "name the joint and the WrenchStamped topic"))
      return false;
    joint_ = d.text("jointName", "");
    if (!context.watchJointWrench(joint_))
    {
      context.log().error(pluginLabel(d) + ": jointName: " + joint_ + " does not exist (or is fixed: Gazebo merges "
                          "fixed joints away) in '" + context.modelName() + "'; the plugin is not loaded");
      return false;
    }
    wrench_.frame_id = context.robotDescription().model->getJoint(joint_)->child_link_name;
    update_rate_ = d.number("updateRate", 0.0);
    noise_ = d.number("gaussianNoise", 0.0);
    port_ = &advertise<WrenchStampedSample>(d.text("topicName", ""));
    Reset(time_ns);
    return true;
  }

  void Reset(int64_t time_ns) override { last_ns_ = time_ns; }

  void OnUpdate(int64_t time_ns) override
  {
    if (update_rate_ > 0 && (time_ns - last_ns_) * 1e-9 < 1.0 / update_rate_)
      return;
    urdf::Vector3 force, torque;
    context_->jointWrench(joint_, force, torque);
    wrench_.stamp_ns = time_ns;
    wrench_.force = urdf::Vector3(force.x + noise(), force.y + noise(), force.z + noise());
    wrench_.torque = urdf::Vector3(torque.x + noise(), torque.y + noise(), torque.z + noise());
    port_->publish(wrench_);
    last_ns_ = time_ns;
  }

private:
  double noise() { return gaussian_kernel_(0.0, noise_); }

  ModelPluginContext* context_ = nullptr;
  std::string joint_;
  double update_rate_ = 0.0, noise_ = 0.0;
  int64_t last_ns_ = 0;
  GaussianKernel gaussian_kernel_;
  WrenchStampedSample wrench_;
  OutputPort<WrenchStampedSample>* port_ = nullptr;
};
}  // namespace

GAZEBO_ROS_MODEL_PLUGIN(GazeboRosFtSensor, modelPluginFile(), "libgazebo_ros_ft_sensor.so");

}  // namespace bullet_plant
