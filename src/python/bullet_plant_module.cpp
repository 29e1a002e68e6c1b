// Python bindings of the plant: tianracer_description.bullet_plant. A thin layer: conversions only.
#include <algorithm>
#include <deque>
#include <iostream>
#include <map>
#include <memory>
#include <stdexcept>
#include <mutex>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "bullet_plant/ray_kernels.h"
#include "bullet_plant/world.h"

namespace py = pybind11;
using namespace bullet_plant;

namespace
{
// Deeper than this a parameter tree is a mistake (and its recursion would outgrow the stack).
constexpr size_t kMaxParamDepth = 100;

// `open`: the dicts and lists being converted on the way here, so that one holding itself is an
// error instead of an endless recursion (a crash).
Param toParam(const py::handle& obj, const std::string& where, std::vector<PyObject*>& open)
{
  if (py::isinstance<py::bool_>(obj))
    return Param::boolean(obj.cast<bool>());
  if (py::isinstance<py::int_>(obj))
    return Param::integer(obj.cast<long long>());
  if (py::isinstance<py::float_>(obj))
    return Param::real(obj.cast<double>());
  if (py::isinstance<py::str>(obj))
    return Param::string(obj.cast<std::string>());
  const bool is_dict = py::isinstance<py::dict>(obj);
  if (is_dict || py::isinstance<py::list>(obj) || py::isinstance<py::tuple>(obj))
  {
    if (std::find(open.begin(), open.end(), obj.ptr()) != open.end())
      throw py::value_error("parameter '" + where + "' contains itself (a dict or list holding a reference to "
                            "one of its parents); the parameter tree holds plain trees only");
    if (open.size() >= kMaxParamDepth)
      throw py::value_error("parameter '" + where + "' is nested deeper than " + std::to_string(kMaxParamDepth) +
                            " levels; the parameter tree takes no deeper");
    open.push_back(obj.ptr());
    Param out = Param::map();
    if (is_dict)
      for (auto item : obj.cast<py::dict>())
      {
        std::string key = py::str(item.first);
        out.set(key, toParam(item.second, (where == "/" ? where : where + "/") + key, open));
      }
    else
    {
      std::vector<Param> items;
      for (auto item : obj)
        items.push_back(toParam(item, where, open));
      out = Param::list(items);
    }
    open.pop_back();
    return out;
  }
  if (obj.is_none())
    return Param();
  throw py::type_error("parameter '" + where + "' has a type the parameter tree cannot hold: " +
                       std::string(py::str(obj.get_type())));
}

urdf::Pose poseFromTuple(const std::vector<double>& v)
{
  if (v.size() != 6)
    throw py::value_error("pose must be (x, y, z, roll, pitch, yaw)");
  return poseFromXyzRpy(v[0], v[1], v[2], v[3], v[4], v[5]);
}

py::array_t<double> poseArray(const urdf::Pose& p)
{
  return py::array_t<double>(7, std::vector<double>{p.position.x, p.position.y, p.position.z, p.rotation.x,
                                                    p.rotation.y, p.rotation.z, p.rotation.w}.data());
}

// Raised by a Robot or ControllerManager handle whose robot World.remove took out.
struct RobotRemoved : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

// What Python holds for a robot. The robot may be removed while Python still holds the handle, so
// the handle keeps no pointer of its own: it reads the robot from a cell its world empties on
// World.remove (and when the world goes), and every call through it checks the cell first.
struct RobotRef
{
  std::shared_ptr<Robot*> robot;
  std::string name;

