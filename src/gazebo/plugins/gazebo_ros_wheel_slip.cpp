// gazebo_ros_pkgs' gazebo_ros_wheel_slip (libgazebo_ros_wheel_slip.so), written over Gazebo's API as
// upstream's is: Gazebo's WheelSlipPlugin with a dynamic_reconfigure server on
// /<model>/<robotNamespace, else wheel_slip>/ whose slip_compliance_unitless_lateral and
// slip_compliance_unitless_longitudinal, when 0 or more, set every wheel's compliance. Served on its
// own queue and thread.
#include <memory>
#include <string>

#include <dynamic_reconfigure/server.h>
#include <ros/ros.h>

#include "gazebo/physics/Model.hh"
#include "gazebo/plugins/WheelSlipPlugin.hh"
#include "ros_callback_thread.h"
#include "tianracer_description/WheelSlipConfig.h"

namespace gazebo
{
class GazeboRosWheelSlip : public WheelSlipPlugin
{
public:
  void Load(physics::ModelPtr _parent, sdf::ElementPtr _sdf) override
  {
    WheelSlipPlugin::Load(_parent, _sdf);
    if (!_parent || !_sdf)
      return;
    std::string robot_namespace = _sdf->HasElement("robotNamespace") ? _sdf->Get<std::string>("robotNamespace") + "/" : "";
    if (robot_namespace.empty() || robot_namespace == "/" || robot_namespace == "//")
      robot_namespace = "wheel_slip/";
    if (!ros::isInitialized())
    {
      ROS_FATAL_STREAM_NAMED("wheel_slip", "Not loading plugin since ROS hasn't been properly initialized.  Try "
                                           "starting gazebo with ros plugin:\n  gazebo -s libgazebo_ros_api_plugin.so\n");
      return;
    }
    ros_.reset(new RosCallbackThread(_parent->GetName() + "/" + robot_namespace));
    server_.reset(new dynamic_reconfigure::Server<tianracer_description::WheelSlipConfig>(ros_->node()));
    server_->setCallback([this](tianracer_description::WheelSlipConfig& config, uint32_t) { configure(config); });
  }

private:
  void configure(const tianracer_description::WheelSlipConfig& config)
  {
    const std::string model = GetParentModel() ? GetParentModel()->GetScopedName() : std::string("?");
    if (config.slip_compliance_unitless_lateral >= 0)
    {
      ROS_INFO_NAMED("wheel_slip", "Reconfigure request for the gazebo ros wheel_slip: %s. New lateral slip compliance: %.3e",
                     model.c_str(), config.slip_compliance_unitless_lateral);
      SetSlipComplianceLateral(config.slip_compliance_unitless_lateral);
    }
    if (config.slip_compliance_unitless_longitudinal >= 0)
    {
      ROS_INFO_NAMED("wheel_slip", "Reconfigure request for the gazebo ros wheel_slip: %s. New longitudinal slip compliance: %.3e",
                     model.c_str(), config.slip_compliance_unitless_longitudinal);
      SetSlipComplianceLongitudinal(config.slip_compliance_unitless_longitudinal);
    }
  }

  std::unique_ptr<dynamic_reconfigure::Server<tianracer_description::WheelSlipConfig>> server_;
  std::unique_ptr<RosCallbackThread> ros_;  // last: it goes first, its thread joined
};

GZ_REGISTER_MODEL_PLUGIN(GazeboRosWheelSlip)
}  // namespace gazebo
