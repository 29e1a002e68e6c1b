#include "ros_plant.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <sstream>

#include <rosgraph_msgs/Clock.h>

#include "bullet_plant/gazebo_host.h"
#include "bullet_plant/geometry.h"
#include "bullet_plant/params.h"
#include "bullet_plant/plugin_names.h"
#include "bullet_plant/world_description.h"
#include "ros_names.h"
#include "ros_time.h"

namespace bullet_plant
{

namespace
{
// The parameter server's value as the plant's parameter tree.
Param toParam(XmlRpc::XmlRpcValue& v)
{
  switch (v.getType())
  {
    case XmlRpc::XmlRpcValue::TypeBoolean: return Param::boolean(static_cast<bool>(v));
    case XmlRpc::XmlRpcValue::TypeInt: return Param::integer(static_cast<int>(v));
    case XmlRpc::XmlRpcValue::TypeDouble: return Param::real(static_cast<double>(v));
    case XmlRpc::XmlRpcValue::TypeString: return Param::string(static_cast<std::string>(v));
    case XmlRpc::XmlRpcValue::TypeArray:
    {
      std::vector<Param> items;
      for (int i = 0; i < v.size(); ++i)
        items.push_back(toParam(v[i]));
      return Param::list(items);
    }
    case XmlRpc::XmlRpcValue::TypeStruct:
    {
      Param map = Param::map();
      for (auto& kv : v)
        map.set(kv.first, toParam(kv.second));
      return map;
    }
    default: return Param();
  }
}

}  // namespace

void RosPlant::post(std::function<void()> work)
{
  {
    std::lock_guard<std::mutex> lock(queue_mutex_);
    queue_.push_back(std::move(work));
  }
  queue_cv_.notify_one();
}

void RosPlant::runQueuedWork()
{
  std::deque<std::function<void()>> work;
  {
    std::lock_guard<std::mutex> lock(queue_mutex_);
    work.swap(queue_);
  }
  for (auto& w : work)
    w();
}

namespace
{
// Slower than this, one 1 ms step takes over a second of wall time: a typo, not a wish.
constexpr double kSlowestRealTimeFactor = 1e-3;

// roslaunch passes `real_time_factor:=1e-6` as a string; read it as the number it spells.
double readRealTimeFactor(const ros::NodeHandle& private_nh, double world_value)
{
  const std::string name = private_nh.resolveName("real_time_factor");
  XmlRpc::XmlRpcValue value;
  if (!private_nh.getParam("real_time_factor", value))
    return world_value;
  double factor = 0;
  if (value.getType() == XmlRpc::XmlRpcValue::TypeDouble)
    factor = static_cast<double>(value);
  else if (value.getType() == XmlRpc::XmlRpcValue::TypeInt)
    factor = static_cast<int>(value);
  else if (value.getType() == XmlRpc::XmlRpcValue::TypeString)
  {
    const std::string text = static_cast<std::string>(value);
    char* end = nullptr;
    factor = std::strtod(text.c_str(), &end);
    if (text.empty() || *end != '\0')
      throw std::runtime_error("parameter " + name + " is '" + text + "', not a number; give e.g. 1.0, or 0 to run as fast as possible");
  }
  else
    throw std::runtime_error("parameter " + name + " must be a number (e.g. 1.0, or 0 to run as fast as possible)");
  if (!std::isfinite(factor) || (factor > 0 && factor < kSlowestRealTimeFactor))
    throw std::runtime_error("parameter " + name + " = " + std::to_string(factor) + " is too small: use at least " +
                             std::to_string(kSlowestRealTimeFactor) + ", or 0 (or less) to run as fast as possible");
  return factor;
}
// A list parameter as a launch file's <rosparam> gives it, or as gzserver passes it on the command
// line (one item a line: roscpp reads `_name:=value` as one string).
std::vector<std::string> readListParam(ros::NodeHandle& private_nh, const std::string& name,
                                       const std::vector<std::string>& fallback)
{
  std::vector<std::string> list;
  if (private_nh.getParam(name, list))
    return list;
  std::string text;
  if (!private_nh.getParam(name, text))
    return fallback;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);)
    if (!line.empty())
      list.push_back(line);
  return list;
}
}  // namespace

