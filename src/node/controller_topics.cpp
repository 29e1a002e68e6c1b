#include "controller_topics.h"

#include <functional>

#include <control_msgs/JointControllerState.h>
#include <geometry_msgs/Twist.h>
#include <tf2_msgs/TFMessage.h>
#include <sensor_msgs/JointState.h>
#include <std_msgs/Float64.h>
#include <std_msgs/Float64MultiArray.h>

#include "bullet_plant/controller_manager.h"
#include "msg_conversions.h"
#include "ros_plant.h"
#include "ros_time.h"

namespace bullet_plant
{
namespace
{
bool claimsJointStates(const Controller& c)
{
  return c.claimedResources().size() == 1 && c.claimedResources()[0].hardware_interface == kJointStateInterface;
}

}  // namespace

ControllerTopics::ControllerTopics(RosPlant& plant, ControllerManager& manager, ros::NodeHandle& nh)
  : plant_(plant), manager_(manager), nh_(nh)
{
}

void ControllerTopics::refresh()
{
  controllers_.clear();
  std::map<std::string, ros::Subscriber> subs;
  std::map<std::string, ros::Publisher> pubs, odom_pubs;
  bool joint_states = false;
  for (const std::string& name : manager_.controllerNames())
  {
    Controller* c = manager_.controller(name);
    controllers_.emplace_back(name, c);
    if (c->commandTopic() != CommandTopic::None)
    {
      auto it = command_subs_.find(name);
      subs[name] = it != command_subs_.end() ? it->second : subscribeCommand(name);
    }
    if (c->hasState())
    {
      auto pub = state_pubs_.find(name);
      pubs[name] = pub != state_pubs_.end() ? pub->second
                                            : nh_.advertise<control_msgs::JointControllerState>(name + "/state", 1);
    }
    if (c->odometryFrames())
    {
      auto pub = odom_pubs_.find(name);
      odom_pubs[name] = pub != odom_pubs_.end() ? pub->second : nh_.advertise<nav_msgs::Odometry>(name + "/odom", 100);
      if (!tf_pub_)
        tf_pub_ = nh_.advertise<tf2_msgs::TFMessage>("/tf", 100);
    }
    joint_states = joint_states || claimsJointStates(*c);
  }
  command_subs_.swap(subs);
  state_pubs_.swap(pubs);
  odom_pubs_.swap(odom_pubs);
  if (joint_states && !joint_states_pub_)
    joint_states_pub_ = nh_.advertise<sensor_msgs::JointState>("joint_states", 10);
}

ros::Subscriber ControllerTopics::subscribeCommand(const std::string& name)
{
  // The controller may be gone (unloaded) when the posted work runs: look it up there.
  auto post = [this, name](std::function<bool(Controller&)> apply, std::string what) {
    plant_.post([this, name, apply, what] {
      Controller* c = manager_.controller(name);
      if (c && !apply(*c))
        ROS_WARN_THROTTLE(1.0, "Rejected %s on %s/%s/command", what.c_str(), manager_.ns().c_str(), name.c_str());
    });
  };
  switch (manager_.controller(name)->commandTopic())
  {
    case CommandTopic::Float64:
      return nh_.subscribe<std_msgs::Float64>(name + "/command", 1, [post](const std_msgs::Float64ConstPtr& m) {
        double value = m->data;
        post([value](Controller& c) { return c.setCommand(value); },
             "a non-finite command (" + std::to_string(value) + ")");
      });
    case CommandTopic::Float64MultiArray:
      return nh_.subscribe<std_msgs::Float64MultiArray>(
          name + "/command", 1, [post](const std_msgs::Float64MultiArrayConstPtr& m) {
            std::vector<double> values = m->data;
            post([values](Controller& c) { return c.setCommands(values); }, "a command (the controller logs why)");
          });
    case CommandTopic::Twist:
      return nh_.subscribe<geometry_msgs::Twist>(name + "/cmd_vel", 1, [post](const geometry_msgs::TwistConstPtr& m) {
        double linear = m->linear.x, angular = m->angular.z;
        post([linear, angular](Controller& c) { return c.setTwist(linear, angular); },
             "a velocity command (the controller logs why)");
      });
    default:
      return ros::Subscriber();
  }
}

void ControllerTopics::publish()
{
  for (auto& entry : controllers_)
  {
    for (const JointStateSample& s : entry.second->takeJointStates())
      joint_states_pub_.publish(toMsg(s));
    auto pub = state_pubs_.find(entry.first);
    for (const ControllerStateSample& s : entry.second->takeControllerStates())
      if (pub != state_pubs_.end())
        pub->second.publish(toMsg(s));
    auto odom_pub = odom_pubs_.find(entry.first);
    for (const OdometrySample& s : entry.second->takeOdometry())
      if (odom_pub != odom_pubs_.end())
        publishOdometry(*entry.second->odometryFrames(), s, odom_pub->second);
  }
}

void ControllerTopics::publishOdometry(const OdometryFrames& frames, const OdometrySample& s, ros::Publisher& pub)
{
  urdf::Pose pose;
  pose.position = urdf::Vector3(s.x, s.y, 0.0);
  pose.rotation.setFromRPY(0.0, 0.0, s.heading);
  nav_msgs::Odometry odom = odometryMessage(s.stamp_ns, frames.odom_frame_id, frames.base_frame_id, pose,
                                            urdf::Vector3(s.linear, 0, 0), urdf::Vector3(0, 0, s.angular));
  for (int k = 0; k < 6; ++k)
  {
    odom.pose.covariance[7 * k] = frames.pose_covariance_diagonal[k];
    odom.twist.covariance[7 * k] = frames.twist_covariance_diagonal[k];
  }
  pub.publish(odom);
  if (!frames.enable_odom_tf)
    return;
  tf2_msgs::TFMessage msg;
  msg.transforms.push_back(odometryTransform(odom));
  tf_pub_.publish(msg);
}

bool ControllerTopics::publishesOdometryTransform() const
{
  return manager_.anyRunning([](const Controller& c) { return c.odometryFrames() && c.odometryFrames()->enable_odom_tf; });
}

}  // namespace bullet_plant
