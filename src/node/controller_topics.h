// The topics of one robot's loaded controllers, as ros_controllers have them: std_msgs/Float64 or
// Float64MultiArray on <controller>/command, geometry_msgs/Twist on <controller>/cmd_vel,
// control_msgs/JointControllerState on <controller>/state, nav_msgs/Odometry on <controller>/odom
// with its transform on /tf, and sensor_msgs/JointState on joint_states. Commands are posted to the
// simulation thread; the rest runs on it.
#pragma once

#include <map>
#include <string>
#include <utility>
#include <vector>

#include <ros/ros.h>

namespace bullet_plant
{
class Controller;
class ControllerManager;
struct OdometryFrames;
struct OdometrySample;
class RosPlant;

class ControllerTopics
{
public:
  ControllerTopics(RosPlant& plant, ControllerManager& manager, ros::NodeHandle& nh);
  // After a load, unload or reload: subscribers and publishers for exactly the loaded controllers.
  void refresh();
  // After a step: the joint states, controller states and odometry the controllers produced.
  void publish();
  // Whether a running controller publishes its odometry's transform (the plant's ground-truth one
  // then stays off /tf: two publishers of one transform would make it jump between them).
  bool publishesOdometryTransform() const;

private:
  ros::Subscriber subscribeCommand(const std::string& name);
  void publishOdometry(const OdometryFrames& frames, const OdometrySample& s, ros::Publisher& pub);

  RosPlant& plant_;
  ControllerManager& manager_;
  ros::NodeHandle nh_;
  std::vector<std::pair<std::string, Controller*>> controllers_;  // load order
  std::map<std::string, ros::Subscriber> command_subs_;
  std::map<std::string, ros::Publisher> state_pubs_, odom_pubs_;
  ros::Publisher joint_states_pub_, tf_pub_;
};

}  // namespace bullet_plant