RosPlant::RosPlant(ros::NodeHandle& nh, ros::NodeHandle& private_nh, ModelPluginLoader load_model_plugins)
  : nh_(nh), private_nh_(private_nh), load_model_plugins_(std::move(load_model_plugins))
{
  // Publishing on threads of its own by default: the simulation thread steps while they serialize
  // and write (outbox.h); 0 publishes on the simulation thread, as before.
  int publishing_threads = 1;
  private_nh_.param("publishing_threads", publishing_threads, publishing_threads);
  if (publishing_threads < 0 || publishing_threads > 64)
    throw std::runtime_error("parameter " + private_nh_.resolveName("publishing_threads") + " = " +
                             std::to_string(publishing_threads) +
                             ": give 0 (publish on the simulation thread) or a number of threads up to 64 (default 1)");
  outbox_.reset(new Outbox(static_cast<unsigned>(publishing_threads)));
  std::string world_file;
  private_nh_.param<std::string>("world_name", world_file, "");
  bool verbose = false;
  private_nh_.param("verbose", verbose, false);
  setGazeboVerbose(verbose);
  WorldDescription description = emptyWorldDescription();
  try
  {
    if (!world_file.empty())
      description = parseWorldFile(world_file);
  }
  catch (const WorldFileNotFound& e)
  {
    // Gazebo 11's server: the error, then the empty world (Server::ParseArgs)
    ROS_ERROR("Could not open file[%s]: %s", world_file.c_str(), e.what());
    ROS_WARN("Falling back on worlds/empty.world");
  }
  // rosout from the world's first message on: what it says while it is built (models refused or
  // spawned from the world file) is the node's too.
  world_.reset(new World(description, [](LogLevel level, const std::string& m) {
    switch (level)
    {
      case LogLevel::Debug: ROS_DEBUG_STREAM(m); break;
      case LogLevel::Info: ROS_INFO_STREAM(m); break;
      case LogLevel::Warn: ROS_WARN_STREAM(m); break;
      case LogLevel::Error: ROS_ERROR_STREAM(m); break;
    }
  }));
  // Camera frames render while the following steps run and are published when done, stamped
  // with their own time: the simulation does not stall on a frame.
  world_->setFramesAhead(true);
  // As Gazebo runs: a camera frame due while the camera's previous one still renders is skipped and
  // the simulation goes on; ~lockstep (gzserver --lockstep) renders every frame and waits for it.
  bool lockstep = false;
  private_nh_.param("lockstep", lockstep, false);
  world_->setLockstep(lockstep);
  loadWorldModels();
  // What Gazebo plugins insert (their world's Load may have already) comes as a spawn's, with its plugins.
  world_->setModelInserter([this](const std::string& sdf_xml) { insertModel(sdf_xml); });
  // gzserver -s FILE: Gazebo system plugins of the user's own (gazebo_ros's own are this node),
  // Load given gzserver's command line as Gazebo's server gives it.
  const std::vector<std::string> server_arguments = readListParam(private_nh_, "server_arguments", {"gzserver"});
  for (const std::string& plugin : readListParam(private_nh_, "system_plugins", {}))
    world_->loadSystemPlugin(plugin, server_arguments);
  world_->prepareCameras();
  real_time_factor_ = readRealTimeFactor(private_nh_, description.pace());
  // Every node on simulated time subscribes /clock; at Gazebo's 1 kHz that costs more than the physics.
  double clock_rate = 100.0;
  private_nh_.param("pub_clock_frequency", clock_rate, clock_rate);
  clock_gate_.setPeriodNs(periodNsOfRate(clock_rate));
  clock_pub_ = nh_.advertise<rosgraph_msgs::Clock>("/clock", 10);
  bool paused = false;
  private_nh_.param("paused", paused, false);
  applyPaused(paused);
  // gzserver --iters N: the world simulates N steps and the server stops, as Gazebo's run_worlds(N).
  int iterations = 0;
  private_nh_.param("iterations", iterations, 0);
  if (iterations < 0)
    throw std::runtime_error("parameter " + private_nh_.resolveName("iterations") + " = " +
                             std::to_string(iterations) + ": give a number of steps, or 0 to run until stopped");
  iterations_ = static_cast<uint64_t>(iterations);
  const unsigned threads = outbox_->threads();
  const std::string publishing =
      threads == 0 ? "the simulation thread" : std::to_string(threads) + (threads == 1 ? " thread" : " threads");
  ROS_INFO("Bullet plant ready: world '%s', %.4f s steps, real time factor %g%s, publishing on %s",
           description.name.c_str(), world_->timeStep(), real_time_factor_, paused ? " (paused)" : "", publishing.c_str());
}

