// gazebo_ros_pkgs' gazebo_ros_harness (libgazebo_ros_harness.so), written over Gazebo's API as
// upstream's is: Gazebo's HarnessPlugin with two ROS subscriptions, /<model>/harness/velocity
// (std_msgs/Float32: the winch's target speed) and /<model>/harness/detach (std_msgs/Bool: true
// lets go), served on their own queue and thread.
#include <memory>
#include <string>
#include <thread>

#include <ros/callback_queue.h>
#include <ros/ros.h>
#include <std_msgs/Bool.h>
#include <std_msgs/Float32.h>

#include "gazebo/physics/Model.hh"
#include "gazebo/plugins/HarnessPlugin.hh"

namespace gazebo
{
class GazeboRosHarness : public HarnessPlugin
{
public:
  ~GazeboRosHarness() override
  {
    queue_.clear();
    queue_.disable();
    if (node_)
      node_->shutdown();
    if (queue_thread_.joinable())
      queue_thread_.join();
  }

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
    node_.reset(new ros::NodeHandle(robot_namespace));
    const std::string prefix = "/" + _parent->GetName() + "/harness/";
    ros::SubscribeOptions velocity = ros::SubscribeOptions::create<std_msgs::Float32>(
        prefix + "velocity", 1, [this](const std_msgs::Float32::ConstPtr& msg) { SetWinchVelocity(msg->data); },
        ros::VoidPtr(), &queue_);
    velocity_ = node_->subscribe(velocity);
    ros::SubscribeOptions detach = ros::SubscribeOptions::create<std_msgs::Bool>(
        prefix + "detach", 1,
        [this](const std_msgs::Bool::ConstPtr& msg) {
          if (msg->data)
            Detach();
        },
        ros::VoidPtr(), &queue_);
    detach_ = node_->subscribe(detach);
    queue_thread_ = std::thread([this] {
      while (node_->ok())
        queue_.callAvailable(ros::WallDuration(0.01));
    });
  }

private:
  std::unique_ptr<ros::NodeHandle> node_;
  ros::Subscriber velocity_, detach_;
  ros::CallbackQueue queue_;
  std::thread queue_thread_;
};

GZ_REGISTER_MODEL_PLUGIN(GazeboRosHarness)
}  // namespace gazebo
