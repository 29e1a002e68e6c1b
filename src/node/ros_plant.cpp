#include "ros_plant.h"

#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>

#include <control_msgs/JointControllerState.h>
#include <controller_manager_msgs/ListControllerTypes.h>
#include <controller_manager_msgs/ListControllers.h>
#include <controller_manager_msgs/LoadController.h>
#include <controller_manager_msgs/ReloadControllerLibraries.h>
#include <controller_manager_msgs/SwitchController.h>
#include <controller_manager_msgs/UnloadController.h>
#include <nav_msgs/Odometry.h>
#include <rosgraph_msgs/Clock.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>
#include <sensor_msgs/JointState.h>
#include <sensor_msgs/PointCloud2.h>
#include <sensor_msgs/LaserScan.h>
#include <std_msgs/Bool.h>
#include <std_msgs/Float64.h>
#include <std_srvs/Empty.h>
#include <tf2_msgs/TFMessage.h>
#include <tianracer_description/DeleteModel.h>
#include <tianracer_description/SpawnModel.h>

namespace bullet_plant
{
namespace cm = controller_manager_msgs;

namespace
{
ros::Time rosTime(int64_t ns)
{
  ros::Time t;
  t.fromNSec(static_cast<uint64_t>(std::max<int64_t>(ns, 0)));
  return t;
}

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

std::string readFile(const std::string& path)
{
  std::ifstream in(path);
  if (!in)
    throw DescriptionError("cannot read world file '" + path + "'");
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}
}  // namespace

// ------------------------------------------------------------------------------------------------
// One robot's ROS side: the controller manager services (gazebo_ros_control), controller topics,
// odometry, sensors and the e-stop.

struct RosPlant::RobotInterface
{
  RosPlant& plant;
  Robot* robot;
  ControllerManager* manager;  // null without a gazebo_ros_control block
  std::string ns;
  ros::NodeHandle nh;
  std::mutex service_mutex;    // the real manager serves one call at a time
  std::vector<ros::ServiceServer> services;
  std::map<std::string, ros::Subscriber> command_subs;
  std::map<std::string, ros::Publisher> state_pubs;
  ros::Publisher joint_states_pub, odom_pub, tf_pub;
  ros::Subscriber estop_sub;
  std::vector<std::pair<std::string, Controller*>> controllers;  // load order, refreshed on changes
  std::vector<std::pair<Lidar*, ros::Publisher>> lidars;
  std::vector<uint64_t> lidar_updates;
  struct CameraTopics
  {
    Camera* camera;
    ros::Publisher image, info, depth, depth_info, points;
    uint64_t updates = 0;
  };
  std::vector<CameraTopics> cameras;
  int64_t odom_period_ns = 20000000, last_odom_ns = -1;

  RobotInterface(RosPlant& p, Robot* r) : plant(p), robot(r), manager(r->controllerManager()), ns(r->controlNamespace()),
                                          nh(r->controlNamespace().empty() ? "/" : r->controlNamespace())
  {
    odom_pub = nh.advertise<nav_msgs::Odometry>("odom", 10);
    tf_pub = plant.nh_.advertise<tf2_msgs::TFMessage>("/tf", 100);
    for (Lidar* lidar : robot->lidars())
    {
      lidars.emplace_back(lidar, nh.advertise<sensor_msgs::LaserScan>(lidar->topic(), 5));
      lidar_updates.push_back(0);
    }
    for (Camera* camera : robot->cameras())
    {
      CameraTopics t;
      t.camera = camera;
      t.image = nh.advertise<sensor_msgs::Image>(camera->topic(), 2);
      t.info = nh.advertise<sensor_msgs::CameraInfo>(camera->cameraInfoTopic(), 2);
      if (camera->depthSensor())
      {
        t.depth = nh.advertise<sensor_msgs::Image>(camera->depthTopic(), 2);
        t.depth_info = nh.advertise<sensor_msgs::CameraInfo>(camera->depthCameraInfoTopic(), 2);
        t.points = nh.advertise<sensor_msgs::PointCloud2>(camera->pointsTopic(), 2);
      }
      cameras.push_back(t);
    }
    const std::string& estop = robot->description().control.e_stop_topic;
    if (!estop.empty())
      estop_sub = nh.subscribe<std_msgs::Bool>(estop, 1, [this](const std_msgs::BoolConstPtr& m) {
        bool on = m->data;
        plant.post([this, on] { robot->setEStop(on); });
      });
    if (manager)
      advertiseManager();
  }