RosPlant::~RosPlant()
{
  world_->setModelInserter(nullptr);  // a plugin going with the world inserts into it, not into this
  robots_.clear();
  outbox_.reset();  // what the plugins queued, published
}

void RosPlant::copyParams(const std::string& key)
{
  XmlRpc::XmlRpcValue value;
  bool found = nh_.getParam(key, value);
  post([this, key, found, value]() mutable {
    if (found)
      world_->params().set(key, toParam(value));
    else
      world_->params().erase(key);
  });
}

RosPlant::SpawnRequest RosPlant::prepareSpawn(const std::string& name, ModelDescription model,
                                              const std::string& ns, const urdf::Pose& pose,
                                              const std::map<std::string, double>& joints)
{
  SpawnRequest request;
  request.name = name.empty() ? model.name : name;
  // gazebo_ros: the SDF's model <pose> in the frame of the request's initial pose (a URDF has none).
  request.pose = compose(pose, model.pose);
  request.description = std::move(model.robot);
  request.ns = ns;
  request.joints = joints;
  // The robot namespace decides where its pid_gains live: read it before the sim thread spawns.
  request.control_ns = request.description.control.controlNamespace(ns);
  requireValidRosName(request.description.control.givenControlNamespace(ns),
                      "robot '" + request.name + "' robotNamespace");
  copyParams(request.control_ns + "/gazebo_ros_control");
  copyParams("/gazebo_ros_control");  // where legacyModeNS (the default) has Gazebo look for pid_gains
  for (const ModelPluginDescription& plugin : request.description.model_plugins)
  {
    // The tf_prefix parameter the plant's GazeboRos helper plugins look up from their namespace.
    for (const std::string& key : tfPrefixParamKeys(plugin, modelPluginNamespace(plugin, ns, request.name)))
      copyParams(key);
    // The mimic joint plugin's pid gains, wherever its <hasPID> puts them.
    const std::string& gains_element = findPluginFile(plugin.filename)->pid_gains_element;
    if (!gains_element.empty() && plugin.has(gains_element))
    {
      const std::string gains = plugin.text(gains_element, "");
      const std::string plugin_ns =
          gains.empty() || gains[0] != '/' ? modelPluginNamespace(plugin, ns, request.name) : "";
      copyParams("/" + joinPath(plugin_ns, gains.empty() ? "gazebo_ros_control" : gains));
    }
  }
  return request;
}

bool RosPlant::addModel(SpawnRequest& request, std::string& message)
{
  const std::string& name = request.name;
  try
  {
    // Two controller managers cannot offer their services under one name: the second would be unreachable.
    for (Robot* other : world_->robots())
      if (request.description.control.present && other->controllerManager() &&
          other->controlNamespace() == request.control_ns)
        throw std::invalid_argument("robot '" + name + "': robotNamespace '" + other->controlNamespace() +
                                    "' already holds the controller manager of robot '" + other->name() +
                                    "'; give each robot its own namespace (spawn_model -robot_namespace)");
    Robot& robot = world_->spawn(std::move(request.description), name, request.pose, request.ns, request.joints);
    loadModelPlugins(robot);
    message = "spawned '" + name + "'" +
              (robot.controllerManager() ? " with a controller manager in " + robot.controlNamespace() : "");
    ROS_INFO_STREAM(message);
  }
  catch (const std::exception& e)
  {
    message = e.what();
    ROS_ERROR("Could not spawn '%s': %s", name.c_str(), message.c_str());
    return false;
  }
  for (const std::function<void()>& callback : models_changed_)
    callback();
  return true;
}

