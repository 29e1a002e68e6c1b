// bullet_plant.ControllerManager and bullet_plant.Pid: controller_manager's services and
// control_toolbox's Pid, driven from Python.
#include "bindings.h"

#include "bullet_plant/action_messages.h"

namespace bullet_plant
{
namespace python
{
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

Port& commandPortOf(Controller& c, const std::string& name)
{
  for (const std::unique_ptr<Port>& port : c.ports())
    if (port->direction() == Port::Direction::In)
      return *port;
  throw py::key_error("controller '" + name + "' takes no command");
}

namespace
{

// The latest message the controller published of this type as a dict, None before the first or
// for a controller without such a port.
template <class Msg>
py::object latestOf(const Controller& c)
{
  const OutputPort<Msg>* port = c.output<Msg>();
  return port ? latestOfPort(*port) : py::none();
}
// The controller's port <action>/<part> (an action's goal, cancel, result or feedback).
Port& actionPort(const Controller& c, const std::string& action, const std::string& part, Port::Direction direction)
{
  if (Port* p = c.port(action + "/" + part, direction))
    return *p;
  throw py::key_error("this controller serves no action '" + action + "'");
}
}  // namespace

void init_controller_manager(py::module_& m)
{
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
        return deliverToPort(commandPortOf(controllerOf(cm, name), name), value);
      }), py::arg("name"), py::arg("value"),
           "what a Float64 (a number) or a Float64MultiArray (a list: the JointGroup controllers) on "
           "<controller>/command does, or a Twist (linear.x, angular.z) on <controller>/cmd_vel; False for a "
           "rejected command")
      .def("odometry", onManager([](ControllerManager& cm, const std::string& name) {
        return latestOf<OdometrySample>(controllerOf(cm, name));
      }), py::arg("name"), "the latest nav_msgs/Odometry a drive controller produced: stamp, x, y, heading, linear, angular")
      .def("joint_states", onManager([](ControllerManager& cm, const std::string& name) {
        return latestOf<JointStateSample>(controllerOf(cm, name));
      }), py::arg("name") = "joint_state_controller", "the latest sensor_msgs/JointState a joint state controller produced")
      .def("state", onManager([](ControllerManager& cm, const std::string& name) {
        const Controller& c = controllerOf(cm, name);
        return c.output<TrajectoryStateSample>() ? latestOf<TrajectoryStateSample>(c) : latestOf<ControllerStateSample>(c);
      }), py::arg("name"),
           "the latest control_msgs/JointControllerState of a PID controller, or JointTrajectoryControllerState "
           "(joint_names, desired, actual, error) of a trajectory controller")
      .def("send_goal", onManager([](ControllerManager& cm, const std::string& name, const std::string& goal_id,
                                     py::dict goal, const std::string& action) {
        goal["goal_id"] = goal_id;
        return deliverToPort(actionPort(controllerOf(cm, name), action, "goal", Port::Direction::In), goal);
      }), py::arg("name"), py::arg("goal_id"), py::arg("goal"), py::arg("action") = "follow_joint_trajectory",
           "what a goal on <controller>/<action> does (FollowJointTrajectory: {'trajectory': {'joint_names', "
           "'points': [{'positions', 'velocities', 'accelerations', 'time_from_start'}], 'stamp'}, "
           "'path_tolerance', 'goal_tolerance', 'goal_time_tolerance'}); True when accepted, else goal_result says why")
      .def("cancel_goal", onManager([](ControllerManager& cm, const std::string& name, const std::string& goal_id,
                                       const std::string& action) {
        return deliverToPort(actionPort(controllerOf(cm, name), action, "cancel", Port::Direction::In), py::str(goal_id));
      }), py::arg("name"), py::arg("goal_id"), py::arg("action") = "follow_joint_trajectory")
      .def("goal_result", onManager([](ControllerManager& cm, const std::string& name, const std::string& action) {
        return latestOfPort(actionPort(controllerOf(cm, name), action, "result", Port::Direction::Out));
      }), py::arg("name"), py::arg("action") = "follow_joint_trajectory",
           "how the last goal that ended ended: goal_id, outcome (rejected, succeeded, aborted, canceled), "
           "error_code, error_string; None before any")
      .def("goal_feedback", onManager([](ControllerManager& cm, const std::string& name, const std::string& action) {
        return latestOfPort(actionPort(controllerOf(cm, name), action, "feedback", Port::Direction::Out));
      }), py::arg("name"), py::arg("action") = "follow_joint_trajectory",
           "the latest feedback of the goal in force (FollowJointTrajectory: goal_id, desired, actual, error)")
      .def("query_state", onManager([](ControllerManager& cm, const std::string& name, double time) -> py::object {
        auto* port = dynamic_cast<ServicePort<QueryTrajectoryStateRequest, QueryTrajectoryStateResponse>*>(
            controllerOf(cm, name).port("query_state", Port::Direction::Service));
        if (!port)
          throw py::key_error("controller '" + name + "' serves no query_state (JointTrajectoryController does)");
        QueryTrajectoryStateResponse r;
        if (!port->call(QueryTrajectoryStateRequest{int64_t(std::llround(time * 1e9))}, r))
          return py::none();
        py::dict d;
        d["name"] = r.name;
        d["position"] = r.position;
        d["velocity"] = r.velocity;
        d["acceleration"] = r.acceleration;
        return d;
      }), py::arg("name"), py::arg("time"),
           "what <controller>/query_state (control_msgs/QueryTrajectoryState) answers: the trajectory sampled "
           "at `time` (s of sim time) as a dict of name, position, velocity, acceleration; None where the "
           "service fails (the controller not running, a time before the trajectory)")
      .def("samples", onManager([](ControllerManager& cm, const std::string& name) { return controllerOf(cm, name).messagesPublished(); }),
           py::arg("name"), "how many messages the controller has produced");
}

}  // namespace python
}  // namespace bullet_plant
