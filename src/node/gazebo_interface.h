// gazebo_ros's simulator interface (its API plugin, Noetic) over the plant: the /gazebo/...
// services with their success flags and status messages (docs/interfaces.md section 10), the
// model_states and link_states topics and the set_model_state / set_link_state topics. Every
// request is answered on the simulation thread, between steps.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <gazebo_msgs/LinkState.h>
#include <gazebo_msgs/ModelState.h>
#include <ros/ros.h>

namespace bullet_plant
{
class Robot;
class RosPlant;

class GazeboInterface
{
public:
  // Advertises in the node's private namespace (/gazebo when the node is named gazebo).
  GazeboInterface(RosPlant& plant, ros::NodeHandle& private_nh);
  // After each step, on the simulation thread: model and link states while someone subscribes
  // (every step, as gazebo_ros publishes them on each world update).
  void publish();

private:
  // set_model_state and set_link_state, service and topic alike (on the simulation thread).
  // Whether the state was set; `message` is gazebo_ros's status message either way.
  bool setModelState(const gazebo_msgs::ModelState& request, std::string& message);
  bool setLinkState(const gazebo_msgs::LinkState& request, std::string& message);

  // Advertises service Srv whose handler (request, response) -> bool runs on the simulation
  // thread, between steps (RosPlant::onSimThread); ROS's callback thread only waits for it.
  template <class Srv, class Handler>
  void serveOnSimThread(ros::NodeHandle& nh, const std::string& name, Handler handler);

  RosPlant& plant_;
  std::vector<ros::ServiceServer> services_;
  std::vector<ros::Subscriber> subscribers_;
  ros::Publisher model_states_pub_, link_states_pub_;
  std::map<std::string, uint32_t> get_model_state_calls_;  // get_model_state's header.seq, per model
};

}  // namespace bullet_plant
