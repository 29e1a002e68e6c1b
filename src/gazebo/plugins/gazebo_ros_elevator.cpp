// gazebo_ros_pkgs' gazebo_ros_elevator (libgazebo_ros_elevator.so), written over Gazebo's API as
// upstream's is: Gazebo's ElevatorPlugin with a ROS subscription. A floor number in a
// std_msgs/String on <topic> ("elevator", in <robotNamespace>) calls MoveToFloor; the plugin's
// Gazebo topic stays as ElevatorPlugin reads it. Where upstream's throws on a message that is not a
// number (std::stoi, which ends the server), this says so on ROS's log and the elevator stays.
#include <memory>
#include <string>

#include <ros/ros.h>
#include <std_msgs/String.h>

#include "gazebo/plugins/ElevatorPlugin.hh"
#include "ros_callback_thread.h"

namespace gazebo
{
class GazeboRosElevator : public ElevatorPlugin
{
public:
  void Load(physics::ModelPtr _parent, sdf::ElementPtr _sdf) override
  {
    const std::string robot_namespace =
        _sdf && _sdf->HasElement("robotNamespace") ? _sdf->Get<std::string>("robotNamespace") + "/" : "";
    if (!ros::isInitialized())
    {
      ROS_FATAL_STREAM_NAMED("elevator", "A ROS node for Gazebo has not been initialized, unable to load plugin. "
                                         "Load the Gazebo system plugin 'libgazebo_ros_api_plugin.so' in the "
                                         "gazebo_ros package)");
      return;
    }
    const std::string topic = _sdf && _sdf->HasElement("topic") ? _sdf->Get<std::string>("topic") : "elevator";
    ElevatorPlugin::Load(_parent, _sdf);
    ros_.reset(new RosCallbackThread(robot_namespace));
    subscriber_ = ros_->subscribe<std_msgs::String>(
        topic, [this](const std_msgs::String::ConstPtr& message) { OnElevator(message); });
  }

private:
  void OnElevator(const std_msgs::String::ConstPtr& message)
  {
    try
    {
      MoveToFloor(std::stoi(message->data));
    }
    catch (const std::exception&)
    {
      ROS_ERROR_STREAM_NAMED("elevator", "elevator: '" << message->data << "' on " << subscriber_.getTopic()
                                                       << " is not a floor number; the elevator stays");
    }
  }

  ros::Subscriber subscriber_;
  std::unique_ptr<RosCallbackThread> ros_;  // last: it goes first, its thread joined
};

GZ_REGISTER_MODEL_PLUGIN(GazeboRosElevator)
}  // namespace gazebo
