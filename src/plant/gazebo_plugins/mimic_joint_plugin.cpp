// roboticsgroup's mimic joint plugin (libroboticsgroup_upatras_gazebo_mimic_joint_plugin.so and
// the older libroboticsgroup_gazebo_mimic_joint_plugin.so, the same tags): every step <mimicJoint>
// follows <joint> * multiplier + offset, by position, or with <hasPID> by an effort from a
// control_toolbox PID whose gains are read at <hasPID> (empty:
// gazebo_ros_control/pid_gains/<mimicJoint>) in its namespace, at most maxEffort (default the
// mimic joint's URDF effort limit). Within sensitiveness of the target nothing is done.
// Parameters and defaults are upstream's (docs/model_plugins.md).
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "bullet_plant/log.h"
#include "bullet_plant/model_plugin.h"
#include "bullet_plant/params.h"
#include "bullet_plant/pid.h"

namespace bullet_plant
{
namespace
{
class MimicJointPlugin : public ModelPlugin
{
public:
  bool Load(const ModelPluginDescription& d, ModelPluginContext& context, int64_t time_ns) override
  {
    context_ = &context;
    const std::string what = pluginLabel(d);
    if (!requireElements(d, context, {"joint", "mimicJoint"},
                         "name the joint to follow in <joint> and the one that follows in <mimicJoint>"))
      return false;
    joint_ = d.text("joint", "");
    double position, velocity;
    if (!context.jointState(joint_, position, velocity))
    {
      context.log().error(what + " <joint> names '" + joint_ + "', which is no movable joint of '" +
                          context.modelName() + "'; the plugin is not loaded");
      return false;
    }
    mimic_ = context.modelJoint(d.text("mimicJoint", ""), what + " <mimicJoint>");
    if (!mimic_)
      return false;
    multiplier_ = d.number("multiplier", 1.0);
    offset_ = d.number("offset", 0.0);
    sensitiveness_ = d.number("sensitiveness", 0.0);
    max_effort_ = d.has("maxEffort") ? d.number("maxEffort", 0.0) : mimic_->effortLimit();
    has_pid_ = d.has("hasPID");
    if (has_pid_)
    {
      std::string name = d.text("hasPID", "");
      if (name.empty())
        name = "gazebo_ros_control/pid_gains/" + d.text("mimicJoint", "");
      const std::string ns = name[0] == '/' ? joinPath("", name) : joinPath(context.pluginNamespace(d), name);
      try
      {
        pid_.setGains(readPidGains(context.params(), ns));
      }
      catch (const std::runtime_error& e)
      {
        context.log().error(what + " <hasPID>: " + e.what() + ": set p (and i, d) there, or drop <hasPID> to "
                                   "follow by position; the plugin is not loaded");
        return false;
      }
    }
    else
      mimic_->setMaxForce(max_effort_);
    Reset(time_ns);
    return true;
  }

  void Reset(int64_t) override { pid_.reset(); }

  void OnUpdate(int64_t) override
  {
    double position, velocity;
    context_->jointState(joint_, position, velocity);
    const double target = position * multiplier_ + offset_;
    double a = mimic_->position();
    if (!(std::fabs(target - a) >= sensitiveness_))
      return;
    if (has_pid_)
    {
      if (std::isnan(a))
        a = target;
      const double effort = pid_.computeCommand(target - a, context_->stepSize());
      mimic_->setForce(std::max(-max_effort_, std::min(effort, max_effort_)));
    }
    else
    {
      // Joint::SetPosition; the plant also moves the joint at the master's rate through the step,
      // by at most maxEffort, so that it follows between the steps' placements instead of being held.
      mimic_->setPosition(target, velocity * multiplier_);
      mimic_->setVelocity(velocity * multiplier_);
    }
  }

private:
  ModelPluginContext* context_ = nullptr;
  std::string joint_;
  ModelJoint* mimic_ = nullptr;
  double multiplier_ = 1.0, offset_ = 0.0, sensitiveness_ = 0.0, max_effort_ = 0.0;
  bool has_pid_ = false;
  Pid pid_;
};
}  // namespace

GAZEBO_ROS_MODEL_PLUGIN(MimicJointPlugin, modelPluginFile(PluginNaming::Default, "hasPID"),
                        "libroboticsgroup_upatras_gazebo_mimic_joint_plugin.so", "libroboticsgroup_gazebo_mimic_joint_plugin.so");

}  // namespace bullet_plant
