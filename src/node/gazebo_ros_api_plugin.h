// gazebo_ros's simulator interface (GazeboRosApiPlugin, Noetic) over the plant: the /gazebo/...
// services with their success flags and status messages (docs/interfaces.md section 10), the
// model_states and link_states topics, the set_model_state / set_link_state topics and the physics'
// dynamic_reconfigure (set_parameters, parameter_descriptions, parameter_updates), all of it left out
// with ~enable_ros_network false as Gazebo leaves it out. One member function per service, named as
// upstream's, wired in advertiseServices(). Every request is answered on the simulation thread,
// between steps; the spawn and delete services hand their work to RosPlant, which does the same.
// Beside them the plant's own topics for viewers (~scene, ~scene_link_states, ~scene_contacts,
// ~step_physics), advertised once a node asks for one of them, so that without a viewer the graph is
// gazebo_ros's own.
#pragma once

#include <atomic>
#include <cstdint>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include <gazebo_msgs/ApplyBodyWrench.h>
#include <gazebo_msgs/ApplyJointEffort.h>
#include <gazebo_msgs/BodyRequest.h>
#include <gazebo_msgs/DeleteLight.h>
#include <gazebo_msgs/DeleteModel.h>
#include <dynamic_reconfigure/server.h>
#include <gazebo_msgs/GetJointProperties.h>
#include <gazebo_msgs/GetLightProperties.h>
#include <gazebo_msgs/GetLinkProperties.h>
#include <gazebo_msgs/GetLinkState.h>
#include <gazebo_msgs/GetModelProperties.h>
#include <gazebo_msgs/GetModelState.h>
#include <gazebo_msgs/GetPhysicsProperties.h>
#include <gazebo_msgs/GetWorldProperties.h>
#include <gazebo_msgs/LinkStates.h>
#include <gazebo_msgs/JointRequest.h>
#include <gazebo_msgs/LinkState.h>
#include <gazebo_msgs/ModelState.h>
#include <gazebo_msgs/SetJointProperties.h>
#include <gazebo_msgs/SetLightProperties.h>
#include <gazebo_msgs/SetLinkProperties.h>
#include <gazebo_msgs/SetLinkState.h>
#include <gazebo_msgs/SetModelConfiguration.h>
#include <gazebo_msgs/SetModelState.h>
#include <gazebo_msgs/SetPhysicsProperties.h>
#include <gazebo_msgs/SpawnModel.h>
#include <ros/ros.h>
#include <std_srvs/Empty.h>
#include <tianracer_description/PhysicsConfig.h>

#include "bullet_plant/rate_gate.h"
#include "counted_publisher.h"

namespace bullet_plant
{
class RosPlant;
class World;

class GazeboRosApiPlugin
{
public:
  // Advertises in the node's private namespace (/gazebo when the node is named gazebo); with the
  // parameter ~enable_ros_network false (empty_world.launch's argument), none of gazebo_ros's services
  // and topics, as Gazebo: /clock (RosPlant's) and roscpp's logger services stay.
  GazeboRosApiPlugin(RosPlant& plant, ros::NodeHandle& private_nh);
  // After each step, on the simulation thread: model and link states while someone subscribes
  // (every step, as gazebo_ros publishes them on each world update).
  void publishModelStates();
  // link_states every step while subscribed (gazebo_ros's), and ~scene_link_states, the same at
  // ~scene_rate Hz of simulated time (default 30) for viewers, and after the last step of a
  // step_physics request.
  void publishLinkStates();
  // ~scene_link_states at once, after a pose set by hand (set_model_state, set_link_state,
  // set_model_configuration, the resets, spawn, delete): viewers see it paused too, as gzclient does.
  void publishScenePoses();
  // ~scene_contacts: every contact of the world (gazebo_msgs/ContactsState in the world frame, a
  // state per pair of collisions, collision1's forces) at ~scene_rate while subscribed, for viewers.
  void publishSceneContacts();
  // ~scene (latched): what a viewer draws (bullet_plant/scene.h), on the simulation thread (or
  // before it runs); nothing before a viewer asked for the viewers' topics.
  void publishScene();

private:
  void advertiseServices();
  // Advertises service Srv whose handler runs on the simulation thread (RosPlant::onSimThread);
  // ROS's callback thread only waits for it.
  template <class Srv>
  void advertiseOnSimThread(const std::string& name,
                            bool (GazeboRosApiPlugin::*handler)(typename Srv::Request&, typename Srv::Response&));

  // On ROS's callback thread: spawning parses the model before it visits the simulation thread.
  bool spawnURDFModel(gazebo_msgs::SpawnModel::Request& req, gazebo_msgs::SpawnModel::Response& res);
  bool spawnSDFModel(gazebo_msgs::SpawnModel::Request& req, gazebo_msgs::SpawnModel::Response& res);
  bool spawnModel(gazebo_msgs::SpawnModel::Request& req, gazebo_msgs::SpawnModel::Response& res);
  bool deleteModel(gazebo_msgs::DeleteModel::Request& req, gazebo_msgs::DeleteModel::Response& res);