  void advertiseManager()
  {
    services.push_back(nh.advertiseService<cm::LoadController::Request, cm::LoadController::Response>(
        "controller_manager/load_controller", [this](cm::LoadController::Request& req, cm::LoadController::Response& res) {
          std::lock_guard<std::mutex> lock(service_mutex);
          plant.copyParams(ns + "/" + req.name);
          res.ok = plant.onSimThread<bool>([&] {
            bool ok = manager->loadController(req.name);
            refreshControllers();
            return ok;
          });
          return true;
        }));
    services.push_back(nh.advertiseService<cm::UnloadController::Request, cm::UnloadController::Response>(
        "controller_manager/unload_controller", [this](cm::UnloadController::Request& req, cm::UnloadController::Response& res) {
          std::lock_guard<std::mutex> lock(service_mutex);
          res.ok = plant.onSimThread<bool>([&] {
            bool ok = manager->unloadController(req.name);
            refreshControllers();
            return ok;
          });
          return true;
        }));
    services.push_back(nh.advertiseService<cm::SwitchController::Request, cm::SwitchController::Response>(
        "controller_manager/switch_controller", [this](cm::SwitchController::Request& req, cm::SwitchController::Response& res) {
          std::lock_guard<std::mutex> lock(service_mutex);
          res.ok = plant.onSimThread<bool>([&] {
            return manager->switchController(req.start_controllers, req.stop_controllers, req.strictness,
                                             req.start_asap, req.timeout);
          });
          // The switch happens in the control loop (at once while paused): wait for it, as the real
          // service does, but never past the caller's timeout or ROS shutdown.
          ros::WallTime start = ros::WallTime::now();
          while (res.ok && ros::ok() && plant.onSimThread<bool>([&] { return manager->switchPending(); }))
          {
            if (req.timeout > 0 && (ros::WallTime::now() - start).toSec() > req.timeout)
            {
              ROS_ERROR("Timed out while waiting for the controller switch to be applied");
              res.ok = false;
              break;
            }
            ros::WallDuration(0.0005).sleep();
          }
          return true;
        }));
    services.push_back(nh.advertiseService<cm::ListControllers::Request, cm::ListControllers::Response>(
        "controller_manager/list_controllers", [this](cm::ListControllers::Request&, cm::ListControllers::Response& res) {
          std::lock_guard<std::mutex> lock(service_mutex);
          std::vector<ControllerInfo> infos = plant.onSimThread<std::vector<ControllerInfo>>([&] { return manager->listControllers(); });
          for (const ControllerInfo& info : infos)
          {
            cm::ControllerState state;
            state.name = info.name;
            state.state = info.state;
            state.type = info.type;
            for (const ClaimedResources& c : info.claimed_resources)
            {
              cm::HardwareInterfaceResources r;
              r.hardware_interface = c.hardware_interface;
              r.resources = c.resources;
              state.claimed_resources.push_back(r);
            }
            res.controller.push_back(state);
          }
          return true;
        }));
    services.push_back(nh.advertiseService<cm::ListControllerTypes::Request, cm::ListControllerTypes::Response>(
        "controller_manager/list_controller_types", [this](cm::ListControllerTypes::Request&, cm::ListControllerTypes::Response& res) {
          res.types = manager->listControllerTypes();
          res.base_classes.assign(res.types.size(), "controller_interface::ControllerBase");
          return true;
        }));
    services.push_back(nh.advertiseService<cm::ReloadControllerLibraries::Request, cm::ReloadControllerLibraries::Response>(
        "controller_manager/reload_controller_libraries",
        [this](cm::ReloadControllerLibraries::Request& req, cm::ReloadControllerLibraries::Response& res) {
          std::lock_guard<std::mutex> lock(service_mutex);
          res.ok = plant.onSimThread<bool>([&] {
            bool ok = manager->reloadControllerLibraries(req.force_kill);
            refreshControllers();
            return ok;
          });
          return true;
        }));
  }

