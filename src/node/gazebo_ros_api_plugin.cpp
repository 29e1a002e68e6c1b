#include "gazebo_ros_api_plugin.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include <gazebo_msgs/ContactsState.h>
#include <gazebo_msgs/LinkStates.h>
#include <gazebo_msgs/ModelStates.h>
#include <std_msgs/String.h>
#include <std_msgs/UInt32.h>
#include <tinyxml2.h>

#include "bullet_plant/geometry.h"
#include "bullet_plant/rate_gate.h"
#include "bullet_plant/scene.h"
#include "bullet_plant/world.h"
#include "msg_conversions.h"
#include "ros_plant.h"
#include "ros_time.h"

namespace bullet_plant
{
namespace
{
// ------------------------------------------------------------------------------ frames and states

// gazebo_ros takes these reference frame names as the world.
bool isWorldFrame(const std::string& frame) { return frame.empty() || frame == "world" || frame == "map" || frame == "/map"; }

// A link by gazebo_ros's scoped name, model::link: a robot's, or a static model's (at rest).
struct LinkRef
{
  Robot* robot = nullptr;
  std::string link;
  const StaticModelDescription::Link* static_link = nullptr;
  explicit operator bool() const { return robot != nullptr || static_link != nullptr; }
};

LinkRef findLink(World& world, const std::string& scoped)
{
  const size_t at = scoped.find("::");
  if (at == std::string::npos)
    return {};
  const std::string model = scoped.substr(0, at), link = scoped.substr(at + 2);
  if (Robot* robot = world.robot(model))
  {
    for (const std::string& name : robot->linkNames())
      if (name == link)
        return {robot, link, nullptr};
  }
  else if (const StaticModelDescription* fixed = world.staticModel(model))
    for (const StaticModelDescription::Link& l : fixed->links)
      if (l.name == link)
        return {nullptr, link, &l};
  return {};
}

// A robot's link by its scoped name: what the services that act on a link's dynamics reach (a static
// model's links never move: Gazebo's static links take no state, wrench or mass).
LinkRef findRobotLink(World& world, const std::string& scoped)
{
  const LinkRef link = findLink(world, scoped);
  return link.robot ? link : LinkRef();
}

struct State
{
  urdf::Pose pose;
  Twist twist;
};

State linkState(const LinkRef& ref)
{
  if (ref.static_link)
    return {ref.static_link->pose, Twist()};
  return {ref.robot->linkPose(ref.link), ref.robot->linkTwist(ref.link)};
}
State modelState(Robot& robot) { return {robot.basePose(), robot.baseTwist()}; }

// A model's state by name, a robot's or a static model's (at rest); false for no such model.
bool modelStateOf(World& world, const std::string& name, State& state)
{
  if (Robot* robot = world.robot(name))
    state = modelState(*robot);
  else if (const StaticModelDescription* fixed = world.staticModel(name))
    state = {fixed->pose, Twist()};
  else
    return false;
  return true;
}

urdf::Vector3 vec(const std::array<double, 3>& a) { return urdf::Vector3(a[0], a[1], a[2]); }
std::array<double, 3> arr(const urdf::Vector3& v) { return {{v.x, v.y, v.z}}; }

// `state` (world) as seen from `frame`: position and velocities in the frame's axes, relative to it.
State relativeTo(const State& state, const State& frame)
{
  const urdf::Rotation to_frame = frame.pose.rotation.GetInverse();
  State out;
  out.pose.position = to_frame * sub(state.pose.position, frame.pose.position);
  out.pose.rotation = to_frame * state.pose.rotation;
  out.twist.linear = arr(to_frame * sub(vec(state.twist.linear), vec(frame.twist.linear)));
  out.twist.angular = arr(to_frame * sub(vec(state.twist.angular), vec(frame.twist.angular)));
  return out;
}

// A target given in `frame`'s axes and origin, in the world.
State inWorld(const State& target, const urdf::Pose& frame)
{
  State out;
  urdf::Vector3 origin = frame.position;  // urdf::Vector3's operator+ is not const
  out.pose.position = origin + frame.rotation * target.pose.position;
  out.pose.rotation = frame.rotation * target.pose.rotation;
  out.twist.linear = arr(frame.rotation * vec(target.twist.linear));
  out.twist.angular = arr(frame.rotation * vec(target.twist.angular));
  return out;
}

bool finite(const State& s)
{
  for (double v : {s.pose.position.x, s.pose.position.y, s.pose.position.z, s.pose.rotation.x, s.pose.rotation.y,
                   s.pose.rotation.z, s.pose.rotation.w, s.twist.linear[0], s.twist.linear[1], s.twist.linear[2],
                   s.twist.angular[0], s.twist.angular[1], s.twist.angular[2]})
    if (!std::isfinite(v))
      return false;
  return true;
}

// gazebo_ros's jobs start no earlier than now.
int64_t jobStart(const ros::Time& start, int64_t now_ns) { return std::max<int64_t>(int64_t(start.toNSec()), now_ns); }

// The name of the XML's root element; "" when it is not well-formed.
std::string rootElement(const std::string& xml)
{
  tinyxml2::XMLDocument doc;
  if (doc.Parse(xml.c_str()) != tinyxml2::XML_SUCCESS || !doc.RootElement())
    return "";
  return doc.RootElement()->Name();
}
}  // namespace

GazeboRosApiPlugin::GazeboRosApiPlugin(RosPlant& plant, ros::NodeHandle& private_nh)
  : plant_(plant), world_(plant.world()), nh_(private_nh)
{
  // gazebo_ros's Load(): the parameter, then advertiseServices() only with the ROS network on.
  nh_.param("enable_ros_network", enable_ros_network_, true);
  if (enable_ros_network_)
  {
    // gazebo_ros's physics reconfigure: its first callback, from setCallback here, reads the physics
    // (the simulation thread has not started yet). It comes before the services: the Server's
    // constructor publishes PhysicsConfig's defaults (max_update_rate 60, 20 solver passes) until that
    // first callback replaces them, and a client that waits for /gazebo/get_physics_properties before
    // reading the configuration must find the physics' own.
    physics_reconfigure_.reset(new dynamic_reconfigure::Server<tianracer_description::PhysicsConfig>(nh_));
    physics_reconfigure_->setCallback(
        [this](tianracer_description::PhysicsConfig& config, uint32_t level) { physicsReconfigure(config, level); });
    advertiseServices();
    model_states_pub_ = CountedPublisher::advertise<gazebo_msgs::ModelStates>(nh_, "model_states", 1);
    link_states_pub_ = CountedPublisher::advertise<gazebo_msgs::LinkStates>(nh_, "link_states", 1);
  }
  else
    ROS_INFO("ROS gazebo topics/services are disabled (~enable_ros_network false)");
  const int64_t scene_period_ns = periodNsOfRate(nh_.param("scene_rate", kDefaultSceneRate));
  scene_link_states_gate_.setPeriodNs(scene_period_ns);
  scene_contacts_gate_.setPeriodNs(scene_period_ns);
  watchForViewers();
  // The scene again after each model that comes or goes (spawn, delete, a Gazebo plugin's insertion):
  // the only ways models come and go.
  plant_.connectModelsChanged([this] {
    publishScene();
    publishScenePoses();
  });
  plant_.connectWorldUpdateEnd([this] {
    publishModelStates();
    publishLinkStates();
    publishSceneContacts();
  });
}

// ------------------------------------------------------------------------------ the viewers' topics

namespace
{
constexpr double kViewerWatchPeriod = 1.0;  // s of wall time

// Whether the master's system state lists `node`s on `topic` in one of its lists (publishers,
// subscribers): [[topic, [node, ...]], ...].
bool listed(XmlRpc::XmlRpcValue& list, const std::string& topic)
{
  if (list.getType() != XmlRpc::XmlRpcValue::TypeArray)
    return false;
  for (int i = 0; i < list.size(); ++i)
  {
    XmlRpc::XmlRpcValue& entry = list[i];
    if (entry.getType() == XmlRpc::XmlRpcValue::TypeArray && entry.size() == 2 &&
        entry[0].getType() == XmlRpc::XmlRpcValue::TypeString && static_cast<std::string>(entry[0]) == topic &&
        entry[1].getType() == XmlRpc::XmlRpcValue::TypeArray && entry[1].size() > 0)
      return true;
  }
  return false;
}
}  // namespace

bool GazeboRosApiPlugin::aViewerAsks() const
{
  XmlRpc::XmlRpcValue args, result, payload;
  args[0] = ros::this_node::getName();
  if (!ros::master::execute("getSystemState", args, result, payload, false) ||
      payload.getType() != XmlRpc::XmlRpcValue::TypeArray || payload.size() < 2)
    return false;
  for (const char* topic : {"scene", "scene_link_states", "scene_contacts"})
    if (listed(payload[1], nh_.resolveName(topic)))
      return true;
  return listed(payload[0], nh_.resolveName("step_physics"));
}

void GazeboRosApiPlugin::watchForViewers()
{
  viewer_watch_ = nh_.createWallTimer(ros::WallDuration(kViewerWatchPeriod), [this](const ros::WallTimerEvent&) {
    if (viewers_asked_ || !aViewerAsks())
      return;
    viewers_asked_ = true;
    viewer_watch_.stop();
    plant_.post([this] { advertiseViewerTopics(); });
  });
}

void GazeboRosApiPlugin::advertiseViewerTopics()
{
  scene_pub_ = nh_.advertise<std_msgs::String>("scene", 1, true);
  // What viewers pose the scene by (gzclient gets poses throttled too): link_states at ~scene_rate.
  scene_link_states_pub_ = CountedPublisher::advertise<gazebo_msgs::LinkStates>(nh_, "scene_link_states", 1);
  // And every contact (gzclient's contact view) on ~scene_contacts at the same rate.
  scene_contacts_pub_ = CountedPublisher::advertise<gazebo_msgs::ContactsState>(nh_, "scene_contacts", 1);
  // gzclient's step button, which Gazebo serves over its own transport (WorldControl's multi_step):
  // that many physics iterations, while paused.
  subscribers_.push_back(nh_.subscribe<std_msgs::UInt32>("step_physics", 10, [this](const std_msgs::UInt32::ConstPtr& msg) {
    const uint32_t iterations = msg->data;
    plant_.post([this, iterations] { plant_.requestSteps(iterations); });
  }));
  ROS_INFO("a viewer asked: %s, %s, %s and %s are up", scene_pub_.getTopic().c_str(),
           scene_link_states_pub_.publisher().getTopic().c_str(), scene_contacts_pub_.publisher().getTopic().c_str(),
           subscribers_.back().getTopic().c_str());
  publishScene();  // the world's; again after each model that comes or goes (connectModelsChanged)
}

template <class Srv>
void GazeboRosApiPlugin::advertiseOnSimThread(const std::string& name,
                                              bool (GazeboRosApiPlugin::*handler)(typename Srv::Request&,
                                                                                  typename Srv::Response&))
{
  services_.push_back(nh_.advertiseService<typename Srv::Request, typename Srv::Response>(
      name, [this, handler](typename Srv::Request& req, typename Srv::Response& res) {
        return plant_.onSimThread<bool>([&] { return (this->*handler)(req, res); });
      }));
}

void GazeboRosApiPlugin::advertiseServices()
{
  services_.push_back(nh_.advertiseService("spawn_urdf_model", &GazeboRosApiPlugin::spawnURDFModel, this));
  services_.push_back(nh_.advertiseService("spawn_sdf_model", &GazeboRosApiPlugin::spawnSDFModel, this));
  services_.push_back(nh_.advertiseService("delete_model", &GazeboRosApiPlugin::deleteModel, this));
  advertiseOnSimThread<std_srvs::Empty>("pause_physics", &GazeboRosApiPlugin::pausePhysics);
  advertiseOnSimThread<std_srvs::Empty>("unpause_physics", &GazeboRosApiPlugin::unpausePhysics);
  advertiseOnSimThread<std_srvs::Empty>("reset_simulation", &GazeboRosApiPlugin::resetSimulation);
  advertiseOnSimThread<std_srvs::Empty>("reset_world", &GazeboRosApiPlugin::resetWorld);
  advertiseOnSimThread<gazebo_msgs::GetModelState>("get_model_state", &GazeboRosApiPlugin::getModelState);
  advertiseOnSimThread<gazebo_msgs::GetLinkState>("get_link_state", &GazeboRosApiPlugin::getLinkState);
  advertiseOnSimThread<gazebo_msgs::SetModelState>("set_model_state", &GazeboRosApiPlugin::setModelState);
  advertiseOnSimThread<gazebo_msgs::SetLinkState>("set_link_state", &GazeboRosApiPlugin::setLinkState);
  advertiseOnSimThread<gazebo_msgs::SetModelConfiguration>("set_model_configuration",
                                                           &GazeboRosApiPlugin::setModelConfiguration);
  advertiseOnSimThread<gazebo_msgs::GetWorldProperties>("get_world_properties", &GazeboRosApiPlugin::getWorldProperties);
  advertiseOnSimThread<gazebo_msgs::GetModelProperties>("get_model_properties", &GazeboRosApiPlugin::getModelProperties);
  advertiseOnSimThread<gazebo_msgs::GetJointProperties>("get_joint_properties", &GazeboRosApiPlugin::getJointProperties);
  advertiseOnSimThread<gazebo_msgs::GetPhysicsProperties>("get_physics_properties",
                                                          &GazeboRosApiPlugin::getPhysicsProperties);
  advertiseOnSimThread<gazebo_msgs::SetPhysicsProperties>("set_physics_properties",
                                                          &GazeboRosApiPlugin::setPhysicsProperties);
  advertiseOnSimThread<gazebo_msgs::ApplyBodyWrench>("apply_body_wrench", &GazeboRosApiPlugin::applyBodyWrench);
  advertiseOnSimThread<gazebo_msgs::BodyRequest>("clear_body_wrenches", &GazeboRosApiPlugin::clearBodyWrenches);
  advertiseOnSimThread<gazebo_msgs::ApplyJointEffort>("apply_joint_effort", &GazeboRosApiPlugin::applyJointEffort);
  advertiseOnSimThread<gazebo_msgs::JointRequest>("clear_joint_forces", &GazeboRosApiPlugin::clearJointForces);
  advertiseOnSimThread<gazebo_msgs::SetJointProperties>("set_joint_properties", &GazeboRosApiPlugin::setJointProperties);
  advertiseOnSimThread<gazebo_msgs::GetLinkProperties>("get_link_properties", &GazeboRosApiPlugin::getLinkProperties);
  advertiseOnSimThread<gazebo_msgs::SetLinkProperties>("set_link_properties", &GazeboRosApiPlugin::setLinkProperties);
  advertiseOnSimThread<gazebo_msgs::GetLightProperties>("get_light_properties", &GazeboRosApiPlugin::getLightProperties);
  advertiseOnSimThread<gazebo_msgs::SetLightProperties>("set_light_properties", &GazeboRosApiPlugin::setLightProperties);
  advertiseOnSimThread<gazebo_msgs::DeleteLight>("delete_light", &GazeboRosApiPlugin::deleteLight);

  // gazebo_ros's topics for the same two requests: queued, nobody waits for them.
  subscribers_.push_back(nh_.subscribe<gazebo_msgs::ModelState>(
      "set_model_state", 10, [this](const gazebo_msgs::ModelState::ConstPtr& msg) {
        plant_.post([this, msg] {
          std::string message;
          updateModelState(*msg, message);
        });
      }));
  subscribers_.push_back(nh_.subscribe<gazebo_msgs::LinkState>(
      "set_link_state", 10, [this](const gazebo_msgs::LinkState::ConstPtr& msg) {
        plant_.post([this, msg] {
          std::string message;
          updateLinkState(*msg, message);
        });
      }));
}

// ------------------------------------------------------------------------------ spawn and delete

bool GazeboRosApiPlugin::spawnURDFModel(gazebo_msgs::SpawnModel::Request& req, gazebo_msgs::SpawnModel::Response& res)
{
  // What is not URDF is refused (gazebo_ros fails the call itself then); XML that is not
  // well-formed goes on to the plant, whose error names the parser's complaint.
  const std::string root = rootElement(req.model_xml);
  if (!root.empty() && root != "robot")
  {
    ROS_ERROR("SpawnModel: Failure - entity format is invalid.");
    res.success = false;
    res.status_message = "SpawnModel: Failure - entity format is invalid.";
    return false;
  }
  return spawnModel(req, res);
}

bool GazeboRosApiPlugin::spawnSDFModel(gazebo_msgs::SpawnModel::Request& req, gazebo_msgs::SpawnModel::Response& res)
{
  // SDF (<sdf>, or the old <gazebo>) and URDF, told by the root element as gazebo_ros tells them;
  // XML that is not well-formed goes on to the plant, whose error names the parser's complaint.
  const std::string root = rootElement(req.model_xml);
  if (root.empty() || root == "robot" || root == "sdf" || root == "gazebo")
    return spawnModel(req, res);
  res.success = false;
  res.status_message = "GazeboRosApiPlugin SpawnModel Failure: input model_xml not SDF or URDF, or cannot be "
                       "converted to Gazebo compatible format.";
  ROS_ERROR_STREAM(res.status_message << " (model '" << req.model_name << "': the root element is <" << root
                                      << ">; send <sdf version=\"1.6\"><model ...></sdf> or a URDF <robot>)");
  return true;
}

bool GazeboRosApiPlugin::spawnModel(gazebo_msgs::SpawnModel::Request& req, gazebo_msgs::SpawnModel::Response& res)
{
  // What the request names in the world, looked at in one visit to the simulation thread.
  enum class Check { Ok, NoReferenceFrame, Exists };
  urdf::Pose pose = fromMsg(req.initial_pose);
  const Check check = plant_.onSimThread<Check>([&] {
    if (!isWorldFrame(req.reference_frame))
    {
      const LinkRef frame = findLink(world_, req.reference_frame);
      if (!frame)
        return Check::NoReferenceFrame;
      pose = inWorld(State{pose, Twist()}, linkState(frame).pose).pose;
    }
    return world_.robot(req.model_name) ? Check::Exists : Check::Ok;
  });
  if (check != Check::Ok)
  {
    res.success = false;
    res.status_message = check == Check::Exists ? "SpawnModel: Failure - entity already exists."
                                                : "SpawnModel: reference reference_frame not found, did you forget "
                                                  "to scope the link by model name?";
    return true;
  }
  std::string message;
  res.success = plant_.spawn(req.model_name, req.model_xml, req.robot_namespace, pose, {}, message);
  res.status_message = res.success ? "SpawnModel: Successfully spawned entity" : "SpawnModel: Failure - " + message;
  return true;
}

bool GazeboRosApiPlugin::deleteModel(gazebo_msgs::DeleteModel::Request& req, gazebo_msgs::DeleteModel::Response& res)
{
  std::string message;
  res.success = plant_.remove(req.model_name, message);
  res.status_message = res.success ? "DeleteModel: successfully deleted model" : "DeleteModel: model does not exist";
  if (!res.success)
    ROS_ERROR("DeleteModel: model [%s] does not exist", req.model_name.c_str());
  return true;
}

// ------------------------------------------------------------------------------ simulation

bool GazeboRosApiPlugin::pausePhysics(std_srvs::Empty::Request&, std_srvs::Empty::Response&)
{
  plant_.applyPaused(true);
  return true;
}

bool GazeboRosApiPlugin::unpausePhysics(std_srvs::Empty::Request&, std_srvs::Empty::Response&)
{
  plant_.applyPaused(false);
  return true;
}

bool GazeboRosApiPlugin::resetSimulation(std_srvs::Empty::Request&, std_srvs::Empty::Response&)
{
  plant_.resetSimulation();
  publishScenePoses();
  return true;
}

bool GazeboRosApiPlugin::resetWorld(std_srvs::Empty::Request&, std_srvs::Empty::Response&)
{
  world_.resetWorld();
  publishScenePoses();
  return true;
}

// ------------------------------------------------------------------------------ states

bool GazeboRosApiPlugin::getModelState(gazebo_msgs::GetModelState::Request& req,
                                       gazebo_msgs::GetModelState::Response& res)
{
  State state;
  if (!modelStateOf(world_, req.model_name, state))
  {
    ROS_ERROR("GetModelState: model [%s] does not exist", req.model_name.c_str());
    res.success = false;
    res.status_message = "GetModelState: model does not exist";
    return true;
  }
  if (!isWorldFrame(req.relative_entity_name))
  {
    const LinkRef frame = findLink(world_, req.relative_entity_name);
    if (!frame)
    {
      res.success = false;
      res.status_message = "GetModelState: reference relative_entity_name not found, did you forget to scope "
                           "the body by model name?";
      return true;
    }
    state = relativeTo(state, linkState(frame));
  }
  res.header.seq = ++get_model_state_calls_[req.model_name];
  res.header.stamp = rosTime(world_.timeNs());
  res.header.frame_id = req.relative_entity_name;
  res.pose = toMsg(state.pose);
  res.twist = toMsg(state.twist);
  res.success = true;
  res.status_message = "GetModelState: got properties";
  return true;
}

bool GazeboRosApiPlugin::getLinkState(gazebo_msgs::GetLinkState::Request& req, gazebo_msgs::GetLinkState::Response& res)
{
  const LinkRef link = findLink(world_, req.link_name);
  if (!link)
  {
    res.success = false;
    res.status_message = "GetLinkState: link not found, did you forget to scope the link by model name?";
    return true;
  }
  State state = linkState(link);
  if (!isWorldFrame(req.reference_frame))
  {
    const LinkRef frame = findLink(world_, req.reference_frame);
    if (!frame)
    {
      res.success = false;
      res.status_message = "GetLinkState: reference reference_frame not found, did you forget to scope the "
                           "link by model name?";
      return true;
    }
    state = relativeTo(state, linkState(frame));
  }
  res.link_state.link_name = req.link_name;
  res.link_state.pose = toMsg(state.pose);
  res.link_state.twist = toMsg(state.twist);
  res.link_state.reference_frame = req.reference_frame;
  res.success = true;
  res.status_message = "GetLinkState: got state";
  return true;
}

bool GazeboRosApiPlugin::setModelState(gazebo_msgs::SetModelState::Request& req,
                                       gazebo_msgs::SetModelState::Response& res)
{
  res.success = updateModelState(req.model_state, res.status_message);
  return true;
}

bool GazeboRosApiPlugin::setLinkState(gazebo_msgs::SetLinkState::Request& req, gazebo_msgs::SetLinkState::Response& res)
{
  res.success = updateLinkState(req.link_state, res.status_message);
  return true;
}

bool GazeboRosApiPlugin::updateModelState(const gazebo_msgs::ModelState& request, std::string& message)
{
  Robot* robot = world_.robot(request.model_name);
  if (!robot && !world_.staticModel(request.model_name))
  {
    ROS_ERROR("Updating ModelState: model [%s] does not exist", request.model_name.c_str());
    message = "SetModelState: model does not exist";
    return false;
  }
  State target{fromMsg(request.pose), fromMsg(request.twist)};
  if (!isWorldFrame(request.reference_frame))
  {
    const LinkRef frame = findLink(world_, request.reference_frame);
    if (!frame)
    {
      ROS_ERROR("Updating ModelState: for model[%s], specified reference frame entity [%s] does not exist",
                request.model_name.c_str(), request.reference_frame.c_str());
      message = "SetModelState: specified reference frame entity does not exist";
      return false;
    }
    target = inWorld(target, linkState(frame).pose);
  }
  if (!finite(target))
  {
    message = "SetModelState: the state of '" + request.model_name + "' is not finite";
    return false;
  }
  if (robot)
    robot->setModelState(target.pose, target.twist);
  else
  {
    world_.moveStaticModel(request.model_name, target.pose);  // a teleport, as Gazebo moves a static model
    publishScene();
  }
  publishScenePoses();
  message = "SetModelState: set model state done";
  return true;
}

bool GazeboRosApiPlugin::updateLinkState(const gazebo_msgs::LinkState& request, std::string& message)
{
  const LinkRef link = findRobotLink(world_, request.link_name);
  if (!link)
  {
    ROS_ERROR("Updating LinkState: link [%s] does not exist", request.link_name.c_str());
    message = "SetLinkState: link does not exist";
    return false;
  }
  State target{fromMsg(request.pose), fromMsg(request.twist)};
  if (!isWorldFrame(request.reference_frame))
  {
    const LinkRef frame = findLink(world_, request.reference_frame);
    if (!frame)
    {
      ROS_ERROR("Updating LinkState: reference_frame is not a valid link name");
      message = "SetLinkState: failed";
      return false;
    }
    target = inWorld(target, linkState(frame).pose);
  }
  if (!finite(target))
  {
    message = "SetLinkState: the state of '" + request.link_name + "' is not finite";
    return false;
  }
  link.robot->setLinkState(link.link, target.pose, target.twist);
  publishScenePoses();
  message = "SetLinkState: success";
  return true;
}

bool GazeboRosApiPlugin::setModelConfiguration(gazebo_msgs::SetModelConfiguration::Request& req,
                                               gazebo_msgs::SetModelConfiguration::Response& res)
{
  Robot* robot = world_.robot(req.model_name);
  res.success = false;
  if (!robot)
  {
    ROS_ERROR("SetModelConfiguration: model [%s] does not exist", req.model_name.c_str());
    res.status_message = "SetModelConfiguration: model does not exist";
    return true;
  }
  if (req.joint_names.size() != req.joint_positions.size())
  {
    res.status_message = "SetModelConfiguration: joint name and position list have different lengths";
    return true;
  }
  std::map<std::string, double> positions;
  for (size_t i = 0; i < req.joint_names.size(); ++i)
    positions[req.joint_names[i]] = req.joint_positions[i];
  try
  {
    robot->setJointPositions(positions);
  }
  catch (const std::exception& e)
  {
    res.status_message = std::string("SetModelConfiguration: ") + e.what();
    return true;
  }
  publishScenePoses();
  res.success = true;
  res.status_message = "SetModelConfiguration: success";
  return true;
}

// ------------------------------------------------------------------------------ properties

bool GazeboRosApiPlugin::getWorldProperties(gazebo_msgs::GetWorldProperties::Request&,
                                            gazebo_msgs::GetWorldProperties::Response& res)
{
  res.sim_time = world_.time();
  for (const StaticModelDescription& fixed : world_.staticModels())
    res.model_names.push_back(fixed.name);
  for (Robot* robot : world_.robots())
    res.model_names.push_back(robot->name());
  res.rendering_enabled = true;
  res.success = true;
  res.status_message = "GetWorldProperties: got properties";
  return true;
}

bool GazeboRosApiPlugin::getModelProperties(gazebo_msgs::GetModelProperties::Request& req,
                                            gazebo_msgs::GetModelProperties::Response& res)
{
  Robot* robot = world_.robot(req.model_name);
  if (!robot)
    if (const StaticModelDescription* fixed = world_.staticModel(req.model_name))
    {
      // A static model: its links, and its collisions by their SDF names, as Gazebo lists them.
      for (const StaticModelDescription::Link& link : fixed->links)
        res.body_names.push_back(link.name);
      for (const StaticCollision& collision : world_.description().collisions)
        if (collision.model == fixed->name)
          res.geom_names.push_back(collision.name.substr(collision.name.rfind("::") + 2));
      res.is_static = true;
      res.success = true;
      res.status_message = "GetModelProperties: got properties";
      return true;
    }
  if (!robot)
  {
    ROS_ERROR("GetModelProperties: model [%s] does not exist", req.model_name.c_str());
    res.success = false;
    res.status_message = "GetModelProperties: model does not exist";
    return true;
  }
  res.body_names = robot->linkNames();
  // Each link's collisions in link order, as Gazebo lists them: their SDF names, or for a URDF the
  // names the plant's contacts give them (the collision's or link's name and "_collision", a second
  // one numbered, as sdformat's URDF reader).
  const urdf::ModelInterface& model = *robot->description().model;
  for (const std::string& link_name : res.body_names)
    if (urdf::LinkConstSharedPtr link = model.getLink(link_name))
      for (size_t i = 0; i < link->collision_array.size(); ++i)
      {
        const urdf::CollisionSharedPtr& collision = link->collision_array[i];
        if (robot->description().format == RobotDescription::Format::Sdf)
          res.geom_names.push_back(collision->name);
        else
          res.geom_names.push_back((collision->name.empty() ? link_name : collision->name) + "_collision" +
                                   (i > 0 ? "_" + std::to_string(i) : ""));
      }
  res.joint_names = robot->jointNames();
  for (const std::string& ball : robot->ballJointNames())  // Gazebo lists them too (get_joint_properties: NaN, 0)
    res.joint_names.push_back(ball);
  res.is_static = robot->description().is_static;
  res.success = true;
  res.status_message = "GetModelProperties: got properties";
  return true;
}

// Upstream's: the first model with a joint of that (unscoped) name; its type always REVOLUTE and
// no damping (both marked FIXME upstream), its position and rate.
Robot* GazeboRosApiPlugin::jointOwner(const std::string& requested, std::string& joint)
{
  // Upstream's: the first model with a joint of that name (Model::GetJoint: its name or its scoped
  // name, model::joint).
  for (Robot* robot : world_.robots())
    for (const std::string& name : robot->jointNames())
      if (name == requested || robot->name() + "::" + name == requested)
      {
        joint = name;
        return robot;
      }
  return nullptr;
}

bool GazeboRosApiPlugin::getJointProperties(gazebo_msgs::GetJointProperties::Request& req,
                                            gazebo_msgs::GetJointProperties::Response& res)
{
  // The first model with a joint of that name or scoped name (ball joints too, whose position is NaN).
  for (Robot* robot : world_.robots())
  {
    const std::string scope = robot->name() + "::";
    const std::string joint =
        req.joint_name.compare(0, scope.size(), scope) == 0 ? req.joint_name.substr(scope.size()) : req.joint_name;
    double position = 0, velocity = 0, effort = 0;
    if (!robot->jointState(joint, position, velocity, effort))
      continue;
    res.type = gazebo_msgs::GetJointProperties::Response::REVOLUTE;
    res.position.assign(1, position);
    res.rate.assign(1, velocity);
    res.success = true;
    res.status_message = "GetJointProperties: got properties";
    return true;
  }
  res.success = false;
  res.status_message = "GetJointProperties: joint not found";
  return true;
}

bool GazeboRosApiPlugin::getPhysicsProperties(gazebo_msgs::GetPhysicsProperties::Request&,
                                              gazebo_msgs::GetPhysicsProperties::Response& res)
{
  res.time_step = world_.timeStep();
  res.pause = world_.paused();
  // Gazebo's real_time_update_rate: steps per wall second; 0 runs as fast as possible.
  res.max_update_rate = plant_.realTimeFactor() > 0 ? plant_.realTimeFactor() / world_.timeStep() : 0.0;
  res.gravity = toMsg(world_.gravity());
  res.ode_config.sor_pgs_iters = world_.solverIterations();
  res.ode_config.sor_pgs_w = world_.solverRelaxation();
  res.ode_config.contact_surface_layer = world_.contactSurfaceLayer();
  res.ode_config.contact_max_correcting_vel = world_.contactMaxCorrectingVel();
  res.success = true;
  res.status_message = "GetPhysicsProperties: got properties";
  return true;
}

void GazeboRosApiPlugin::sayNotHonoured(const std::string& name, const std::string& why)
{
  if (said_not_honoured_.insert(name).second)
    ROS_WARN("%s is not honoured: %s (said once)", name.c_str(), why.c_str());
}

bool GazeboRosApiPlugin::applyPhysics(const gazebo_msgs::SetPhysicsProperties::Request& req, std::string& message)
{
  // Every value checked before anything changes.
  if (!std::isfinite(req.max_update_rate))
  {
    message = "max_update_rate must be a number (0: as fast as possible)";
    return false;
  }
  if (!(req.time_step >= kMinStepSize && req.time_step <= kMaxStepSize))
  {
    std::ostringstream text;
    text << "time step " << req.time_step << " s is outside [" << kMinStepSize << ", " << kMaxStepSize << "] s";
    message = text.str();
    return false;
  }
  if (!std::isfinite(req.gravity.x) || !std::isfinite(req.gravity.y) || !std::isfinite(req.gravity.z))
  {
    message = "gravity must be finite";
    return false;
  }
  const gazebo_msgs::ODEPhysics& ode = req.ode_config;
  if (ode.sor_pgs_iters > uint32_t(kMaxSolverIterations))
  {
    message = "sor_pgs_iters " + std::to_string(ode.sor_pgs_iters) + " is not a number of solver passes from 1 to " +
              std::to_string(kMaxSolverIterations);
    return false;
  }
  try
  {
    // The ODE settings the plant's solver has (it checks them all before it changes one).
    world_.setSolverSettings(int(ode.sor_pgs_iters), ode.sor_pgs_w, ode.contact_surface_layer,
                             ode.contact_max_correcting_vel);
    world_.setTimeStep(req.time_step);
    world_.setGravity(urdf::Vector3(req.gravity.x, req.gravity.y, req.gravity.z));
  }
  catch (const std::exception& e)
  {
    message = e.what();
    return false;
  }
  plant_.setRealTimeFactor(req.max_update_rate > 0 ? req.max_update_rate * world_.timeStep() : 0.0);
  // ODE's own, which the plant's solver has no counterpart of: what get_physics_properties reports
  // for them is all they can be.
  if (ode.auto_disable_bodies)
    sayNotHonoured("ode_config.auto_disable_bodies", "resting bodies sleep by the plant's own rule "
                                                     "(docs/gazebo_compatibility.md)");
  const std::pair<const char*, double> ode_only[] = {{"ode_config.sor_pgs_precon_iters", ode.sor_pgs_precon_iters},
                                                     {"ode_config.sor_pgs_rms_error_tol", ode.sor_pgs_rms_error_tol},
                                                     {"ode_config.cfm", ode.cfm},
                                                     {"ode_config.erp", ode.erp},
                                                     {"ode_config.max_contacts", ode.max_contacts}};
  for (const auto& setting : ode_only)
    if (setting.second != 0)
      sayNotHonoured(setting.first, "ODE's, which the plant's solver has no counterpart of");
  return true;
}

bool GazeboRosApiPlugin::setPhysicsProperties(gazebo_msgs::SetPhysicsProperties::Request& req,
                                              gazebo_msgs::SetPhysicsProperties::Response& res)
{
  std::string message;
  res.success = applyPhysics(req, message);
  res.status_message = res.success ? "physics engine updated" : "SetPhysicsProperties: " + message + "; nothing was changed";
  return true;
}

void GazeboRosApiPlugin::physicsReconfigure(tianracer_description::PhysicsConfig& config, uint32_t)
{
  auto fromPhysics = [this](tianracer_description::PhysicsConfig& config) {
    gazebo_msgs::GetPhysicsProperties::Request req;
    gazebo_msgs::GetPhysicsProperties::Response now;
    getPhysicsProperties(req, now);
    config.time_step = now.time_step;
    config.max_update_rate = now.max_update_rate;
    config.gravity_x = now.gravity.x;
    config.gravity_y = now.gravity.y;
    config.gravity_z = now.gravity.z;
    config.auto_disable_bodies = now.ode_config.auto_disable_bodies;
    config.sor_pgs_precon_iters = int(now.ode_config.sor_pgs_precon_iters);
    config.sor_pgs_iters = int(now.ode_config.sor_pgs_iters);
    config.sor_pgs_w = now.ode_config.sor_pgs_w;
    config.sor_pgs_rms_error_tol = now.ode_config.sor_pgs_rms_error_tol;
    config.cfm = now.ode_config.cfm;
    config.erp = now.ode_config.erp;
    config.contact_surface_layer = now.ode_config.contact_surface_layer;
    config.contact_max_correcting_vel = now.ode_config.contact_max_correcting_vel;
    config.max_contacts = int(now.ode_config.max_contacts);
  };
  if (!physics_reconfigure_initialized_)
  {
    fromPhysics(config);  // the constructor's call: the simulation thread is not running yet
    physics_reconfigure_initialized_ = true;
    return;
  }
  plant_.onSimThread<bool>([&] {
    tianracer_description::PhysicsConfig now = config;
    fromPhysics(now);
    // gazebo_ros's rule: anything that differs from the physics sends the whole config.
    const bool changed =
        config.time_step != now.time_step || config.max_update_rate != now.max_update_rate ||
        config.gravity_x != now.gravity_x || config.gravity_y != now.gravity_y || config.gravity_z != now.gravity_z ||
        config.auto_disable_bodies != now.auto_disable_bodies || config.sor_pgs_precon_iters != now.sor_pgs_precon_iters ||
        config.sor_pgs_iters != now.sor_pgs_iters || config.sor_pgs_w != now.sor_pgs_w ||
        config.sor_pgs_rms_error_tol != now.sor_pgs_rms_error_tol || config.cfm != now.cfm || config.erp != now.erp ||
        config.contact_surface_layer != now.contact_surface_layer ||
        config.contact_max_correcting_vel != now.contact_max_correcting_vel || config.max_contacts != now.max_contacts;
    if (!changed)
      return true;
    gazebo_msgs::SetPhysicsProperties::Request req;
    req.time_step = config.time_step;
    req.max_update_rate = config.max_update_rate;
    req.gravity.x = config.gravity_x;
    req.gravity.y = config.gravity_y;
    req.gravity.z = config.gravity_z;
    req.ode_config.auto_disable_bodies = config.auto_disable_bodies;
    req.ode_config.sor_pgs_precon_iters = uint32_t(std::max(0, config.sor_pgs_precon_iters));
    req.ode_config.sor_pgs_iters = uint32_t(std::max(0, config.sor_pgs_iters));
    req.ode_config.sor_pgs_w = config.sor_pgs_w;
    req.ode_config.sor_pgs_rms_error_tol = config.sor_pgs_rms_error_tol;
    req.ode_config.cfm = config.cfm;
    req.ode_config.erp = config.erp;
    req.ode_config.contact_surface_layer = config.contact_surface_layer;
    req.ode_config.contact_max_correcting_vel = config.contact_max_correcting_vel;
    req.ode_config.max_contacts = uint32_t(std::max(0, config.max_contacts));
    std::string message;
    if (applyPhysics(req, message))
      ROS_INFO("physics dynamics reconfigure update complete");
    else
    {
      // parameter_updates then says what the physics still is.
      ROS_ERROR("physics dynamics reconfigure refused: %s; nothing was changed", message.c_str());
      config = now;
    }
    return true;
  });
}

// ------------------------------------------------------------------------------ joint and link properties

bool GazeboRosApiPlugin::setJointProperties(gazebo_msgs::SetJointProperties::Request& req,
                                            gazebo_msgs::SetJointProperties::Response& res)
{
  std::string joint;
  Robot* owner = jointOwner(req.joint_name, joint);
  if (!owner)
  {
    res.success = false;
    res.status_message = "SetJointProperties: joint not found";
    return true;
  }
  const gazebo_msgs::ODEJointProperties& ode = req.ode_joint_config;
  // The plant's joints have one axis (ball joints none it sets): index 0 of each list.
  auto first = [](const std::vector<double>& values) {
    return values.empty() ? std::numeric_limits<double>::quiet_NaN() : values[0];
  };
  JointProperties properties;
  properties.damping = first(ode.damping);
  properties.upper = first(ode.hiStop);
  properties.lower = first(ode.loStop);
  properties.fmax = first(ode.fmax);
  properties.vel = first(ode.vel);
  try
  {
    owner->setJointProperties(joint, properties);
  }
  catch (const std::exception& e)
  {
    res.success = false;
    res.status_message = std::string("SetJointProperties: ") + e.what();
    return true;
  }
  const std::pair<const char*, const std::vector<double>*> ode_only[] = {
      {"ode_joint_config.erp", &ode.erp}, {"ode_joint_config.cfm", &ode.cfm},
      {"ode_joint_config.stop_erp", &ode.stop_erp}, {"ode_joint_config.stop_cfm", &ode.stop_cfm},
      {"ode_joint_config.fudge_factor", &ode.fudge_factor}};
  for (const auto& setting : ode_only)
    if (!setting.second->empty())
      sayNotHonoured(setting.first, "ODE's constraint softness, which the plant's joint rows have no counterpart of");
  for (const std::vector<double>* values : {&ode.damping, &ode.hiStop, &ode.loStop, &ode.fmax, &ode.vel})
    if (values->size() > 1)
      sayNotHonoured("set_joint_properties beyond a joint's first axis", "the plant's joints have one axis");
  res.success = true;
  res.status_message = "SetJointProperties: properties set";
  return true;
}

bool GazeboRosApiPlugin::getLinkProperties(gazebo_msgs::GetLinkProperties::Request& req,
                                           gazebo_msgs::GetLinkProperties::Response& res)
{
  const LinkRef link = findRobotLink(world_, req.link_name);
  if (!link)
  {
    res.success = false;
    res.status_message = "GetLinkProperties: link not found, did you forget to scope the link by model name?";
    return true;
  }
  const LinkProperties p = link.robot->linkProperties(link.link);
  res.gravity_mode = p.gravity;
  res.mass = p.mass;
  res.ixx = p.ixx;
  res.iyy = p.iyy;
  res.izz = p.izz;
  res.ixy = p.ixy;
  res.ixz = p.ixz;
  res.iyz = p.iyz;
  res.com.position.x = p.com.x;
  res.com.position.y = p.com.y;
  res.com.position.z = p.com.z;
  res.com.orientation.w = 1;  // upstream's: no rotated inertia
  res.success = true;
  res.status_message = "GetLinkProperties: got properties";
  return true;
}

bool GazeboRosApiPlugin::setLinkProperties(gazebo_msgs::SetLinkProperties::Request& req,
                                           gazebo_msgs::SetLinkProperties::Response& res)
{
  const LinkRef link = findRobotLink(world_, req.link_name);
  if (!link)
  {
    res.success = false;
    res.status_message = "SetLinkProperties: link not found, did you forget to scope the link by model name?";
    return true;
  }
  LinkProperties p;
  p.mass = req.mass;
  p.com = urdf::Vector3(req.com.position.x, req.com.position.y, req.com.position.z);
  p.ixx = req.ixx;
  p.ixy = req.ixy;
  p.ixz = req.ixz;
  p.iyy = req.iyy;
  p.iyz = req.iyz;
  p.izz = req.izz;
  p.gravity = req.gravity_mode;
  try
  {
    const std::string left_out = link.robot->setLinkProperties(link.link, p);
    if (!left_out.empty())
      ROS_WARN("SetLinkProperties: %s: %s", req.link_name.c_str(), left_out.c_str());
  }
  catch (const std::exception& e)
  {
    res.success = false;
    res.status_message = std::string("SetLinkProperties: ") + e.what();
    return true;
  }
  res.success = true;
  res.status_message = "SetLinkProperties: properties set";
  return true;
}

// ------------------------------------------------------------------------------ lights

bool GazeboRosApiPlugin::getLightProperties(gazebo_msgs::GetLightProperties::Request& req,
                                            gazebo_msgs::GetLightProperties::Response& res)
{
  WorldLight light;
  if (!world_.light(req.light_name, light))
  {
    res.success = false;
    res.status_message = "getLightProperties: Requested light " + req.light_name + " not found!";
    return true;
  }
  res.diffuse.r = light.light.diffuse.r;
  res.diffuse.g = light.light.diffuse.g;
  res.diffuse.b = light.light.diffuse.b;
  res.diffuse.a = light.light.diffuse.a;
  res.attenuation_constant = light.light.constant;
  res.attenuation_linear = light.light.linear;
  res.attenuation_quadratic = light.light.quadratic;
  res.success = true;  // upstream says nothing more
  return true;
}

bool GazeboRosApiPlugin::setLightProperties(gazebo_msgs::SetLightProperties::Request& req,
                                            gazebo_msgs::SetLightProperties::Response& res)
{
  WorldLight light;
  if (!world_.light(req.light_name, light))
  {
    res.success = false;
    res.status_message = "setLightProperties: Requested light " + req.light_name + " not found!";
    return true;
  }
  // Upstream's: every field of the request replaces the light's (its message to the renderer).
  light.cast_shadows = req.cast_shadows;
  light.light.diffuse = {float(req.diffuse.r), float(req.diffuse.g), float(req.diffuse.b), float(req.diffuse.a)};
  light.light.specular = {float(req.specular.r), float(req.specular.g), float(req.specular.b), float(req.specular.a)};
  light.light.constant = req.attenuation_constant;
  light.light.linear = req.attenuation_linear;
  light.light.quadratic = req.attenuation_quadratic;
  const urdf::Vector3 direction(req.direction.x, req.direction.y, req.direction.z);
  if (light.directional)
    light.light.direction = direction;  // a directional light's pose is not used, as the plant reads a world's
  else
  {
    const urdf::Pose pose = fromMsg(req.pose);  // a zero quaternion is the identity
    light.light.position = pose.position;
    light.light.direction = rotate(pose.rotation, direction);
  }
  try
  {
    world_.setLight(light);
  }
  catch (const std::exception& e)
  {
    res.success = false;
    res.status_message = std::string("setLightProperties: ") + e.what();
    return true;
  }
  if (!light.directional && req.cast_shadows)
    sayNotHonoured("set_light_properties' cast_shadows for a point or spot light",
                   "only a directional light casts shadows, as in Gazebo");
  publishScene();
  res.success = true;
  return true;
}

bool GazeboRosApiPlugin::deleteLight(gazebo_msgs::DeleteLight::Request& req, gazebo_msgs::DeleteLight::Response& res)
{
  if (!world_.removeLight(req.light_name))
  {
    res.success = false;
    res.status_message = "DeleteLight: Requested light " + req.light_name + " not found!";
    return true;
  }
  publishScene();
  res.success = true;
  res.status_message = "DeleteLight: " + req.light_name + " successfully deleted";
  return true;
}

// ------------------------------------------------------------------------------ forces

bool GazeboRosApiPlugin::applyBodyWrench(gazebo_msgs::ApplyBodyWrench::Request& req,
                                         gazebo_msgs::ApplyBodyWrench::Response& res)
{
  res.success = false;
  const LinkRef body = findRobotLink(world_, req.body_name);
  if (!body)
  {
    ROS_ERROR("ApplyBodyWrench: body [%s] does not exist", req.body_name.c_str());
    res.status_message = "ApplyBodyWrench: body does not exist";
    return true;
  }
  // A force at reference_point adds reference_point x force to the torque.
  const auto& f = req.wrench.force;
  const auto& p = req.reference_point;
  urdf::Vector3 force(f.x, f.y, f.z);
  urdf::Vector3 torque(req.wrench.torque.x + p.y * f.z - p.z * f.y, req.wrench.torque.y + p.z * f.x - p.x * f.z,
                       req.wrench.torque.z + p.x * f.y - p.y * f.x);
  if (!isWorldFrame(req.reference_frame))
  {
    const LinkRef frame = findLink(world_, req.reference_frame);
    if (!frame)
    {
      ROS_ERROR("ApplyBodyWrench: reference_frame is not a valid link name");
      res.status_message = "ApplyBodyWrench: reference_frame not found";
      return true;
    }
    const urdf::Rotation axes = linkState(frame).pose.rotation;
    force = axes * force;
    torque = axes * torque;
  }
  for (double v : {force.x, force.y, force.z, torque.x, torque.y, torque.z})
    if (!std::isfinite(v))
    {
      res.status_message = "ApplyBodyWrench: the wrench on '" + req.body_name + "' is not finite";
      return true;
    }
  body.robot->applyLinkWrench(body.link, force, torque, jobStart(req.start_time, world_.timeNs()),
                              req.duration.toNSec());
  res.success = true;
  res.status_message = "";
  return true;
}

bool GazeboRosApiPlugin::clearBodyWrenches(gazebo_msgs::BodyRequest::Request& req, gazebo_msgs::BodyRequest::Response&)
{
  if (const LinkRef body = findRobotLink(world_, req.body_name))
    body.robot->clearLinkWrenches(body.link);
  return true;
}

bool GazeboRosApiPlugin::applyJointEffort(gazebo_msgs::ApplyJointEffort::Request& req,
                                          gazebo_msgs::ApplyJointEffort::Response& res)
{
  res.success = false;
  if (!std::isfinite(req.effort))
  {
    res.status_message = "ApplyJointEffort: the effort on '" + req.joint_name + "' is not finite";
    return true;
  }
  std::string joint;
  if (Robot* robot = jointOwner(req.joint_name, joint))
  {
    robot->applyJointEffort(joint, req.effort, jobStart(req.start_time, world_.timeNs()), req.duration.toNSec());
    res.success = true;
    res.status_message = "ApplyJointEffort: effort set";
    return true;
  }
  res.status_message = "ApplyJointEffort: joint not found";
  return true;
}

bool GazeboRosApiPlugin::clearJointForces(gazebo_msgs::JointRequest::Request& req, gazebo_msgs::JointRequest::Response&)
{
  // Upstream's: every job on a joint of that name (Joint::GetName, the bare name), whichever model.
  for (Robot* robot : world_.robots())
    robot->clearJointEfforts(req.joint_name);
  return true;
}

// ------------------------------------------------------------------------------ topics

void GazeboRosApiPlugin::publishModelStates()
{
  if (!model_states_pub_.subscribed())
    return;
  gazebo_msgs::ModelStates states;
  for (const StaticModelDescription& fixed : world_.staticModels())  // at rest where they are
  {
    states.name.push_back(fixed.name);
    states.pose.push_back(toMsg(fixed.pose));
    states.twist.push_back(toMsg(Twist()));
  }
  for (Robot* robot : world_.robots())
  {
    states.name.push_back(robot->name());
    states.pose.push_back(toMsg(robot->basePose()));
    states.twist.push_back(toMsg(robot->baseTwist()));
  }
  plant_.outbox().publish(model_states_pub_.publisher(), std::move(states));
}

gazebo_msgs::LinkStates GazeboRosApiPlugin::linkStates()
{
  gazebo_msgs::LinkStates states;
  for (const StaticModelDescription& fixed : world_.staticModels())
    for (const StaticModelDescription::Link& link : fixed.links)
    {
      states.name.push_back(fixed.name + "::" + link.name);
      states.pose.push_back(toMsg(link.pose));
      states.twist.push_back(toMsg(Twist()));
    }
  for (Robot* robot : world_.robots())
    for (const std::string& link : robot->linkNames())
    {
      states.name.push_back(robot->name() + "::" + link);
      states.pose.push_back(toMsg(robot->linkPose(link)));
      states.twist.push_back(toMsg(robot->linkTwist(link)));
    }
  return states;
}

void GazeboRosApiPlugin::publishLinkStates()
{
  const bool every_step = link_states_pub_.subscribed();
  const bool for_scene = scene_link_states_pub_.subscribed() &&
                         (scene_link_states_gate_.due(world_.timeNs()) || plant_.lastRequestedStep());
  if (!every_step && !for_scene)
    return;
  gazebo_msgs::LinkStates states = linkStates();
  if (every_step && for_scene)
    plant_.outbox().publish(scene_link_states_pub_.publisher(), states);
  plant_.outbox().publish((every_step ? link_states_pub_ : scene_link_states_pub_).publisher(), std::move(states));
}

void GazeboRosApiPlugin::publishScenePoses()
{
  if (scene_link_states_pub_.subscribed())
    plant_.outbox().publish(scene_link_states_pub_.publisher(), linkStates());
}

void GazeboRosApiPlugin::publishSceneContacts()
{
  if (!scene_contacts_pub_.subscribed() || !scene_contacts_gate_.due(world_.timeNs()))
    return;
  gazebo_msgs::ContactsState contacts;
  contacts.header.stamp = rosTime(world_.timeNs());
  contacts.header.frame_id = "world";
  for (const Contact& c : world_.contacts())
  {
    if (contacts.states.empty() || contacts.states.back().collision1_name != c.collision1 ||
        contacts.states.back().collision2_name != c.collision2)
    {
      contacts.states.emplace_back();
      contacts.states.back().collision1_name = c.collision1;
      contacts.states.back().collision2_name = c.collision2;
    }
    // the force on collision1 at the point: about the point itself it has no torque
    addContactPoint(contacts.states.back(), c.position, c.normal, c.depth, c.force, urdf::Vector3());
  }
  plant_.outbox().publish(scene_contacts_pub_.publisher(), std::move(contacts));
}

void GazeboRosApiPlugin::publishScene()
{
  if (!scene_pub_)
    return;
  std_msgs::String scene;
  scene.data = sceneJson(sceneOf(world_));
  plant_.outbox().publish(scene_pub_, std::move(scene));
}

}  // namespace bullet_plant
