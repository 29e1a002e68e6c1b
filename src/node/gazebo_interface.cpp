#include "gazebo_interface.h"

#include <cmath>
#include <stdexcept>

#include <gazebo_msgs/ApplyBodyWrench.h>
#include <gazebo_msgs/ApplyJointEffort.h>
#include <gazebo_msgs/BodyRequest.h>
#include <gazebo_msgs/DeleteModel.h>
#include <gazebo_msgs/GetLinkState.h>
#include <gazebo_msgs/GetModelProperties.h>
#include <gazebo_msgs/GetModelState.h>
#include <gazebo_msgs/GetPhysicsProperties.h>
#include <gazebo_msgs/GetWorldProperties.h>
#include <gazebo_msgs/JointRequest.h>
#include <gazebo_msgs/LinkStates.h>
#include <gazebo_msgs/ModelStates.h>
#include <gazebo_msgs/SetLinkState.h>
#include <gazebo_msgs/SetModelConfiguration.h>
#include <gazebo_msgs/SetModelState.h>
#include <gazebo_msgs/SetPhysicsProperties.h>
#include <gazebo_msgs/SpawnModel.h>
#include <std_srvs/Empty.h>
#include <tinyxml2.h>

#include "bullet_plant/world.h"
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
urdf::Vector3 sub(const urdf::Vector3& a, const urdf::Vector3& b) { return urdf::Vector3(a.x - b.x, a.y - b.y, a.z - b.z); }

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

// ------------------------------------------------------------------------------ messages

urdf::Pose fromMsg(const geometry_msgs::Pose& m)
{
  urdf::Pose p;
  p.position = urdf::Vector3(m.position.x, m.position.y, m.position.z);
  p.rotation = urdf::Rotation(m.orientation.x, m.orientation.y, m.orientation.z, m.orientation.w);
  // gazebo_ros normalises, so that an all-zero quaternion means no rotation.
  if (m.orientation.x == 0 && m.orientation.y == 0 && m.orientation.z == 0 && m.orientation.w == 0)
    p.rotation = urdf::Rotation(0, 0, 0, 1);
  p.rotation.normalize();
  return p;
}

geometry_msgs::Pose toMsg(const urdf::Pose& p)
{
  geometry_msgs::Pose m;
  m.position.x = p.position.x;
  m.position.y = p.position.y;
  m.position.z = p.position.z;
  m.orientation.x = p.rotation.x;
  m.orientation.y = p.rotation.y;
  m.orientation.z = p.rotation.z;
  m.orientation.w = p.rotation.w;
  return m;
}

Twist fromMsg(const geometry_msgs::Twist& m)
{
  Twist t;
  t.linear = {{m.linear.x, m.linear.y, m.linear.z}};
  t.angular = {{m.angular.x, m.angular.y, m.angular.z}};
  return t;
}