  // After a load/unload (sim thread): the topics each loaded controller has, as the real ones do.
  void refreshControllers()
  {
    controllers.clear();
    std::map<std::string, ros::Subscriber> subs;
    std::map<std::string, ros::Publisher> pubs;
    bool joint_states = false;
    for (const std::string& name : manager->controllerNames())
    {
      Controller* c = manager->controller(name);
      controllers.emplace_back(name, c);
      if (c->hasCommand())
      {
        auto it = command_subs.find(name);
        subs[name] = it != command_subs.end() ? it->second : subscribeCommand(name);
      }
      if (c->hasState())
      {
        auto pub = state_pubs.find(name);
        pubs[name] = pub != state_pubs.end() ? pub->second
                                             : nh.advertise<control_msgs::JointControllerState>(name + "/state", 1);
      }
      joint_states = joint_states || (c->claimedResources().size() == 1 &&
                                         c->claimedResources()[0].hardware_interface == "hardware_interface::JointStateInterface");
    }
    command_subs.swap(subs);
    state_pubs.swap(pubs);
    if (joint_states && !joint_states_pub)
      joint_states_pub = nh.advertise<sensor_msgs::JointState>("joint_states", 10);
  }

  ros::Subscriber subscribeCommand(const std::string& name)
  {
    return nh.subscribe<std_msgs::Float64>(name + "/command", 1, [this, name](const std_msgs::Float64ConstPtr& m) {
      double value = m->data;
      plant.post([this, name, value] {
        Controller* c = manager->controller(name);
        if (c && !c->setCommand(value))
          ROS_WARN_THROTTLE(1.0, "Rejected a non-finite command (%f) on %s/%s/command", value, ns.c_str(), name.c_str());
      });
    });
  }

  // Sim thread, after each step.
  void publish(int64_t time_ns)
  {
    for (auto& entry : controllers)
    {
      for (const JointStateSample& s : entry.second->takeJointStates())
      {
        sensor_msgs::JointState msg;
        msg.header.stamp = rosTime(s.stamp_ns);
        msg.name = s.name;
        msg.position = s.position;
        msg.velocity = s.velocity;
        msg.effort = s.effort;
        joint_states_pub.publish(msg);
      }
      auto pub = state_pubs.find(entry.first);
      for (const ControllerStateSample& s : entry.second->takeControllerStates())
      {
        if (pub == state_pubs.end())
          continue;
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
        pub->second.publish(msg);
      }
    }
    if (last_odom_ns < 0 || time_ns - last_odom_ns >= odom_period_ns || time_ns < last_odom_ns)
    {
      last_odom_ns = time_ns;
      publishOdometry(time_ns);
    }
    for (size_t i = 0; i < lidars.size(); ++i)
    {
      Lidar* lidar = lidars[i].first;
      if (lidar->updates() == lidar_updates[i])
        continue;
      lidar_updates[i] = lidar->updates();
      const LaserScan& s = lidar->latest();
      sensor_msgs::LaserScan msg;
      msg.header.stamp = rosTime(s.stamp_ns);
      msg.header.frame_id = s.frame_id;
      msg.angle_min = s.angle_min;
      msg.angle_max = s.angle_max;
      msg.angle_increment = s.angle_increment;
      msg.time_increment = s.time_increment;
      msg.scan_time = s.scan_time;
      msg.range_min = s.range_min;
      msg.range_max = s.range_max;
      msg.ranges = s.ranges;
      lidars[i].second.publish(msg);
    }
    publishCameras();
  }

  // Sensors work only while someone listens (checked a few times per simulated second).
  void updateSubscriptions()
  {
    for (auto& entry : lidars)
      setActive(entry.first, entry.second.getNumSubscribers() > 0);
    for (CameraTopics& t : cameras)
    {
      uint32_t listeners = t.image.getNumSubscribers() + t.info.getNumSubscribers();
      if (t.camera->depthSensor())
        listeners += t.depth.getNumSubscribers() + t.depth_info.getNumSubscribers() + t.points.getNumSubscribers();
      setActive(t.camera, listeners > 0);
    }
  }

  void setActive(Sensor* sensor, bool active)
  {
    if (sensor->active() != active)
      ROS_INFO("%s sensor '%s': %s", robot->name().c_str(), sensor->name().c_str(),
               active ? "subscribed, computing" : "no subscribers, idle");
    sensor->setActive(active);
  }

