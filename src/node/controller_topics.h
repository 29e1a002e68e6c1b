// The topics of one robot's loaded controllers, as ros_controllers have them: <controller>/command,
// <controller>/cmd_vel, <controller>/state, <controller>/odom, joint_states and /tf, from each
// controller's ports (port_topics.h).
#pragma once

#include <ros/ros.h>

#include "port_topics.h"

namespace bullet_plant
{
class ControllerManager;
class RosPlant;

class ControllerTopics
{
public:
  ControllerTopics(RosPlant& plant, ControllerManager& manager, ros::NodeHandle& nh);
  // After a load, unload or reload: subscribers and publishers for exactly the loaded controllers.
  void refresh();
  // After a step: what the controllers published.
  void publish() { topics_.publish(); }
  // Whether a running controller publishes a transform on /tf (the plant's ground-truth odometry
  // then stays off /tf: two publishers of one transform would make it jump between them).
  bool publishesOdometryTransform() const;

private:
  ControllerManager& manager_;
  PortTopics topics_;
};

}  // namespace bullet_plant