bool RosPlant::spawn(const std::string& name, const std::string& model_xml, const std::string& ns,
                     const urdf::Pose& pose, const std::map<std::string, double>& joints, std::string& message)
{
  SpawnRequest request;
  try
  {
    request = prepareSpawn(name, readSpawnedModel(model_xml), ns, pose, joints);
  }
  catch (const std::exception& e)
  {
    message = e.what();
    ROS_ERROR("Could not spawn '%s': %s", name.c_str(), message.c_str());
    return false;
  }
  return onSimThread<bool>([&] { return addModel(request, message); });
}

void RosPlant::insertModel(const std::string& sdf_xml)
{
  std::shared_ptr<SpawnRequest> request;
  try
  {
    request = std::make_shared<SpawnRequest>(prepareSpawn("", readInsertedModel(sdf_xml), "", urdf::Pose(), {}));
  }
  catch (const std::exception& e)
  {
    ROS_ERROR("Could not insert the model a Gazebo plugin asked for (World::InsertModelString, InsertModelFile or "
              "InsertModelSDF): %s; the world goes on without it", e.what());
    return;
  }
  // After the parameters prepareSpawn copies, as Gazebo's world adds it after its update, paused or not.
  post([this, request] {
    request->name = world_->uniqueModelName(request->name);
    std::string message;
    addModel(*request, message);
  });
}

void RosPlant::connectModelsChanged(std::function<void()> callback) { models_changed_.push_back(std::move(callback)); }

void RosPlant::loadModelPlugins(Robot& robot)
{
  const std::string name = robot.name();
  std::unique_ptr<ModelPlugins> plugins;
  try
  {
    plugins = load_model_plugins_(*this, robot);
  }
  catch (const std::exception&)
  {
    // A name ROS refuses (a sensor topic, the namespace): refuse the whole robot, as no half of it can run.
    world_->remove(name);
    throw;
  }
  robots_[name] = std::move(plugins);
  robots_[name]->updateSubscriptions();
}

void RosPlant::loadWorldModels()
{
  std::vector<std::string> names;
  for (Robot* robot : world_->robots())
    names.push_back(robot->name());
  for (const std::string& name : names)
    try
    {
      loadModelPlugins(*world_->robot(name));
      ROS_INFO("world model '%s' loaded", name.c_str());
    }
    catch (const std::exception& e)
    {
      ROS_ERROR("world model '%s' is left out: %s", name.c_str(), e.what());
    }
}

bool RosPlant::remove(const std::string& name, std::string& message)
{
  return onSimThread<bool>([&] {
    robots_.erase(name);
    if (!world_->remove(name))
    {
      message = "no model named '" + name + "'";
      return false;
    }
    message = "deleted '" + name + "'";
    for (const std::function<void()>& callback : models_changed_)
      callback();
    return true;
  });
}

void RosPlant::applyPaused(bool paused)
{
  paused_ = paused;
  steps_requested_ = 0;
  world_->setPaused(paused);
  if (paused)
    publishClock(true);  // where it stopped, whatever the clock's rate
  pace_start_wall_ = ros::WallTime::now();
  pace_start_sim_ns_ = world_->timeNs();
}

void RosPlant::requestSteps(uint32_t iterations)
{
  if (!paused_)
  {
    ROS_WARN("step: the simulation is running; pause it (/gazebo/pause_physics) to step it");
    return;
  }
  if (steps_requested_ == 0)
  {
    pace_start_wall_ = ros::WallTime::now();
    pace_start_sim_ns_ = world_->timeNs();
  }
  steps_requested_ += iterations;
}

void RosPlant::resetSimulation()
{
  world_->resetSimulation();
  clock_gate_.reset();
  publishClock();
  pace_start_wall_ = ros::WallTime::now();
  pace_start_sim_ns_ = world_->timeNs();
}

void RosPlant::setRealTimeFactor(double factor)
{
  real_time_factor_ = factor;
  pace_start_wall_ = ros::WallTime::now();
  pace_start_sim_ns_ = world_->timeNs();
}

void RosPlant::publishClock(bool force)
{
  if (!clock_gate_.due(world_->timeNs()) && !force)
    return;
  rosgraph_msgs::Clock clock;
  clock.clock = rosTime(world_->timeNs());
  outbox_->publish(clock_pub_, clock);
}