  static sensor_msgs::CameraInfo cameraInfo(const CameraFrame& f, const std_msgs::Header& header)
  {
    sensor_msgs::CameraInfo info;
    info.header = header;
    info.width = f.width;
    info.height = f.height;
    info.distortion_model = "plumb_bob";
    info.D.assign(5, 0.0);
    info.K = {f.fx, 0, f.cx, 0, f.fy, f.cy, 0, 0, 1};
    info.R = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    info.P = {f.fx, 0, f.cx, 0, 0, f.fy, f.cy, 0, 0, 0, 1, 0};
    return info;
  }

  void publishCameras()
  {
    for (CameraTopics& t : cameras)
    {
      if (t.camera->updates() == t.updates)
        continue;
      t.updates = t.camera->updates();
      const CameraFrame& f = t.camera->latest();
      std_msgs::Header header;
      header.stamp = rosTime(f.stamp_ns);
      header.frame_id = f.frame_id;
      sensor_msgs::Image image;
      image.header = header;
      image.width = f.width;
      image.height = f.height;
      image.encoding = "rgb8";
      image.step = f.width * 3;
      image.data = f.rgb;
      t.image.publish(image);
      t.info.publish(cameraInfo(f, header));
      if (!t.camera->depthSensor())
        continue;
      sensor_msgs::Image depth;
      depth.header = header;
      depth.width = f.width;
      depth.height = f.height;
      depth.encoding = "32FC1";
      depth.step = f.width * 4;
      depth.data.resize(f.depth.size() * 4);
      std::memcpy(depth.data.data(), f.depth.data(), depth.data.size());
      t.depth.publish(depth);
      t.depth_info.publish(cameraInfo(f, header));
      if (t.points.getNumSubscribers() == 0)
        continue;
      // x y z float32 and rgb packed in a float32, as gazebo_ros_openni_kinect publishes
      sensor_msgs::PointCloud2 cloud;
      cloud.header = header;
      cloud.width = f.width;
      cloud.height = f.height;
      cloud.is_bigendian = false;
      cloud.is_dense = false;
      cloud.point_step = 16;
      cloud.row_step = cloud.point_step * f.width;
      const char* names[] = {"x", "y", "z", "rgb"};
      for (int i = 0; i < 4; ++i)
      {
        sensor_msgs::PointField field;
        field.name = names[i];
        field.offset = 4 * i;
        field.datatype = sensor_msgs::PointField::FLOAT32;
        field.count = 1;
        cloud.fields.push_back(field);
      }
      cloud.data.resize(size_t(cloud.row_step) * f.height);
      for (size_t p = 0; p < size_t(f.width) * f.height; ++p)
      {
        uint8_t* out = &cloud.data[p * 16];
        std::memcpy(out, &f.points[3 * p], 12);
        uint32_t rgb = (uint32_t(f.rgb[3 * p]) << 16) | (uint32_t(f.rgb[3 * p + 1]) << 8) | f.rgb[3 * p + 2];
        std::memcpy(out + 12, &rgb, 4);
      }
      t.points.publish(cloud);
    }
  }

