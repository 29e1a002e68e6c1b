#include "controller_topics.h"

#include <control_msgs/JointControllerState.h>
#include <sensor_msgs/JointState.h>
#include <std_msgs/Float64.h>

#include "bullet_plant/controller_manager.h"
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

sensor_msgs::JointState jointStateMessage(const JointStateSample& s)
{
  sensor_msgs::JointState msg;
  msg.header.stamp = rosTime(s.stamp_ns);
  msg.name = s.name;
  msg.position = s.position;
  msg.velocity = s.velocity;
  msg.effort = s.effort;
  return msg;
}

control_msgs::JointControllerState controllerStateMessage(const ControllerStateSample& s)
{
  control_msgs::JointControllerState msg;
  msg.header.stamp = rosTime(s.stamp_ns);
  msg.set_point = s.set_point;
  msg.process_value = s.process_value;
  msg.process_value_dot = s.process_value_dot;
  msg.error = s.error;
  msg.time_step = s.time_step;
  msg.command = s.command;
  msg.p = s.p;
  msg.i = s.i;
  msg.d = s.d;
  msg.i_clamp = s.i_clamp;
  msg.antiwindup = s.antiwindup;
  return msg;
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
  std::map<std::string, ros::Publisher> pubs;
  bool joint_states = false;
  for (const std::string& name : manager_.controllerNames())
  {
    Controller* c = manager_.controller(name);
    controllers_.emplace_back(name, c);
    if (c->hasCommand())
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
    joint_states = joint_states || claimsJointStates(*c);
  }
  command_subs_.swap(subs);
  state_pubs_.swap(pubs);
  if (joint_states && !joint_states_pub_)
    joint_states_pub_ = nh_.advertise<sensor_msgs::JointState>("joint_states", 10);
}

ros::Subscriber ControllerTopics::subscribeCommand(const std::string& name)
{
  return nh_.subscribe<std_msgs::Float64>(name + "/command", 1, [this, name](const std_msgs::Float64ConstPtr& m) {
    double value = m->data;
    plant_.post([this, name, value] {
      Controller* c = manager_.controller(name);
      if (c && !c->setCommand(value))
        ROS_WARN_THROTTLE(1.0, "Rejected a non-finite command (%f) on %s/%s/command", value, manager_.ns().c_str(),
                          name.c_str());
    });
  });
}

void ControllerTopics::publish()
{
  for (auto& entry : controllers_)
  {
    for (const JointStateSample& s : entry.second->takeJointStates())
      joint_states_pub_.publish(jointStateMessage(s));
    auto pub = state_pubs_.find(entry.first);
    for (const ControllerStateSample& s : entry.second->takeControllerStates())
      if (pub != state_pubs_.end())
        pub->second.publish(controllerStateMessage(s));
  }
}

}  // namespace bullet_plant