void RosPlant::stepAndPublish()
{
  world_->step();
  const int64_t now = world_->timeNs();
  if (paused_ && steps_requested_ > 0)
    --steps_requested_;
  publishClock(paused_ && steps_requested_ == 0);
  const bool check_subscribers = world_->steps() % 100 == 0;
  for (auto& kv : robots_)
  {
    if (check_subscribers)
      kv.second->updateSubscriptions();
    kv.second->OnUpdate(now);
  }
  for (const std::function<void()>& callback : world_update_end_)
    callback();
  outbox_->endOfStep();
}

void RosPlant::connectWorldUpdateEnd(std::function<void()> callback)
{
  world_update_end_.push_back(std::move(callback));
}

void RosPlant::pace()
{
  if (real_time_factor_ <= 0)
    return;
  // Sleep in short slices that keep serving the services and notice shutdown, however slow the pace.
  const ros::WallDuration slice(0.01);
  ros::WallTime target = pace_start_wall_ + ros::WallDuration((world_->timeNs() - pace_start_sim_ns_) * 1e-9 / real_time_factor_);
  ros::WallTime now = ros::WallTime::now();
  // Steps go on without a sleep until the simulation is kPaceSlack ahead of the wall clock: a sleep
  // and its wake-up cost the kernel more than a light step (with a sleep after every 1 ms step the
  // scheduler was a sixth of the node's CPU with 50 robots, make bench-fleet), and the simulated
  // time keeps to the wall clock within that slack. A/B, medians of 3 (make bench-fleet's fleet):
  // 2 ms -> 5 ms took one robot from 5.6 % to 4.0 % of a core and 50 from 57.5 % to 55.3 %.
  static const ros::WallDuration kPaceSlack(0.005);
  if (target > now && target - now < kPaceSlack)
    return;
  outbox_->handOver();  // nothing waits while the simulation sleeps
  while (target > now && ros::ok() && stepping())
  {
    std::min(target - now, slice).sleep();
    runQueuedWork();
    target = pace_start_wall_ + ros::WallDuration((world_->timeNs() - pace_start_sim_ns_) * 1e-9 / real_time_factor_);
    now = ros::WallTime::now();
  }
  if ((now - target).toSec() > 0.5)
  {
    // Far behind (a slow machine, a debugger): start pacing afresh instead of racing to catch up.
    pace_start_wall_ = now;
    pace_start_sim_ns_ = world_->timeNs();
  }
}

void RosPlant::publishStatus()
{
  ros::WallTime now = ros::WallTime::now();
  if (last_status_.isZero())
  {
    last_status_ = now;
    status_start_sim_ns_ = world_->timeNs();
    return;
  }
  double wall = (now - last_status_).toSec();
  if (wall < 5.0)
    return;
  double rtf = (world_->timeNs() - status_start_sim_ns_) * 1e-9 / wall;
  std::ostringstream line;
  line.precision(3);
  line << std::fixed << "sim " << world_->time() << " s, real time factor " << rtf;
  for (Robot* r : world_->robots())
  {
    urdf::Pose p = r->basePose();
    Twist t = r->baseTwist();
    line << ", " << r->name() << " at (" << p.position.x << ", " << p.position.y << ") "
         << std::hypot(t.linear[0], t.linear[1]) << " m/s";
  }
  ROS_INFO_STREAM(line.str());
  last_status_ = now;
  status_start_sim_ns_ = world_->timeNs();
}

void RosPlant::run()
{
  while (ros::ok())
  {
    runQueuedWork();
    if (!stepping())
    {
      outbox_->handOver();  // the last step's messages (a stepper waits for them)
      std::unique_lock<std::mutex> lock(queue_mutex_);
      queue_cv_.wait_for(lock, std::chrono::milliseconds(10), [this] { return !queue_.empty(); });
      last_status_ = ros::WallTime();
      continue;
    }
    stepAndPublish();
    if (iterations_ > 0 && world_->steps() >= iterations_)
    {
      ROS_INFO("Bullet plant: %llu iterations simulated (~iterations), %.3f s of simulated time; stopping",
               static_cast<unsigned long long>(iterations_), world_->timeNs() * 1e-9);
      break;
    }
    pace();
    publishStatus();
  }
  // Anyone still waiting on the sim thread gets an answer.
  runQueuedWork();
  outbox_->handOver();
}

}  // namespace bullet_plant