  // On the simulation thread.
  bool pausePhysics(std_srvs::Empty::Request& req, std_srvs::Empty::Response& res);
  bool unpausePhysics(std_srvs::Empty::Request& req, std_srvs::Empty::Response& res);
  bool resetSimulation(std_srvs::Empty::Request& req, std_srvs::Empty::Response& res);
  bool resetWorld(std_srvs::Empty::Request& req, std_srvs::Empty::Response& res);
  bool getModelState(gazebo_msgs::GetModelState::Request& req, gazebo_msgs::GetModelState::Response& res);
  bool getLinkState(gazebo_msgs::GetLinkState::Request& req, gazebo_msgs::GetLinkState::Response& res);
  bool setModelState(gazebo_msgs::SetModelState::Request& req, gazebo_msgs::SetModelState::Response& res);
  bool setLinkState(gazebo_msgs::SetLinkState::Request& req, gazebo_msgs::SetLinkState::Response& res);
  bool setModelConfiguration(gazebo_msgs::SetModelConfiguration::Request& req,
                             gazebo_msgs::SetModelConfiguration::Response& res);
  bool getWorldProperties(gazebo_msgs::GetWorldProperties::Request& req, gazebo_msgs::GetWorldProperties::Response& res);
  bool getModelProperties(gazebo_msgs::GetModelProperties::Request& req, gazebo_msgs::GetModelProperties::Response& res);
  // The robot with the joint a service names (by its name or MODEL::JOINT), and that joint's name in
  // it; null for none.
  Robot* jointOwner(const std::string& requested, std::string& joint);
  bool getJointProperties(gazebo_msgs::GetJointProperties::Request& req, gazebo_msgs::GetJointProperties::Response& res);
  bool getPhysicsProperties(gazebo_msgs::GetPhysicsProperties::Request& req,
                            gazebo_msgs::GetPhysicsProperties::Response& res);
  bool setPhysicsProperties(gazebo_msgs::SetPhysicsProperties::Request& req,
                            gazebo_msgs::SetPhysicsProperties::Response& res);
  bool applyBodyWrench(gazebo_msgs::ApplyBodyWrench::Request& req, gazebo_msgs::ApplyBodyWrench::Response& res);
  bool clearBodyWrenches(gazebo_msgs::BodyRequest::Request& req, gazebo_msgs::BodyRequest::Response& res);
  bool applyJointEffort(gazebo_msgs::ApplyJointEffort::Request& req, gazebo_msgs::ApplyJointEffort::Response& res);
  bool clearJointForces(gazebo_msgs::JointRequest::Request& req, gazebo_msgs::JointRequest::Response& res);
  bool setJointProperties(gazebo_msgs::SetJointProperties::Request& req, gazebo_msgs::SetJointProperties::Response& res);
  bool getLinkProperties(gazebo_msgs::GetLinkProperties::Request& req, gazebo_msgs::GetLinkProperties::Response& res);
  bool setLinkProperties(gazebo_msgs::SetLinkProperties::Request& req, gazebo_msgs::SetLinkProperties::Response& res);
  bool getLightProperties(gazebo_msgs::GetLightProperties::Request& req,
                          gazebo_msgs::GetLightProperties::Response& res);
  bool setLightProperties(gazebo_msgs::SetLightProperties::Request& req,
                          gazebo_msgs::SetLightProperties::Response& res);
  bool deleteLight(gazebo_msgs::DeleteLight::Request& req, gazebo_msgs::DeleteLight::Response& res);

  // set_physics_properties' work, for the service and the reconfigure alike: false with the reason
  // in `message` when a value is refused, and nothing changed then.
  bool applyPhysics(const gazebo_msgs::SetPhysicsProperties::Request& req, std::string& message);
  // gazebo_ros's physicsReconfigureCallback: the first call (from the constructor, before the
  // simulation runs) fills the config from the physics; a later one (set_parameters) applies the
  // config on the simulation thread when it differs from the physics.
  void physicsReconfigure(tianracer_description::PhysicsConfig& config, uint32_t level);
  // A warning, once per name, for a setting the plant does not honour.
  void sayNotHonoured(const std::string& name, const std::string& why);

  // Every second until a node subscribes to ~scene, ~scene_link_states or ~scene_contacts, or
  // publishes on ~step_physics (the master's system state): then advertiseViewerTopics on the
  // simulation thread, once.
  void watchForViewers();
  bool aViewerAsks() const;
  void advertiseViewerTopics();

  // set_model_state and set_link_state, service and topic alike: whether the state was set;
  // `message` is gazebo_ros's status message either way.
  bool updateModelState(const gazebo_msgs::ModelState& state, std::string& message);
  bool updateLinkState(const gazebo_msgs::LinkState& state, std::string& message);

  RosPlant& plant_;
  World& world_;
  ros::NodeHandle nh_;
  bool enable_ros_network_ = true;
  std::unique_ptr<dynamic_reconfigure::Server<tianracer_description::PhysicsConfig>> physics_reconfigure_;
  bool physics_reconfigure_initialized_ = false;
  std::set<std::string> said_not_honoured_;
  ros::WallTimer viewer_watch_;
  std::atomic<bool> viewers_asked_{false};
  std::vector<ros::ServiceServer> services_;
  std::vector<ros::Subscriber> subscribers_;
  gazebo_msgs::LinkStates linkStates();
  static constexpr double kDefaultSceneRate = 30.0;  // Hz
  // Asked after every step whether anyone subscribes: counted (counted_publisher.h).
  CountedPublisher model_states_pub_, link_states_pub_, scene_link_states_pub_, scene_contacts_pub_;
  ros::Publisher scene_pub_;
  RateGate scene_link_states_gate_, scene_contacts_gate_;
  std::map<std::string, uint32_t> get_model_state_calls_;  // get_model_state's header.seq, per model
};

}  // namespace bullet_plant
