// gazebo_ros_pkgs' gazebo_ros_harness (libgazebo_ros_harness.so), written over Gazebo's API as
// upstream's is: Gazebo's HarnessPlugin with two ROS subscriptions, /<model>/harness/velocity
// (std_msgs/Float32: the winch's target speed) and /<model>/harness/detach (std_msgs/Bool: true
// lets go), served on their own queue and thread.
#include <memory>
#include <string>

#include <ros/ros.h>
#include <std_msgs/Bool.h>
#include <std_msgs/Float32.h>

#include "gazebo/physics/Model.hh"
#include "gazebo/plugins/HarnessPlugin.hh"
#include "ros_callback_thread.h"

namespace gazebo
{
class GazeboRosHarness : public HarnessPlugin
{
public:
  void Load(physics::ModelPtr _parent, sdf::ElementPtr _sdf) override
  {
    HarnessPlugin::Load(_parent, _sdf);
    if (!_parent || !_sdf)
      return;
    const std::string robot_namespace =
        _sdf->HasElement("robotNamespace") ? _sdf->Get<std::string>("robotNamespace") + "/" : "";
    if (!ros::isInitialized())
    {
      ROS_FATAL_STREAM_NAMED("harness", "Not loading plugin since ROS hasn't been properly initialized.  Try "
                                        "starting gazebo with ros plugin:\n  gazebo -s libgazebo_ros_api_plugin.so\n");
      return;
    }
    ros_.reset(new RosCallbackThread(robot_namespace));
    const std::string prefix = "/" + _parent->GetName() + "/harness/";
    velocity_ = ros_->subscribe<std_msgs::Float32>(
        prefix + "velocity", [this](const std_msgs::Float32::ConstPtr& msg) { SetWinchVelocity(msg->data); });
    detach_ = ros_->subscribe<std_msgs::Bool>(prefix + "detach", [this](const std_msgs::Bool::ConstPtr& msg) {
      if (msg->data)
        Detach();
    });
  }

private:
  ros::Subscriber velocity_, detach_;
  std::unique_ptr<RosCallbackThread> ros_;  // last: it goes first, its thread joined
};

GZ_REGISTER_MODEL_PLUGIN(GazeboRosHarness)
}  // namespace gazebo