  void publishOdometry(int64_t time_ns)
  {
    urdf::Pose pose = robot->basePose();
    Twist twist = robot->baseTwist();
    const std::string child = robot->description().model->getRoot()->name;
    nav_msgs::Odometry odom;
    odom.header.stamp = rosTime(time_ns);
    odom.header.frame_id = "odom";
    odom.child_frame_id = child;
    odom.pose.pose.position.x = pose.position.x;
    odom.pose.pose.position.y = pose.position.y;
    odom.pose.pose.position.z = pose.position.z;
    odom.pose.pose.orientation.x = pose.rotation.x;
    odom.pose.pose.orientation.y = pose.rotation.y;
    odom.pose.pose.orientation.z = pose.rotation.z;
    odom.pose.pose.orientation.w = pose.rotation.w;
    // nav_msgs/Odometry's twist is in the child frame.
    urdf::Rotation to_body = pose.rotation.GetInverse();
    urdf::Vector3 v = rotate(to_body, urdf::Vector3(twist.linear[0], twist.linear[1], twist.linear[2]));
    urdf::Vector3 w = rotate(to_body, urdf::Vector3(twist.angular[0], twist.angular[1], twist.angular[2]));
    odom.twist.twist.linear.x = v.x;
    odom.twist.twist.linear.y = v.y;
    odom.twist.twist.linear.z = v.z;
    odom.twist.twist.angular.x = w.x;
    odom.twist.twist.angular.y = w.y;
    odom.twist.twist.angular.z = w.z;
    odom_pub.publish(odom);

    geometry_msgs::TransformStamped tf;
    tf.header = odom.header;
    tf.child_frame_id = child;
    tf.transform.translation.x = pose.position.x;
    tf.transform.translation.y = pose.position.y;
    tf.transform.translation.z = pose.position.z;
    tf.transform.rotation = odom.pose.pose.orientation;
    tf2_msgs::TFMessage msg;
    msg.transforms.push_back(tf);
    tf_pub.publish(msg);
  }
};

// ------------------------------------------------------------------------------------------------

template <class Result>
Result RosPlant::onSimThread(std::function<Result()> work)
{
  auto task = std::make_shared<std::packaged_task<Result()>>(std::move(work));
  std::future<Result> result = task->get_future();
  post([task] { (*task)(); });
  return result.get();
}

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

RosPlant::RosPlant(ros::NodeHandle& nh, ros::NodeHandle& private_nh) : nh_(nh), private_nh_(private_nh)
{
  std::string world_file;
  private_nh_.param<std::string>("world_name", world_file, "");
  WorldDescription description = world_file.empty() ? emptyWorldDescription() : parseWorldDescription(readFile(world_file));
  world_.reset(new World(description));
  world_->log().setSink([](LogLevel level, const std::string& m) {
    switch (level)
    {
      case LogLevel::Debug: ROS_DEBUG_STREAM(m); break;
      case LogLevel::Info: ROS_INFO_STREAM(m); break;
      case LogLevel::Warn: ROS_WARN_STREAM(m); break;
      case LogLevel::Error: ROS_ERROR_STREAM(m); break;
    }
  });
  real_time_factor_ = description.real_time_factor;
  private_nh_.param("real_time_factor", real_time_factor_, real_time_factor_);
  // Every node on simulated time subscribes /clock; at Gazebo's 1 kHz that costs more than the physics.
  double clock_rate = 100.0;
  private_nh_.param("pub_clock_frequency", clock_rate, clock_rate);
  clock_period_ns_ = clock_rate > 0 ? int64_t(std::llround(1e9 / clock_rate)) : 0;
  bool paused = false;
  private_nh_.param("paused", paused, false);
  applyPaused(paused);

  clock_pub_ = nh_.advertise<rosgraph_msgs::Clock>("/clock", 10);
  auto simulator_service = [this](const std::string& name, std::function<void()> action) {
    simulator_services_.push_back(private_nh_.advertiseService<std_srvs::Empty::Request, std_srvs::Empty::Response>(
        name, [this, action](std_srvs::Empty::Request&, std_srvs::Empty::Response&) {
          onSimThread<bool>([&] {
            action();
            return true;
          });
          return true;
        }));
  };
  simulator_service("pause_physics", [this] { applyPaused(true); });
  simulator_service("unpause_physics", [this] { applyPaused(false); });
  simulator_service("reset_simulation", [this] {
    world_->resetSimulation();
    last_clock_ns_ = -1;
    publishClock();
    pace_start_wall_ = ros::WallTime::now();
    pace_start_sim_ns_ = world_->timeNs();
  });
  simulator_service("reset_world", [this] { world_->resetWorld(); });

  simulator_services_.push_back(private_nh_.advertiseService<tianracer_description::SpawnModel::Request,
                                                             tianracer_description::SpawnModel::Response>(
      "spawn_model", [this](tianracer_description::SpawnModel::Request& req, tianracer_description::SpawnModel::Response& res) {
        if (!req.reference_frame.empty() && req.reference_frame != "world" && req.reference_frame != "map")
        {
          res.success = false;
          res.status_message = "reference frame '" + req.reference_frame + "' is not supported; use world";
          return true;
        }
        urdf::Pose pose;
        pose.position = urdf::Vector3(req.initial_pose.position.x, req.initial_pose.position.y, req.initial_pose.position.z);
        pose.rotation = urdf::Rotation(req.initial_pose.orientation.x, req.initial_pose.orientation.y,
                                       req.initial_pose.orientation.z, req.initial_pose.orientation.w);
        std::map<std::string, double> joints;
        for (size_t i = 0; i < req.joint_names.size() && i < req.joint_positions.size(); ++i)
          joints[req.joint_names[i]] = req.joint_positions[i];
        res.success = spawn(req.model_name, req.model_xml, req.robot_namespace, pose, joints, res.status_message);
        return true;
      }));
  simulator_services_.push_back(private_nh_.advertiseService<tianracer_description::DeleteModel::Request,
                                                             tianracer_description::DeleteModel::Response>(
      "delete_model", [this](tianracer_description::DeleteModel::Request& req, tianracer_description::DeleteModel::Response& res) {
        res.success = remove(req.model_name, res.status_message);
        return true;
      }));
  ROS_INFO("Bullet plant ready: world '%s', %.4f s steps, real time factor %g%s", description.name.c_str(),
           world_->timeStep(), real_time_factor_, paused ? " (paused)" : "");
}

RosPlant::~RosPlant()
{
  robots_.clear();
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

bool RosPlant::spawn(const std::string& name, const std::string& urdf, const std::string& ns, const urdf::Pose& pose,
                     const std::map<std::string, double>& joints, std::string& message)
{
  // The robot namespace decides where its pid_gains live: read it before the sim thread spawns.
  std::string control_ns = ns;
  try
  {
    RobotDescription d = parseRobotDescription(urdf);
    if (!d.control.robot_namespace.empty())
      control_ns = d.control.robot_namespace;
  }
  catch (const DescriptionError& e)
  {
    message = e.what();
    ROS_ERROR("Could not spawn '%s': %s", name.c_str(), message.c_str());
    return false;
  }
  copyParams(normaliseNamespace(control_ns) + "/gazebo_ros_control");
  return onSimThread<bool>([&] {
    try
    {
      Robot& robot = world_->spawn(urdf, name, pose, ns, joints);
      robots_[name].reset(new RobotInterface(*this, &robot));
      robots_[name]->updateSubscriptions();
      message = "spawned '" + name + "'" + (robot.controllerManager() ? " with a controller manager in " + robot.controlNamespace() : "");
      ROS_INFO_STREAM(message);
      return true;
    }
    catch (const std::exception& e)
    {
      message = e.what();
      ROS_ERROR("Could not spawn '%s': %s", name.c_str(), message.c_str());
      return false;
    }
  });
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
    return true;
  });
}

