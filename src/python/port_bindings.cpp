// Ports from Python (bullet_plant/message_ports.h): what a controller's or a model plugin's topics
// carry, as Python values. The one place a port's message type meets Python.
#include "bindings.h"

#include <cmath>

#include "bullet_plant/geometry.h"
#include "bullet_plant/model_plugin.h"
#include "bullet_plant/messages.h"
#include "bullet_plant/action_messages.h"

namespace bullet_plant
{
namespace python
{
namespace
{
py::dict jointStateDict(const JointStateSample& s)
{
  py::dict d = stampedDict(s.stamp_ns);
  d["name"] = s.name;
  d["position"] = s.position;
  d["velocity"] = s.velocity;
  d["effort"] = s.effort;
  return d;
}

py::dict controllerStateDict(const ControllerStateSample& s)
{
  py::dict d = stampedDict(s.stamp_ns);
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

// The planar reading drives are used by (x, y, heading, linear.x, angular.z) and the full pose and twist.
py::dict odometryDict(const OdometrySample& s)
{
  py::dict d = stampedDict(s.stamp_ns, s.frame_id);
  d["child_frame_id"] = s.child_frame_id;
  d["x"] = s.pose.position.x;
  d["y"] = s.pose.position.y;
  d["heading"] = yawOf(s.pose.rotation);
  d["linear"] = s.linear.x;
  d["angular"] = s.angular.z;
  d["pose"] = poseArray(s.pose);
  d["twist"] = std::vector<double>{s.linear.x, s.linear.y, s.linear.z, s.angular.x, s.angular.y, s.angular.z};
  // The diagonals of nav_msgs/Odometry's 6 x 6 covariances (x, y, z, roll, pitch, yaw).
  d["pose_covariance"] = std::vector<double>(s.pose_covariance_diagonal.begin(), s.pose_covariance_diagonal.end());
  d["twist_covariance"] = std::vector<double>(s.twist_covariance_diagonal.begin(), s.twist_covariance_diagonal.end());
  return d;
}

py::dict navSatFixDict(const NavSatFixSample& s)
{
  py::dict d = stampedDict(s.stamp_ns, s.frame_id);
  d["status"] = s.status;
  d["service"] = s.service;
  d["latitude"] = s.latitude;
  d["longitude"] = s.longitude;
  d["altitude"] = s.altitude;
  d["position_covariance"] = std::vector<double>(s.position_covariance_diagonal.begin(), s.position_covariance_diagonal.end());
  return d;
}

py::dict imuDict(const ImuSample& s)
{
  auto diagonal = [](const std::array<double, 3>& a) { return std::vector<double>(a.begin(), a.end()); };
  py::dict d = stampedDict(s.stamp_ns, s.frame_id);
  d["orientation"] = xyzwList(s.orientation);
  d["angular_velocity"] = xyzList(s.angular_velocity);
  d["linear_acceleration"] = xyzList(s.linear_acceleration);
  d["orientation_covariance"] = diagonal(s.orientation_covariance_diagonal);
  d["angular_velocity_covariance"] = diagonal(s.angular_velocity_covariance_diagonal);
  d["linear_acceleration_covariance"] = diagonal(s.linear_acceleration_covariance_diagonal);
  return d;
}

py::dict vector3StampedDict(const Vector3StampedSample& s)
{
  py::dict d = stampedDict(s.stamp_ns, s.frame_id);
  d["vector"] = xyzList(s.vector);
  return d;
}

py::dict wrenchStampedDict(const WrenchStampedSample& s)
{
  py::dict d = stampedDict(s.stamp_ns, s.frame_id);
  d["force"] = xyzList(s.force);
  d["torque"] = xyzList(s.torque);
  return d;
}

py::dict transformDict(const TransformSample& s)
{
  py::dict d = stampedDict(s.stamp_ns, s.frame_id);
  d["child_frame_id"] = s.child_frame_id;
  d["pose"] = poseArray(s.pose);
  return d;
}

py::dict trajectoryPointDict(const TrajectoryPointSample& p)
{
  py::dict d;
  d["positions"] = p.positions;
  d["velocities"] = p.velocities;
  d["accelerations"] = p.accelerations;
  d["effort"] = p.effort;
  d["time_from_start"] = double(p.time_from_start_ns) * 1e-9;
  return d;
}

py::dict trajectoryStateDict(const TrajectoryStateSample& s)
{
  py::dict d = stampedDict(s.stamp_ns);
  d["joint_names"] = s.joint_names;
  d["desired"] = trajectoryPointDict(s.desired);
  d["actual"] = trajectoryPointDict(s.actual);
  d["error"] = trajectoryPointDict(s.error);
  return d;
}

py::dict trajectoryFeedbackDict(const ActionFeedback<TrajectoryStateSample>& f)
{
  py::dict d = trajectoryStateDict(f.feedback);
  d["goal_id"] = f.id;
  return d;
}

// actionlib's terminal states as Python names them.
const char* outcomeName(GoalOutcome outcome)
{
  static const char* names[] = {"rejected", "succeeded", "aborted", "canceled"};
  return names[int(outcome)];
}

// Every action result's dict starts with the goal's id and how it ended.
template <class Result>
py::dict actionResultDict(const ActionResult<Result>& r)
{
  py::dict d;
  d["goal_id"] = r.id;
  d["outcome"] = outcomeName(r.outcome);
  return d;
}

py::dict trajectoryResultDict(const ActionResult<FollowJointTrajectoryResult>& r)
{
  py::dict d = actionResultDict(r);
  d["error_code"] = r.result.error_code;
  d["error_string"] = r.result.error_string;
  return d;
}

py::dict gripperResultDict(const ActionResult<GripperCommandResult>& r)
{
  py::dict d = actionResultDict(r);
  d["position"] = r.result.position;
  d["effort"] = r.result.effort;
  d["stalled"] = r.result.stalled;
  d["reached_goal"] = r.result.reached_goal;
  return d;
}

int64_t nsOfSeconds(double s) { return int64_t(std::llround(s * 1e9)); }

// trajectory_msgs/JointTrajectory from {"joint_names": [...], "points": [{"positions": [...],
// "velocities": [...], "accelerations": [...], "time_from_start": s}, ...], "stamp": s (0: now),
// "frame_id": the header's (optional)}.
JointTrajectoryCommand trajectoryOf(const py::dict& d)
{
  JointTrajectoryCommand t;
  t.stamp_ns = nsOfSeconds(d.contains("stamp") ? d["stamp"].cast<double>() : 0.0);
  t.frame_id = d.contains("frame_id") ? d["frame_id"].cast<std::string>() : "";
  t.joint_names = d["joint_names"].cast<std::vector<std::string>>();
  for (const py::handle& item : d["points"])
  {
    const py::dict point = item.cast<py::dict>();
    TrajectoryPointSample p;
    for (auto field : {std::make_pair("positions", &p.positions), std::make_pair("velocities", &p.velocities),
                       std::make_pair("accelerations", &p.accelerations), std::make_pair("effort", &p.effort)})
      if (point.contains(field.first))
        *field.second = point[field.first].cast<std::vector<double>>();
    p.time_from_start_ns = nsOfSeconds(point["time_from_start"].cast<double>());
    t.points.push_back(p);
  }
  return t;
}

// control_msgs/JointTolerance[] from [{"name": ..., "position": ..., "velocity": ..., "acceleration": ...}].
std::vector<JointToleranceSpec> tolerancesOf(const py::object& list)
{
  std::vector<JointToleranceSpec> out;
  for (const py::handle& item : list)
  {
    const py::dict t = item.cast<py::dict>();
    auto number = [&](const char* key) { return t.contains(key) ? t[key].cast<double>() : 0.0; };
    out.push_back(JointToleranceSpec{t["name"].cast<std::string>(), number("position"), number("velocity"),
                                     number("acceleration")});
  }
  return out;
}

template <class Msg, class ToDict>
bool latestAs(const Port& port, ToDict toDict, py::object& out)
{
  auto* typed = dynamic_cast<const OutputPort<Msg>*>(&port);
  if (!typed)
    return false;
  out = typed->latest() ? py::object(toDict(*typed->latest())) : py::none();
  return true;
}
}  // namespace

bool deliverToPort(Port& port, py::object value)
{
  if (auto* in = dynamic_cast<InputPort<double>*>(&port))
    return in->deliver(value.cast<double>());
  if (auto* in = dynamic_cast<InputPort<std::vector<double>>*>(&port))
    return in->deliver(value.cast<std::vector<double>>());
  if (auto* in = dynamic_cast<InputPort<TwistCommand>*>(&port))
  {
    // (linear x, angular z) as a car or differential base takes it, (x, y, angular z) for holonomic ones
    const auto twist = value.cast<std::vector<double>>();
    if (twist.size() == 2)
      return in->deliver(TwistCommand{twist[0], twist[1]});
    if (twist.size() == 3)
      return in->deliver(TwistCommand{twist[0], twist[2], twist[1]});
    throw py::value_error("port '" + port.topic() + "' takes (linear_x, angular_z) or (linear_x, linear_y, angular_z); got " +
                          std::to_string(twist.size()) + " numbers");
  }
  if (auto* in = dynamic_cast<InputPort<TransformsCommand>*>(&port))
  {
    // a tf2_msgs/TFMessage: [{"frame_id", "child_frame_id", "pose": (x, y, z, qx, qy, qz, qw), "stamp"}, ...]
    TransformsCommand message;
    for (const py::handle& item : value)
    {
      const py::dict d = item.cast<py::dict>();
      const auto pose = d["pose"].cast<std::vector<double>>();
      if (pose.size() != 7)
        throw py::value_error("a transform's pose is (x, y, z, qx, qy, qz, qw); got " + std::to_string(pose.size()) +
                              " numbers");
      TransformSample s;
      s.stamp_ns = nsOfSeconds(d.contains("stamp") ? d["stamp"].cast<double>() : 0.0);
      s.frame_id = d["frame_id"].cast<std::string>();
      s.child_frame_id = d["child_frame_id"].cast<std::string>();
      s.pose.position = urdf::Vector3(pose[0], pose[1], pose[2]);
      s.pose.rotation = urdf::Rotation(pose[3], pose[4], pose[5], pose[6]);
      message.transforms.push_back(s);
    }
    return in->deliver(message);
  }
  if (auto* in = dynamic_cast<InputPort<WrenchCommand>*>(&port))
  {
    const auto w = value.cast<std::vector<double>>();  // (fx, fy, fz, tx, ty, tz)
    if (w.size() != 6)
      throw py::value_error("port '" + port.topic() + "' takes a wrench (fx, fy, fz, tx, ty, tz); got " +
                            std::to_string(w.size()) + " numbers");
    return in->deliver(WrenchCommand{urdf::Vector3(w[0], w[1], w[2]), urdf::Vector3(w[3], w[4], w[5])});
  }
  if (auto* in = dynamic_cast<InputPort<JointTrajectoryCommand>*>(&port))
    return in->deliver(trajectoryOf(value.cast<py::dict>()));
  if (auto* in = dynamic_cast<InputPort<ActionGoal<FollowJointTrajectoryGoal>>*>(&port))
  {
    // {"goal_id": ..., "trajectory": {...}, "path_tolerance": [...], "goal_tolerance": [...], "goal_time_tolerance": s}
    const py::dict d = value.cast<py::dict>();
    FollowJointTrajectoryGoal goal;
    goal.trajectory = trajectoryOf(d["trajectory"].cast<py::dict>());
    if (d.contains("path_tolerance"))
      goal.path_tolerance = tolerancesOf(d["path_tolerance"]);
    if (d.contains("goal_tolerance"))
      goal.goal_tolerance = tolerancesOf(d["goal_tolerance"]);
    goal.goal_time_tolerance_ns = nsOfSeconds(d.contains("goal_time_tolerance") ? d["goal_time_tolerance"].cast<double>() : 0.0);
    return in->deliver(ActionGoal<FollowJointTrajectoryGoal>{d["goal_id"].cast<std::string>(), goal});
  }
  if (auto* in = dynamic_cast<InputPort<ActionGoal<GripperCommandGoal>>*>(&port))
  {
    // {"goal_id": ..., "position": ..., "max_effort": ...}
    const py::dict d = value.cast<py::dict>();
    return in->deliver(ActionGoal<GripperCommandGoal>{
        d["goal_id"].cast<std::string>(),
        GripperCommandGoal{d["position"].cast<double>(), d.contains("max_effort") ? d["max_effort"].cast<double>() : 0.0}});
  }
  if (auto* in = dynamic_cast<InputPort<ActionCancel>*>(&port))
    return in->deliver(ActionCancel{value.cast<std::string>()});  // the goal id
  throw py::type_error("port '" + port.topic() + "' carries a message Python cannot send; add it to port_bindings.cpp");
}

py::object latestOfPort(const Port& port)
{
  py::object out;
  if (latestAs<JointStateSample>(port, jointStateDict, out) ||
      latestAs<ControllerStateSample>(port, controllerStateDict, out) ||
      latestAs<OdometrySample>(port, odometryDict, out) || latestAs<TransformSample>(port, transformDict, out) ||
      latestAs<NavSatFixSample>(port, navSatFixDict, out) || latestAs<Vector3StampedSample>(port, vector3StampedDict, out) ||
      latestAs<WrenchStampedSample>(port, wrenchStampedDict, out) ||
      latestAs<ImuSample>(port, imuDict, out) || latestAs<TrajectoryStateSample>(port, trajectoryStateDict, out) ||
      latestAs<ActionResult<FollowJointTrajectoryResult>>(port, trajectoryResultDict, out) ||
      latestAs<ActionFeedback<TrajectoryStateSample>>(port, trajectoryFeedbackDict, out) ||
      latestAs<ActionResult<GripperCommandResult>>(port, gripperResultDict, out))
    return out;
  throw py::type_error("port '" + port.topic() + "' carries a message Python cannot read; add it to port_bindings.cpp");
}

namespace
{
ModelPlugin& pluginOf(Robot& r, const std::string& name)
{
  for (ModelPlugin* p : r.modelPlugins())
    if (p->description().name == name)
      return *p;
  throw py::key_error("robot '" + r.name() + "' has no loaded model plugin '" + name + "' (Robot.model_plugins)");
}

Port& portOf(ModelPlugin& plugin, const std::string& topic, Port::Direction direction)
{
  if (Port* p = plugin.port(topic, direction))
    return *p;
  std::string topics;
  for (const std::unique_ptr<Port>& p : plugin.ports())
    if (p->direction() == direction)
      topics += (topics.empty() ? "" : ", ") + p->topic();
  throw py::key_error("model plugin '" + plugin.description().name + "' " +
                      (direction == Port::Direction::In    ? "subscribes to"
                       : direction == Port::Direction::Out ? "publishes"
                                                           : "serves") +
                      " no topic '" + topic +
                      "' (it has: " + topics + ")");
}
}  // namespace

void init_model_plugins(py::class_<RobotRef>& robot)
{
  robot
      .def_property_readonly("model_plugins", onRobot([](Robot& r) {
        std::vector<std::string> names;
        for (ModelPlugin* p : r.modelPlugins())
          names.push_back(p->description().name);
        return names;
      }), "the gazebo_plugins model plugins that loaded (libgazebo_ros_diff_drive.so, ...), by <plugin name>")
      .def("plugin_topics", onRobot([](Robot& r, const std::string& name) {
        py::dict d;
        std::vector<std::string> in, out;
        std::vector<std::string> services;
        for (const std::unique_ptr<Port>& p : pluginOf(r, name).ports())
          (p->direction() == Port::Direction::In ? in : p->direction() == Port::Direction::Out ? out : services)
              .push_back(p->topic());
        d["subscribes"] = in;
        d["publishes"] = out;
        if (!services.empty())
          d["serves"] = services;
        return d;
      }), py::arg("name"), "the topics the plugin subscribes to and publishes, and the services it serves (relative "
                           "to its namespace)")
      .def("plugin_send", onRobot([](Robot& r, const std::string& name, const std::string& topic, py::object value) {
        return deliverToPort(portOf(pluginOf(r, name), topic, Port::Direction::In), value);
      }), py::arg("name"), py::arg("topic"), py::arg("value"),
           "what a message on the plugin's topic does: a Twist as (linear.x, angular.z); False when refused")
      .def("plugin_call", onRobot([](Robot& r, const std::string& name, const std::string& service, py::object request) {
        Port& port = portOf(pluginOf(r, name), service, Port::Direction::Service);
        EmptyRequest answer;
        if (auto* empty = dynamic_cast<ServicePort<EmptyRequest, EmptyRequest>*>(&port))
          return empty->call(EmptyRequest(), answer);
        if (auto* bias = dynamic_cast<ServicePort<SetBiasRequest, EmptyRequest>*>(&port))
        {
          const auto b = request.cast<std::vector<double>>();
          if (b.size() != 3)
            throw py::value_error("service '" + service + "' takes a bias (x, y, z); got " + std::to_string(b.size()) +
                                  " numbers");
          return bias->call(SetBiasRequest{urdf::Vector3(b[0], b[1], b[2])}, answer);
        }
        throw py::type_error("service '" + service + "' takes a request Python cannot send; add it to port_bindings.cpp");
      }), py::arg("name"), py::arg("service"), py::arg("request") = py::none(),
           "what a call of the plugin's service does (std_srvs/Empty: no request; hector's SetBias: (x, y, z)); "
           "True when it succeeded")
      .def("plugin_latest", onRobot([](Robot& r, const std::string& name, const std::string& topic) {
        return latestOfPort(portOf(pluginOf(r, name), topic, Port::Direction::Out));
      }), py::arg("name"), py::arg("topic"),
           "the latest message the plugin published on the topic as a dict (Odometry: x, y, heading, linear, "
           "angular, pose, twist, frames), or None before the first");
}

}  // namespace python
}  // namespace bullet_plant