  Robot& get() const
  {
    if (!*robot)
      throw RobotRemoved("robot '" + name + "' was removed from the world (World.remove): this handle and its "
                         "controller manager no longer refer to anything; spawn it again and use the new handle");
    return **robot;
  }
};

// The controller manager of a robot, reached through the robot's handle on every call.
struct ManagerRef
{
  RobotRef robot;
  ControllerManager& get() const;
};

// Binds f(Target&, args...) as a method of the handle type Ref: each call resolves the handle first.
template <typename Ref, typename F, typename Ret, typename Target, typename... Args>
auto throughHandle(F f, Ret (F::*)(Target&, Args...) const)
{
  return [f](const Ref& ref, Args... args) -> Ret { return f(ref.get(), std::forward<Args>(args)...); };
}
template <typename F>
auto onRobot(F f)
{
  return throughHandle<RobotRef>(f, &F::operator());
}
template <typename F>
auto onManager(F f)
{
  return throughHandle<ManagerRef>(f, &F::operator());
}

// A World plus the messages its log produced, kept for Python to read.
struct PyWorld
{
  explicit PyWorld(const WorldDescription& d) : world(new World(d))
  {
    world->log().setSink([this](LogLevel level, const std::string& m) {
      std::lock_guard<std::mutex> lock(mutex);
      messages.emplace_back(levelName(level), m);
      if (messages.size() > 10000)
        messages.pop_front();
      if (echo && level >= LogLevel::Warn)
        std::cerr << "[" << levelName(level) << "] " << m << std::endl;
    });
    // The world logged its description's warnings while it was built, before this sink existed.
    for (const std::string& warning : d.warnings)
      messages.emplace_back(levelName(LogLevel::Warn), "world: " + warning);
  }
  ~PyWorld()
  {
    for (auto& entry : handle_cells)
      *entry.second = nullptr;
  }

  RobotRef handleTo(Robot& r)
  {
    std::shared_ptr<Robot*>& cell = handle_cells[r.name()];
    if (!cell)
      cell = std::make_shared<Robot*>(&r);
    return RobotRef{cell, r.name()};
  }
  bool remove(const std::string& name)
  {
    auto it = handle_cells.find(name);
    if (it != handle_cells.end())
    {
      *it->second = nullptr;
      handle_cells.erase(it);
    }
    return world->remove(name);
  }

  std::unique_ptr<World> world;
  std::map<std::string, std::shared_ptr<Robot*>> handle_cells;  // robot name -> what its handles read
  std::mutex mutex;
  std::deque<std::pair<std::string, std::string>> messages;
  bool echo = true;
};

JointHandle& handleOf(Robot& r, const std::string& joint)
{
  JointHandle* h = r.handle(joint);
  if (!h)
    throw py::key_error("robot '" + r.name() + "' has no joint handle '" + joint +
                        "' (joints with a <transmission>: see Robot.handles)");
  return *h;
}

ControllerManager& managerOf(Robot& r)
{
  ControllerManager* cm = r.controllerManager();
  if (!cm)
    throw py::value_error("robot '" + r.name() + "' has no gazebo_ros_control plugin block, so no controller manager");
  return *cm;
}

ControllerManager& ManagerRef::get() const
{
  return managerOf(robot.get());
}

Controller& controllerOf(ControllerManager& cm, const std::string& name)
{
  Controller* c = cm.controller(name);
  if (!c)
    throw py::key_error("no controller named '" + name + "' is loaded");
  return *c;
}

py::dict jointStateDict(const JointStateSample& s)
{
  py::dict d;
  d["stamp"] = s.stamp_ns * 1e-9;
  d["name"] = s.name;
  d["position"] = s.position;
  d["velocity"] = s.velocity;
  d["effort"] = s.effort;
  return d;
}

py::dict controllerStateDict(const ControllerStateSample& s)
{
  py::dict d;
  d["stamp"] = s.stamp_ns * 1e-9;
  d["set_point"] = s.set_point;
  d["process_value"] = s.process_value;
  d["process_value_dot"] = s.process_value_dot;
  d["error"] = s.error;
  d["time_step"] = s.time_step;
  d["command"] = s.command;
  d["p"] = s.p;
  d["i"] = s.i;
  d["d"] = s.d;
  d["i_clamp"] = s.i_clamp;
  d["antiwindup"] = s.antiwindup;
  return d;
}

Sensor& sensorOf(Robot& r, const std::string& name)
{
  Sensor* s = r.sensor(name);
  if (!s)
    throw py::key_error("robot '" + r.name() + "' has no simulated sensor '" + name + "'");
  return *s;
}
}  // namespace

