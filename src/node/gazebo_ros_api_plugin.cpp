#include "gazebo_ros_api_plugin.h"

#include <cmath>
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

// A link by gazebo_ros's scoped name, model::link.
struct LinkRef
{
  Robot* robot = nullptr;
  std::string link;
  explicit operator bool() const { return robot != nullptr; }
};

LinkRef findLink(World& world, const std::string& scoped)
{
  const size_t at = scoped.find("::");
  if (at == std::string::npos)
    return {};
  Robot* robot = world.robot(scoped.substr(0, at));
  const std::string link = scoped.substr(at + 2);
  if (!robot)
    return {};
  for (const std::string& name : robot->linkNames())
    if (name == link)
      return {robot, link};
  return {};
}

struct State
{
  urdf::Pose pose;
  Twist twist;
};

State linkState(const LinkRef& ref) { return {ref.robot->linkPose(ref.link), ref.robot->linkTwist(ref.link)}; }
State modelState(Robot& robot) { return {robot.basePose(), robot.baseTwist()}; }

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
  advertiseServices();
  model_states_pub_ = nh_.advertise<gazebo_msgs::ModelStates>("model_states", 1);
  link_states_pub_ = nh_.advertise<gazebo_msgs::LinkStates>("link_states", 1);
  scene_pub_ = nh_.advertise<std_msgs::String>("scene", 1, true);
  // What viewers pose the scene by (gzclient gets poses throttled too): link_states at ~scene_rate.
  scene_link_states_pub_ = nh_.advertise<gazebo_msgs::LinkStates>("scene_link_states", 1);
  // And every contact (gzclient's contact view) on ~scene_contacts at the same rate.
  scene_contacts_pub_ = nh_.advertise<gazebo_msgs::ContactsState>("scene_contacts", 1);
  const int64_t scene_period_ns = periodNsOfRate(nh_.param("scene_rate", kDefaultSceneRate));
  scene_link_states_gate_.setPeriodNs(scene_period_ns);
  scene_contacts_gate_.setPeriodNs(scene_period_ns);
  publishScene();  // the world's; again after each spawn and delete, the only ways robots come and go
  plant_.connectWorldUpdateEnd([this] {
    publishModelStates();
    publishLinkStates();
    publishSceneContacts();
  });
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
  // Not gazebo_ros's: gzclient's step button, which Gazebo serves over its own transport
  // (WorldControl's multi_step). That many physics iterations, while paused.
  subscribers_.push_back(nh_.subscribe<std_msgs::UInt32>("step_physics", 10, [this](const std_msgs::UInt32::ConstPtr& msg) {
    const uint32_t iterations = msg->data;
    plant_.post([this, iterations] { plant_.requestSteps(iterations); });
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
      pose = inWorld(State{pose, Twist()}, frame.robot->linkPose(frame.link)).pose;
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
  plant_.onSimThread<bool>([this] {
    publishScene();
    publishScenePoses();
    return true;
  });
  return true;
}

bool GazeboRosApiPlugin::deleteModel(gazebo_msgs::DeleteModel::Request& req, gazebo_msgs::DeleteModel::Response& res)
{
  std::string message;
  res.success = plant_.remove(req.model_name, message);
  res.status_message = res.success ? "DeleteModel: successfully deleted model" : "DeleteModel: model does not exist";
  plant_.onSimThread<bool>([this] {
    publishScene();
    publishScenePoses();
    return true;
  });
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
  Robot* robot = world_.robot(req.model_name);
  if (!robot)
  {
    ROS_ERROR("GetModelState: model [%s] does not exist", req.model_name.c_str());
    res.success = false;
    res.status_message = "GetModelState: model does not exist";
    return true;
  }
  State state = modelState(*robot);
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
  if (!robot)
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
    target = inWorld(target, frame.robot->linkPose(frame.link));
  }
  if (!finite(target))
  {
    message = "SetModelState: the state of '" + request.model_name + "' is not finite";
    return false;
  }
  robot->setLinkState(robot->description().model->getRoot()->name, target.pose, target.twist);
  publishScenePoses();
  message = "SetModelState: set model state done";
  return true;
}

bool GazeboRosApiPlugin::updateLinkState(const gazebo_msgs::LinkState& request, std::string& message)
{
  const LinkRef link = findLink(world_, request.link_name);
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
    target = inWorld(target, frame.robot->linkPose(frame.link));
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
bool GazeboRosApiPlugin::getJointProperties(gazebo_msgs::GetJointProperties::Request& req,
                                            gazebo_msgs::GetJointProperties::Response& res)
{
  for (Robot* robot : world_.robots())
  {
    double position = 0, velocity = 0, effort = 0;
    if (!robot->jointState(req.joint_name, position, velocity, effort))
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
  res.ode_config.contact_max_correcting_vel = world_.description().contact_max_correcting_vel;
  res.success = true;
  res.status_message = "GetPhysicsProperties: got properties";
  return true;
}

bool GazeboRosApiPlugin::setPhysicsProperties(gazebo_msgs::SetPhysicsProperties::Request& req,
                                              gazebo_msgs::SetPhysicsProperties::Response& res)
{
  res.success = false;
  if (!std::isfinite(req.max_update_rate))
  {
    res.status_message = "SetPhysicsProperties: max_update_rate must be a number (0: as fast as possible)";
    return true;
  }
  try
  {
    world_.setTimeStep(req.time_step);
    world_.setGravity(urdf::Vector3(req.gravity.x, req.gravity.y, req.gravity.z));
  }
  catch (const std::exception& e)
  {
    res.status_message = std::string("SetPhysicsProperties: ") + e.what() + "; nothing was changed";
    return true;
  }
  plant_.setRealTimeFactor(req.max_update_rate > 0 ? req.max_update_rate * world_.timeStep() : 0.0);
  res.success = true;
  res.status_message = "physics engine updated";
  return true;
}

// ------------------------------------------------------------------------------ forces

bool GazeboRosApiPlugin::applyBodyWrench(gazebo_msgs::ApplyBodyWrench::Request& req,
                                         gazebo_msgs::ApplyBodyWrench::Response& res)
{
  res.success = false;
  const LinkRef body = findLink(world_, req.body_name);
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
    const urdf::Rotation axes = frame.robot->linkPose(frame.link).rotation;
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
  if (const LinkRef body = findLink(world_, req.body_name))
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
  // gazebo_ros names joints without their model: the first model that has it.
  for (Robot* robot : world_.robots())
    for (const std::string& joint : robot->jointNames())
      if (joint == req.joint_name)
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
  for (Robot* robot : world_.robots())
    robot->clearJointEfforts(req.joint_name);
  return true;
}

// ------------------------------------------------------------------------------ topics

void GazeboRosApiPlugin::publishModelStates()
{
  if (model_states_pub_.getNumSubscribers() == 0)
    return;
  gazebo_msgs::ModelStates states;
  for (Robot* robot : world_.robots())
  {
    states.name.push_back(robot->name());
    states.pose.push_back(toMsg(robot->basePose()));
    states.twist.push_back(toMsg(robot->baseTwist()));
  }
  model_states_pub_.publish(states);
}

gazebo_msgs::LinkStates GazeboRosApiPlugin::linkStates()
{
  gazebo_msgs::LinkStates states;
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
  const bool every_step = link_states_pub_.getNumSubscribers() > 0;
  const bool for_scene = scene_link_states_pub_.getNumSubscribers() > 0 &&
                         (scene_link_states_gate_.due(world_.timeNs()) || plant_.lastRequestedStep());
  if (!every_step && !for_scene)
    return;
  const gazebo_msgs::LinkStates states = linkStates();
  if (every_step)
    link_states_pub_.publish(states);
  if (for_scene)
    scene_link_states_pub_.publish(states);
}

void GazeboRosApiPlugin::publishScenePoses()
{
  if (scene_link_states_pub_.getNumSubscribers() > 0)
    scene_link_states_pub_.publish(linkStates());
}

void GazeboRosApiPlugin::publishSceneContacts()
{
  if (scene_contacts_pub_.getNumSubscribers() == 0 || !scene_contacts_gate_.due(world_.timeNs()))
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
  scene_contacts_pub_.publish(contacts);
}

void GazeboRosApiPlugin::publishScene()
{
  std_msgs::String scene;
  scene.data = sceneJson(sceneOf(world_));
  scene_pub_.publish(scene);
}

}  // namespace bullet_plant