void RosPlant::applyPaused(bool paused)
{
  paused_ = paused;
  world_->setPaused(paused);
  pace_start_wall_ = ros::WallTime::now();
  pace_start_sim_ns_ = world_->timeNs();
}

void RosPlant::publishClock()
{
  if (last_clock_ns_ >= 0 && world_->timeNs() - last_clock_ns_ < clock_period_ns_ && world_->timeNs() >= last_clock_ns_)
    return;
  last_clock_ns_ = world_->timeNs();
  rosgraph_msgs::Clock clock;
  clock.clock = rosTime(world_->timeNs());
  clock_pub_.publish(clock);
}

void RosPlant::stepAndPublish()
{
  world_->step();
  const int64_t now = world_->timeNs();
  publishClock();
  const bool check_subscribers = world_->steps() % 100 == 0;
  for (auto& kv : robots_)
  {
    if (check_subscribers)
      kv.second->updateSubscriptions();
    kv.second->publish(now);
  }
}

void RosPlant::pace()
{
  if (real_time_factor_ <= 0)
    return;
  ros::WallTime target = pace_start_wall_ + ros::WallDuration((world_->timeNs() - pace_start_sim_ns_) * 1e-9 / real_time_factor_);
  ros::WallTime now = ros::WallTime::now();
  if (target > now)
    (target - now).sleep();
  else if ((now - target).toSec() > 0.5)
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
    if (paused_)
    {
      std::unique_lock<std::mutex> lock(queue_mutex_);
      queue_cv_.wait_for(lock, std::chrono::milliseconds(10), [this] { return !queue_.empty(); });
      last_status_ = ros::WallTime();
      continue;
    }
    stepAndPublish();
    pace();
    publishStatus();
  }
  // Anyone still waiting on the sim thread gets an answer.
  runQueuedWork();
}

}  // namespace bullet_plant