PYBIND11_MODULE(bullet_plant, m)
{
  m.doc() = "The Bullet plant that stands in for Gazebo + gazebo_ros_control, driven from Python.";

  py::register_exception<DescriptionError>(m, "DescriptionError", PyExc_ValueError);

  m.def("embree_isas", &embreeIsasThisCpuRuns,
        "the instruction sets of Embree's kernels this CPU runs, narrowest first: the values "
        "TIANRACER_EMBREE_ISA takes");
  m.def("embree_isa", [] {
    const EmbreeIsa isa = embreeIsa();
    return py::dict(py::arg("name") = isa.name, py::arg("forced") = isa.forced, py::arg("problem") = isa.problem);
  }, "the ISA of the kernels a world made now casts its sensors' rays with: {name, forced, problem}");
  py::register_exception<RobotRemoved>(m, "RobotRemovedError", PyExc_RuntimeError);

  py::class_<RobotRef>(m, "Robot")
      .def_property_readonly("name", [](const RobotRef& ref) { return ref.name; }, "still readable after the robot was removed")
      .def_property_readonly("removed", [](const RobotRef& ref) { return *ref.robot == nullptr; }, "whether World.remove took the robot out (every other use then raises RobotRemovedError)")
      .def_property_readonly("namespace", onRobot([](Robot& r) { return r.controlNamespace(); }), "gazebo_ros_control's robot namespace")
      .def_property_readonly("handles", onRobot([](Robot& r) {
        std::vector<std::string> names;
        for (JointHandle& h : r.handles())
          names.push_back(h.name());
        return names;
      }), "joints with a transmission, in transmission order")
      .def("interface", onRobot([](Robot& r, const std::string& joint) { return std::string(interfaceName(handleOf(r, joint).interface())); }))
      .def("has_pid", onRobot([](Robot& r, const std::string& joint) { return handleOf(r, joint).pid() != nullptr; }),
           "whether the joint is driven by its gazebo_ros_control/pid_gains loop")
      .def("set_command", onRobot([](Robot& r, const std::string& joint, double value) { return handleOf(r, joint).setCommand(value); }),
           py::arg("joint"), py::arg("value"),
           "command in the joint interface's unit; a non-finite value is rejected (returns False, counted)")
      .def("set_effort_law", onRobot([](Robot& r, const std::string& joint, double feedforward, double stiffness,
                                double position_target, double damping, double velocity_target) {
        JointHandle& h = handleOf(r, joint);
        if (h.interface() != JointInterface::Effort)
          throw py::value_error("joint '" + joint + "' is not an effort joint");
        EffortLaw law;
        law.feedforward = feedforward;
        law.stiffness = stiffness;
        law.position_target = position_target;
        law.damping = damping;
        law.velocity_target = velocity_target;
        h.setEffortLaw(law);
      }), py::arg("joint"), py::arg("feedforward") = 0.0, py::arg("stiffness") = 0.0, py::arg("position_target") = 0.0,
         py::arg("damping") = 0.0, py::arg("velocity_target") = 0.0,
         "effort = feedforward + stiffness*(position_target - q) + damping*(velocity_target - qd), evaluated at the "
         "end of each step (what the PID controllers use); set_command replaces it")
      .def("command", onRobot([](Robot& r, const std::string& joint) { return handleOf(r, joint).command(); }))
      .def("rejected_commands", onRobot([](Robot& r, const std::string& joint) { return handleOf(r, joint).rejectedCommands(); }))
      .def("limits", onRobot([](Robot& r, const std::string& joint) {
        const JointLimits& l = handleOf(r, joint).limits();
        py::dict d;
        d["effort"] = l.effort;
        d["velocity"] = l.velocity;
        if (l.has_position)
        {
          d["lower"] = l.lower;
          d["upper"] = l.upper;
        }
        return d;
      }))
      .def_property_readonly("joint_names", onRobot([](Robot& r) { return r.jointNames(); }), "every movable joint of the URDF")
      .def("joint_state", onRobot([](Robot& r, const std::string& joint) {
        double p, v, e;
        if (!r.jointState(joint, p, v, e))
          throw py::key_error("robot '" + r.name() + "' has no movable joint '" + joint + "'");
        return py::make_tuple(p, v, e);
      }), "(position, velocity, effort) of a movable joint")
      .def("base_pose", onRobot([](Robot& r) { return poseArray(r.basePose()); }),
           "root link pose in the world: x y z qx qy qz qw")
      .def("base_twist", onRobot([](Robot& r) {
        Twist t = r.baseTwist();
        return py::make_tuple(py::array_t<double>(3, t.linear.data()), py::array_t<double>(3, t.angular.data()));
      }), "(linear, angular) velocity of the root link origin, world frame")
      .def("link_pose", onRobot([](Robot& r, const std::string& link) {
        try
        {
          return poseArray(r.linkPose(link));
        }
        catch (const std::out_of_range& e)
        {
          throw py::key_error(e.what());
        }
      }))
      .def_property("e_stop", onRobot([](Robot& r) { return r.eStop(); }), onRobot([](Robot& r, bool on) { r.setEStop(on); }))
      .def_property_readonly("recoveries", onRobot([](Robot& r) { return r.recoveries(); }))
      .def_property_readonly("disabled", onRobot([](Robot& r) { return r.disabled(); }), "taken out of the physics after diverging step after step")
      .def_property_readonly("controller_manager", py::cpp_function([](const RobotRef& ref) {
        managerOf(ref.get());  // a robot without one says so here, not at first use
        return ManagerRef{ref};
      }, py::keep_alive<0, 1>()))
      .def_property_readonly("control_period", onRobot([](Robot& r) { return r.controlPeriod(); }))
      .def_property_readonly("sensors", onRobot([](Robot& r) {
        std::vector<std::string> names;
        for (Sensor* s : r.sensors())
          names.push_back(s->name());
        return names;
      }), "the simulated sensors of the URDF's <gazebo reference> blocks")
      .def("enable_sensor", onRobot([](Robot& r, const std::string& name, bool on) { sensorOf(r, name).setActive(on); }),
           py::arg("name"), py::arg("on") = true, "sensors work only while enabled (subscribed, in ROS)")
      .def("sensor_updates", onRobot([](Robot& r, const std::string& name) { return sensorOf(r, name).updates(); }))
      .def("sensor_topic", onRobot([](Robot& r, const std::string& name) { return sensorOf(r, name).topic(); }))
      .def("sensor_namespace", onRobot([](Robot& r, const std::string& name) { return sensorOf(r, name).rosNamespace(); }),
           "the namespace the sensor's gazebo_ros plugin publishes in")
      .def("sensor_frame", onRobot([](Robot& r, const std::string& name) { return sensorOf(r, name).frameId(); }),
           "the frame id the sensor's plugin publishes (tf_prefix resolved)")
      .def("imu", onRobot([](Robot& r, const std::string& name) -> py::object {
        auto* imu = dynamic_cast<Imu*>(&sensorOf(r, name));
        if (!imu)
          throw py::key_error("sensor '" + name + "' is not an IMU");
        if (!imu->hasReading())
          return py::none();
        const ImuReading& m = imu->latest();
        py::dict d;
        d["stamp"] = m.stamp_ns * 1e-9;
        d["frame_id"] = m.frame_id;
        d["orientation"] = std::vector<double>{m.orientation.x, m.orientation.y, m.orientation.z, m.orientation.w};
        d["angular_velocity"] = std::vector<double>{m.angular_velocity.x, m.angular_velocity.y, m.angular_velocity.z};
        d["linear_acceleration"] =
            std::vector<double>{m.linear_acceleration.x, m.linear_acceleration.y, m.linear_acceleration.z};
        return std::move(d);
      }), "the latest sensor_msgs/Imu fields (x y z w; IMU frame), or None before the first")
      .def("ground_truth", onRobot([](Robot& r, const std::string& name) -> py::object {
        auto* odometry = dynamic_cast<GroundTruthOdometry*>(&sensorOf(r, name));
        if (!odometry)
          throw py::key_error("sensor '" + name + "' is not a gazebo_ros_p3d plugin");
        if (!odometry->hasReading())
          return py::none();
        const GroundTruthReading& m = odometry->latest();
        py::dict d;
        d["stamp"] = m.stamp_ns * 1e-9;
        d["frame_id"] = m.frame_id;
        d["child_frame_id"] = m.child_frame_id;
        d["position"] = std::vector<double>{m.pose.position.x, m.pose.position.y, m.pose.position.z};
        d["orientation"] = std::vector<double>{m.pose.rotation.x, m.pose.rotation.y, m.pose.rotation.z, m.pose.rotation.w};
        d["linear"] = std::vector<double>{m.linear.x, m.linear.y, m.linear.z};
        d["angular"] = std::vector<double>{m.angular.x, m.angular.y, m.angular.z};
        return std::move(d);
      }), "the latest nav_msgs/Odometry fields of a gazebo_ros_p3d plugin, or None before the first")
      .def("scan", onRobot([](Robot& r, const std::string& name) -> py::object {
        auto* lidar = dynamic_cast<Lidar*>(&sensorOf(r, name));
        if (!lidar)
          throw py::key_error("sensor '" + name + "' is not a lidar");
        if (!lidar->hasScan())
          return py::none();
        const LaserScan& s = lidar->latest();
        py::dict d;
        d["stamp"] = s.stamp_ns * 1e-9;
        d["frame_id"] = s.frame_id;
        d["angle_min"] = s.angle_min;
        d["angle_max"] = s.angle_max;
        d["angle_increment"] = s.angle_increment;
        d["time_increment"] = s.time_increment;
        d["scan_time"] = s.scan_time;
        d["range_min"] = s.range_min;
        d["range_max"] = s.range_max;
        d["ranges"] = py::array_t<float>(s.ranges.size(), s.ranges.data());
        return std::move(d);
      }), "the latest scan as a dict of sensor_msgs/LaserScan's fields, or None before the first")
      .def("image", onRobot([](Robot& r, const std::string& name) -> py::object {
        auto* camera = dynamic_cast<Camera*>(&sensorOf(r, name));
        if (!camera)
          throw py::key_error("sensor '" + name + "' is not a camera");
        if (!camera->hasFrame())
          return py::none();
        const CameraFrame& f = camera->latest();
        py::dict d;
        d["stamp"] = f.stamp_ns * 1e-9;
        d["frame_id"] = f.frame_id;
        d["width"] = f.width;
        d["height"] = f.height;
        d["K"] = std::vector<double>{f.fx, 0, f.cx, 0, f.fy, f.cy, 0, 0, 1};
        d["rgb"] = py::array_t<uint8_t>({f.height, f.width, 3}, f.rgb.data());
        if (camera->depthSensor())
        {
          d["depth"] = py::array_t<float>({f.height, f.width}, f.depth.data());
          d["points"] = py::array_t<float>({f.height, f.width, 3}, f.points.data());
        }
        return std::move(d);
      }), "the latest camera frame: rgb (H x W x 3 uint8), for depth cameras depth (H x W, m, NaN: no hit) and "
         "points (H x W x 3, optical frame); K the pinhole matrix; None before the first");

  py::class_<Pid>(m, "Pid", "control_toolbox::Pid, as the plant's controllers and pid_gains loops use it")
      .def(py::init([](double p, double i, double d, double i_clamp, bool antiwindup) {
        return Pid(PidGains::withIClamp(p, i, d, i_clamp, antiwindup));
      }), py::arg("p"), py::arg("i") = 0.0, py::arg("d") = 0.0, py::arg("i_clamp") = 0.0, py::arg("antiwindup") = false)
      .def_static("from_params", [](PyWorld& w, const std::string& ns) {
        try
        {
          return Pid(readPidGains(w.world->params(), ns));
        }
        catch (const std::runtime_error& e)
        {
          throw py::value_error(e.what());
        }
      }, py::arg("world"), py::arg("namespace"), "gains from p, i, d, i_clamp, i_clamp_min/max, antiwindup under namespace")
      .def("compute_command", py::overload_cast<double, double>(&Pid::computeCommand), py::arg("error"), py::arg("dt"))
      .def("compute_command", py::overload_cast<double, double, double>(&Pid::computeCommand), py::arg("error"),
           py::arg("error_dot"), py::arg("dt"))
      .def("reset", &Pid::reset)
      .def_property_readonly("gains", [](Pid& pid) {
        const PidGains& g = pid.gains();
        py::dict d;
        d["p"] = g.p;
        d["i"] = g.i;
        d["d"] = g.d;
        d["i_max"] = g.i_max;
        d["i_min"] = g.i_min;
        d["antiwindup"] = g.antiwindup;
        return d;
      })
      .def_property_readonly("i_error", &Pid::iError)
      .def_property_readonly("command", &Pid::command);

  py::class_<ManagerRef>(m, "ControllerManager",
      "controller_manager's services for one robot (its namespace: .ns); errors go to World.messages()")
      .def_property_readonly("ns", onManager([](ControllerManager& cm) { return cm.ns(); }))
      .def("load", onManager([](ControllerManager& cm, const std::string& name) { return cm.loadController(name); }), py::arg("name"))
      .def("unload", onManager([](ControllerManager& cm, const std::string& name) { return cm.unloadController(name); }), py::arg("name"))
      .def("switch", onManager([](ControllerManager& cm, const std::vector<std::string>& start, const std::vector<std::string>& stop,
                                   int strictness, bool start_asap, double timeout) {
        return cm.switchController(start, stop, strictness, start_asap, timeout);
      }), py::arg("start") = std::vector<std::string>(),
           py::arg("stop") = std::vector<std::string>(), py::arg("strictness") = int(ControllerManager::STRICT),
           py::arg("start_asap") = false, py::arg("timeout") = 0.0,
           "validated at once; applied after the next control update's controller updates, or at once while paused")
      .def("list", onManager([](ControllerManager& cm) {
        py::list out;
        for (const ControllerInfo& info : cm.listControllers())
        {
          py::dict d;
          d["name"] = info.name;
          d["state"] = controllerStateName(info.state);
          d["type"] = info.type;
          py::list claimed;
          for (const ClaimedResources& c : info.claimed_resources)
          {
            py::dict r;
            r["hardware_interface"] = c.hardware_interface;
            r["resources"] = c.resources;
            claimed.append(r);
          }
          d["claimed_resources"] = claimed;
          out.append(d);
        }
        return out;
      }))
      .def("list_types", onManager([](ControllerManager& cm) {
        std::vector<std::string> types = cm.listControllerTypes();
        return py::make_tuple(types, std::vector<std::string>(types.size(), "controller_interface::ControllerBase"));
      }), "(types, base_classes)")
      .def("reload_libraries", onManager([](ControllerManager& cm, bool force_kill) { return cm.reloadControllerLibraries(force_kill); }),
           py::arg("force_kill") = false)
      .def("spawn", onManager([](ControllerManager& cm, const std::vector<std::string>& names) {
        std::vector<std::string> loaded;
        for (const std::string& n : names)
          if (cm.loadController(n))
            loaded.push_back(n);
        bool started = cm.switchController(loaded, {}, ControllerManager::STRICT);
        return py::make_tuple(loaded, started);
      }), py::arg("names"), "what the spawner does: load each, then one STRICT switch starting all loaded; (loaded, ok)")
      .def("command", onManager([](ControllerManager& cm, const std::string& name, py::object value) {
        Controller& c = controllerOf(cm, name);
        switch (c.commandTopic())
        {
          case CommandTopic::Float64: return c.setCommand(value.cast<double>());
          case CommandTopic::Float64MultiArray: return c.setCommands(value.cast<std::vector<double>>());
          case CommandTopic::Twist:
          {
            auto twist = value.cast<std::pair<double, double>>();
            return c.setTwist(twist.first, twist.second);
          }
          default: throw py::key_error("controller '" + name + "' takes no command");
        }
      }), py::arg("name"), py::arg("value"),
           "what a Float64 (a number) or a Float64MultiArray (a list: the JointGroup controllers) on "
           "<controller>/command does, or a Twist (linear.x, angular.z) on <controller>/cmd_vel; False for a "
           "rejected command")
      .def("odometry", onManager([](ControllerManager& cm, const std::string& name) -> py::object {
        const OdometrySample* s = controllerOf(cm, name).latestOdometry();
        if (!s)
          return py::none();
        py::dict d;
        d["stamp"] = double(s->stamp_ns) * 1e-9;
        d["x"] = s->x;
        d["y"] = s->y;
        d["heading"] = s->heading;
        d["linear"] = s->linear;
        d["angular"] = s->angular;
        return d;
      }), py::arg("name"), "the latest nav_msgs/Odometry a drive controller produced: stamp, x, y, heading, linear, angular")
      .def("joint_states", onManager([](ControllerManager& cm, const std::string& name) -> py::object {
        const JointStateSample* s = controllerOf(cm, name).latestJointState();
        return s ? py::object(jointStateDict(*s)) : py::none();
      }), py::arg("name") = "joint_state_controller", "the latest sensor_msgs/JointState a joint state controller produced")
      .def("state", onManager([](ControllerManager& cm, const std::string& name) -> py::object {
        const ControllerStateSample* s = controllerOf(cm, name).latestControllerState();
        return s ? py::object(controllerStateDict(*s)) : py::none();
      }), py::arg("name"), "the latest control_msgs/JointControllerState of a PID controller")
      .def("samples", onManager([](ControllerManager& cm, const std::string& name) { return controllerOf(cm, name).samplesProduced(); }),
           py::arg("name"), "how many messages the controller has produced");

  py::class_<PyWorld>(m, "World")
      .def(py::init([]() { return new PyWorld(emptyWorldDescription()); }), "an empty world with a ground plane")
      .def_static("from_sdf", [](const std::string& sdf) { return new PyWorld(parseWorldDescription(sdf)); },
                  py::arg("sdf"), "a world from SDF text (relative URIs: relative to the working directory)")
      .def_static("from_file", [](const std::string& path) { return new PyWorld(parseWorldFile(path)); },
                  py::arg("path"), "a world from an SDF file; its relative URIs resolve against the file's directory")
      .def_property_readonly("file", [](PyWorld& w) { return w.world->description().file; },
                             "the world file ('' for a world from text)")
      .def("static_collisions", [](PyWorld& w) {
        static const char* kind_names[] = {"box", "cylinder", "sphere", "plane", "mesh"};
        py::list out;
        for (const StaticCollision& c : w.world->description().collisions)
        {
          py::dict d;
          d["name"] = c.name;
          d["kind"] = kind_names[static_cast<int>(c.shape.kind)];
          d["pose"] = poseArray(c.pose);
          d["mesh_uri"] = c.shape.mesh_uri;
          d["mesh_file"] = c.shape.mesh_file;
          d["scale"] = std::vector<double>{c.shape.scale.x, c.shape.scale.y, c.shape.scale.z};
          d["mu"] = c.mu;
          out.append(d);
        }
        return out;
      }, "the world's static collisions as described: name (model::link::collision), kind, pose (x y z qx qy qz qw), "
         "mesh_uri and mesh_file (as written, as resolved), scale, mu")
      .def_property("echo", [](PyWorld& w) { return w.echo; }, [](PyWorld& w, bool on) { w.echo = on; },
                    "print warnings and errors to stderr as they happen (default True)")
      .def("messages", [](PyWorld& w, bool clear) {
        std::lock_guard<std::mutex> lock(w.mutex);
        std::vector<std::pair<std::string, std::string>> out(w.messages.begin(), w.messages.end());
        if (clear)
          w.messages.clear();
        return out;
      }, py::arg("clear") = false, "(level, text) of what the plant logged")
      .def("load_params", [](PyWorld& w, py::object tree, const std::string& ns) {
        if (py::isinstance<py::str>(tree))
        {
          py::object yaml = py::module_::import("yaml");
          py::object file = py::module_::import("builtins").attr("open")(tree);
          tree = yaml.attr("safe_load")(file);
          file.attr("close")();
        }
        if (!py::isinstance<py::dict>(tree))
          throw py::type_error("load_params takes a dict or the path of a YAML file holding one");
        std::vector<PyObject*> open;
        w.world->params().set(ns, toParam(tree, ns, open));
      }, py::arg("tree"), py::arg("namespace") = "/",
         "merge a dict or YAML file into the parameter tree under namespace, as `rosparam load`: its top "
         "key (e.g. tianracer) is the robot namespace the controller manager reads")
      .def_property("paused", [](PyWorld& w) { return w.world->paused(); },
                    [](PyWorld& w, bool p) { w.world->setPaused(p); },
                    "while paused, controller switches apply at once (step() still steps)")
      .def("get_param", [](PyWorld& w, const std::string& path) -> py::object {
        const Param* p = w.world->params().find(path);
        if (!p)
          return py::none();
        switch (p->type())
        {
          case Param::Type::Bool: return py::bool_(p->asBool());
          case Param::Type::Int: return py::int_(p->asInt());
          case Param::Type::Double: return py::float_(p->asDouble());
          case Param::Type::String: return py::str(p->asString());
          default: return py::str(p->describe());
        }
      })
      .def_property_readonly("time_step", [](PyWorld& w) { return w.world->timeStep(); })
      .def_property_readonly("real_time_factor", [](PyWorld& w) { return w.world->description().real_time_factor; })
      .def_property_readonly("time", [](PyWorld& w) { return w.world->time(); })
      .def_property_readonly("steps", [](PyWorld& w) { return w.world->steps(); })
      .def("spawn", [](PyWorld& w, const std::string& urdf, const std::string& name, std::vector<double> pose,
                       const std::string& ns, std::map<std::string, double> joints) {
        return w.handleTo(w.world->spawn(urdf, name, poseFromTuple(pose), ns, joints));
      }, py::arg("urdf"), py::arg("name"), py::arg("pose") = std::vector<double>(6, 0.0), py::arg("namespace") = "",
         py::arg("joints") = std::map<std::string, double>(), py::keep_alive<0, 1>(),
         "add a robot from URDF text; raises DescriptionError naming what is wrong")
      .def("remove", [](PyWorld& w, const std::string& name) { return w.remove(name); }, py::arg("name"),
           "take a robot out; its handles then raise RobotRemovedError")
      .def("robot", [](PyWorld& w, const std::string& name) {
        Robot* r = w.world->robot(name);
        if (!r)
          throw py::key_error("no robot named '" + name + "'");
        return w.handleTo(*r);
      }, py::keep_alive<0, 1>())
      .def_property_readonly("robots", [](PyWorld& w) {
        std::vector<std::string> names;
        for (Robot* r : w.world->robots())
          names.push_back(r->name());
        return names;
      })
      .def("step", [](PyWorld& w, py::object count) {
        // bool is a subclass of int in Python; step(True) is a mistake, not one step.
        if (py::isinstance<py::bool_>(count) || !py::isinstance<py::int_>(count))
          throw py::type_error("step(n): n must be an int, not " + std::string(py::str(count.get_type())));
        long long n = count.cast<long long>();
        if (n < 0)
          throw py::value_error("step(n): n must not be negative, got " + std::to_string(n));
        // In chunks, so that Ctrl-C (checked between chunks, with the GIL held) stops a long run.
        const long long chunk = 1000;
        while (n > 0)
        {
          const int now = static_cast<int>(std::min(n, chunk));
          {
            py::gil_scoped_release release;
            w.world->step(now);
          }
          n -= now;
          if (PyErr_CheckSignals() != 0)
            throw py::error_already_set();
        }
      }, py::arg("n") = 1, "advance n fixed physics steps; Ctrl-C interrupts between chunks of 1000")
      .def("reset_simulation", [](PyWorld& w) { w.world->resetSimulation(); })
      .def("reset_world", [](PyWorld& w) { w.world->resetWorld(); })
      .def("cast_ray", [](PyWorld& w, std::vector<double> origin, std::vector<double> direction, double max_range) {
        if (origin.size() != 3 || direction.size() != 3)
          throw py::value_error("origin and direction are 3-vectors");
        return w.world->castRay(urdf::Vector3(origin[0], origin[1], origin[2]),
                                urdf::Vector3(direction[0], direction[1], direction[2]), max_range, nullptr);
      });
}