geometry_msgs::Twist toMsg(const Twist& t)
{
  geometry_msgs::Twist m;
  m.linear.x = t.linear[0];
  m.linear.y = t.linear[1];
  m.linear.z = t.linear[2];
  m.angular.x = t.angular[0];
  m.angular.y = t.angular[1];
  m.angular.z = t.angular[2];
  return m;
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

// ------------------------------------------------------------------------------ the interface

template <class Srv, class Handler>
void GazeboInterface::serveOnSimThread(ros::NodeHandle& nh, const std::string& name, Handler handler)
{
  services_.push_back(nh.advertiseService<typename Srv::Request, typename Srv::Response>(
      name, [this, handler](typename Srv::Request& req, typename Srv::Response& res) {
        return plant_.onSimThread<bool>([&] { return handler(req, res); });
      }));
}

GazeboInterface::GazeboInterface(RosPlant& plant, ros::NodeHandle& nh) : plant_(plant)
{
  auto empty = [&](const std::string& name, std::function<void()> action) {
    serveOnSimThread<std_srvs::Empty>(nh, name, [action](auto&, auto&) {
      action();
      return true;
    });
  };
  empty("pause_physics", [this] { plant_.applyPaused(true); });
  empty("unpause_physics", [this] { plant_.applyPaused(false); });
  empty("reset_simulation", [this] { plant_.resetSimulation(); });
  empty("reset_world", [this] { plant_.world_->resetWorld(); });

  World& world = *plant_.world_;
  auto spawn = [this, &world](gazebo_msgs::SpawnModel::Request& req, gazebo_msgs::SpawnModel::Response& res) {
    // What the request names in the world, looked at in one visit to the simulation thread.
    enum class Check { Ok, NoReferenceFrame, Exists };
    urdf::Pose pose = fromMsg(req.initial_pose);
    const Check check = plant_.onSimThread<Check>([&] {
      if (!isWorldFrame(req.reference_frame))
      {
        const LinkRef frame = findLink(world, req.reference_frame);
        if (!frame)
          return Check::NoReferenceFrame;
        pose = inWorld(State{pose, Twist()}, frame.robot->linkPose(frame.link)).pose;
      }
      return world.robot(req.model_name) ? Check::Exists : Check::Ok;
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
  };
  // spawn_urdf_model refuses what is not URDF (gazebo_ros fails the call itself then).
  services_.push_back(nh.advertiseService<gazebo_msgs::SpawnModel::Request, gazebo_msgs::SpawnModel::Response>(
      "spawn_urdf_model", [spawn](gazebo_msgs::SpawnModel::Request& req, gazebo_msgs::SpawnModel::Response& res) {
        // XML that is not well-formed goes on to the plant, whose error names the parser's complaint.
        const std::string root = rootElement(req.model_xml);
        if (!root.empty() && root != "robot")
        {
          ROS_ERROR("SpawnModel: Failure - entity format is invalid.");
          res.success = false;
          res.status_message = "SpawnModel: Failure - entity format is invalid.";
          return false;
        }
        return spawn(req, res);
      }));
  // spawn_sdf_model takes URDF too, as gazebo_ros's does; the plant's robots are URDF only.
  services_.push_back(nh.advertiseService<gazebo_msgs::SpawnModel::Request, gazebo_msgs::SpawnModel::Response>(
      "spawn_sdf_model", [spawn](gazebo_msgs::SpawnModel::Request& req, gazebo_msgs::SpawnModel::Response& res) {
        const std::string root = rootElement(req.model_xml);
        if (root == "robot")
          return spawn(req, res);
        res.success = false;
        res.status_message = root == "sdf" || root == "gazebo"
                                 ? "SpawnModel: Failure - the Bullet plant spawns URDF models only; put SDF model '" +
                                       req.model_name + "' in the world file (<include> or <model>)"
                                 : "GazeboRosApiPlugin SpawnModel Failure: input model_xml not SDF or URDF, or cannot "
                                   "be converted to Gazebo compatible format.";
        ROS_ERROR_STREAM(res.status_message);
        return true;
      }));
  services_.push_back(nh.advertiseService<gazebo_msgs::DeleteModel::Request, gazebo_msgs::DeleteModel::Response>(
      "delete_model", [this](auto& req, auto& res) {
        std::string message;
        res.success = plant_.remove(req.model_name, message);
        res.status_message = res.success ? "DeleteModel: successfully deleted model" : "DeleteModel: model does not exist";
        if (!res.success)
          ROS_ERROR("DeleteModel: model [%s] does not exist", req.model_name.c_str());
        return true;
      }));

  serveOnSimThread<gazebo_msgs::GetModelState>(nh, "get_model_state", [this, &world](auto& req, auto& res) {
    Robot* robot = world.robot(req.model_name);
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
      const LinkRef frame = findLink(world, req.relative_entity_name);
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
    res.header.stamp = rosTime(world.timeNs());
    res.header.frame_id = req.relative_entity_name;
    res.pose = toMsg(state.pose);
    res.twist = toMsg(state.twist);
    res.success = true;
    res.status_message = "GetModelState: got properties";
    return true;
  });

  serveOnSimThread<gazebo_msgs::GetLinkState>(nh, "get_link_state", [this, &world](auto& req, auto& res) {
    const LinkRef link = findLink(world, req.link_name);
    if (!link)
    {
      res.success = false;
      res.status_message = "GetLinkState: link not found, did you forget to scope the link by model name?";
      return true;
    }
    State state = linkState(link);
    if (!isWorldFrame(req.reference_frame))
    {
      const LinkRef frame = findLink(world, req.reference_frame);
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
  });

  serveOnSimThread<gazebo_msgs::SetModelState>(nh, "set_model_state", [this](auto& req, auto& res) {
    res.success = setModelState(req.model_state, res.status_message);
    return true;
  });
  subscribers_.push_back(nh.subscribe<gazebo_msgs::ModelState>(
      "set_model_state", 10, [this](const gazebo_msgs::ModelState::ConstPtr& msg) {
        plant_.post([this, msg] {
          std::string message;
          setModelState(*msg, message);
        });
      }));
  serveOnSimThread<gazebo_msgs::SetLinkState>(nh, "set_link_state", [this](auto& req, auto& res) {
    res.success = setLinkState(req.link_state, res.status_message);
    return true;
  });
  subscribers_.push_back(nh.subscribe<gazebo_msgs::LinkState>(
      "set_link_state", 10, [this](const gazebo_msgs::LinkState::ConstPtr& msg) {
        plant_.post([this, msg] {
          std::string message;
          setLinkState(*msg, message);
        });
      }));

  serveOnSimThread<gazebo_msgs::SetModelConfiguration>(nh, "set_model_configuration", [this, &world](auto& req, auto& res) {
    Robot* robot = world.robot(req.model_name);
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
    res.success = true;
    res.status_message = "SetModelConfiguration: success";
    return true;
  });

  serveOnSimThread<gazebo_msgs::GetWorldProperties>(nh, "get_world_properties", [this, &world](auto&, auto& res) {
    res.sim_time = world.time();
    for (Robot* robot : world.robots())
      res.model_names.push_back(robot->name());
    res.rendering_enabled = true;
    res.success = true;
    res.status_message = "GetWorldProperties: got properties";
    return true;
  });

  serveOnSimThread<gazebo_msgs::GetModelProperties>(nh, "get_model_properties", [this, &world](auto& req, auto& res) {
    Robot* robot = world.robot(req.model_name);
    if (!robot)
    {
      ROS_ERROR("GetModelProperties: model [%s] does not exist", req.model_name.c_str());
      res.success = false;
      res.status_message = "GetModelProperties: model does not exist";
      return true;
    }
    res.body_names = robot->linkNames();
    res.joint_names = robot->jointNames();
    res.is_static = robot->description().is_static;
    res.success = true;
    res.status_message = "GetModelProperties: got properties";
    return true;
  });

  serveOnSimThread<gazebo_msgs::GetPhysicsProperties>(nh, "get_physics_properties", [this, &world](auto&, auto& res) {
    res.time_step = world.timeStep();
    res.pause = world.paused();
    // Gazebo's real_time_update_rate: steps per wall second; 0 runs as fast as possible.
    res.max_update_rate = plant_.real_time_factor_ > 0 ? plant_.real_time_factor_ / world.timeStep() : 0.0;
    const urdf::Vector3 g = world.gravity();
    res.gravity.x = g.x;
    res.gravity.y = g.y;
    res.gravity.z = g.z;
    res.ode_config.sor_pgs_iters = 10;  // the plant's solver passes (README, contacts)
    res.ode_config.sor_pgs_w = 1.0;
    res.success = true;
    res.status_message = "GetPhysicsProperties: got properties";
    return true;
  });

  serveOnSimThread<gazebo_msgs::SetPhysicsProperties>(nh, "set_physics_properties", [this, &world](auto& req, auto& res) {
    res.success = false;
    if (!std::isfinite(req.max_update_rate))
    {
      res.status_message = "SetPhysicsProperties: max_update_rate must be a number (0: as fast as possible)";
      return true;
    }
    try
    {
      world.setTimeStep(req.time_step);
      world.setGravity(urdf::Vector3(req.gravity.x, req.gravity.y, req.gravity.z));
    }
    catch (const std::exception& e)
    {
      res.status_message = std::string("SetPhysicsProperties: ") + e.what() + "; nothing was changed";
      return true;
    }
    plant_.setRealTimeFactor(req.max_update_rate > 0 ? req.max_update_rate * world.timeStep() : 0.0);
    res.success = true;
    res.status_message = "physics engine updated";
    return true;
  });

  serveOnSimThread<gazebo_msgs::ApplyBodyWrench>(nh, "apply_body_wrench", [this, &world](auto& req, auto& res) {
    res.success = false;
    const LinkRef body = findLink(world, req.body_name);
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
      const LinkRef frame = findLink(world, req.reference_frame);
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
    body.robot->applyLinkWrench(body.link, force, torque, jobStart(req.start_time, world.timeNs()),
                                req.duration.toNSec());
    res.success = true;
    res.status_message = "";
    return true;
  });
  serveOnSimThread<gazebo_msgs::BodyRequest>(nh, "clear_body_wrenches", [this, &world](auto& req, auto&) {
    if (const LinkRef body = findLink(world, req.body_name))
      body.robot->clearLinkWrenches(body.link);
    return true;
  });

  serveOnSimThread<gazebo_msgs::ApplyJointEffort>(nh, "apply_joint_effort", [this, &world](auto& req, auto& res) {
    res.success = false;
    if (!std::isfinite(req.effort))
    {
      res.status_message = "ApplyJointEffort: the effort on '" + req.joint_name + "' is not finite";
      return true;
    }
    // gazebo_ros names joints without their model: the first model that has it.
    for (Robot* robot : world.robots())
      for (const std::string& joint : robot->jointNames())
        if (joint == req.joint_name)
        {
          robot->applyJointEffort(joint, req.effort, jobStart(req.start_time, world.timeNs()), req.duration.toNSec());
          res.success = true;
          res.status_message = "ApplyJointEffort: effort set";
          return true;
        }
    res.status_message = "ApplyJointEffort: joint not found";
    return true;
  });
  serveOnSimThread<gazebo_msgs::JointRequest>(nh, "clear_joint_forces", [this, &world](auto& req, auto&) {
    for (Robot* robot : world.robots())
      robot->clearJointEfforts(req.joint_name);
    return true;
  });

  model_states_pub_ = nh.advertise<gazebo_msgs::ModelStates>("model_states", 1);
  link_states_pub_ = nh.advertise<gazebo_msgs::LinkStates>("link_states", 1);
}

bool GazeboInterface::setModelState(const gazebo_msgs::ModelState& request, std::string& message)
{
  World& world = *plant_.world_;
  Robot* robot = world.robot(request.model_name);
  if (!robot)
  {
    ROS_ERROR("Updating ModelState: model [%s] does not exist", request.model_name.c_str());
    message = "SetModelState: model does not exist";
    return false;
  }
  State target{fromMsg(request.pose), fromMsg(request.twist)};
  if (!isWorldFrame(request.reference_frame))
  {
    const LinkRef frame = findLink(world, request.reference_frame);
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
  message = "SetModelState: set model state done";
  return true;
}

bool GazeboInterface::setLinkState(const gazebo_msgs::LinkState& request, std::string& message)
{
  World& world = *plant_.world_;
  const LinkRef link = findLink(world, request.link_name);
  if (!link)
  {
    ROS_ERROR("Updating LinkState: link [%s] does not exist", request.link_name.c_str());
    message = "SetLinkState: link does not exist";
    return false;
  }
  State target{fromMsg(request.pose), fromMsg(request.twist)};
  if (!isWorldFrame(request.reference_frame))
  {
    const LinkRef frame = findLink(world, request.reference_frame);
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
  message = "SetLinkState: success";
  return true;
}

void GazeboInterface::publish()
{
  const bool models = model_states_pub_.getNumSubscribers() > 0, links = link_states_pub_.getNumSubscribers() > 0;
  if (!models && !links)
    return;
  gazebo_msgs::ModelStates model_states;
  gazebo_msgs::LinkStates link_states;
  for (Robot* robot : plant_.world_->robots())
  {
    if (models)
    {
      model_states.name.push_back(robot->name());
      model_states.pose.push_back(toMsg(robot->basePose()));
      model_states.twist.push_back(toMsg(robot->baseTwist()));
    }
    if (links)
      for (const std::string& link : robot->linkNames())
      {
        link_states.name.push_back(robot->name() + "::" + link);
        link_states.pose.push_back(toMsg(robot->linkPose(link)));
        link_states.twist.push_back(toMsg(robot->linkTwist(link)));
      }
  }
  if (models)
    model_states_pub_.publish(model_states);
  if (links)
    link_states_pub_.publish(link_states);
}

}  // namespace bullet_plant
