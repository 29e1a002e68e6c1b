// bullet_plant.Robot: joint handles, poses, the e-stop and the robot's controller manager.
#include "bindings.h"

#include <cmath>

namespace bullet_plant
{
namespace python
{
namespace
{
JointHandle& handleOf(Robot& r, const std::string& joint)
{
  JointHandle* h = r.handle(joint);
  if (!h)
    throw py::key_error("robot '" + r.name() + "' has no joint handle '" + joint +
                        "' (joints with a <transmission>: see Robot.handles)");
  return *h;
}

// A state as set_link_state and set_model_state take it: x y z qx qy qz qw, and two velocities.
void stateFrom(const char* method, const std::vector<double>& pose, const std::vector<double>& linear,
               const std::vector<double>& angular, urdf::Pose& p, Twist& t)
{
  if (pose.size() != 7 || linear.size() != 3 || angular.size() != 3)
    throw py::value_error(std::string(method) + " takes a pose of x y z qx qy qz qw (as link_pose gives) and linear and "
                          "angular velocities of three numbers each");
  p.position = urdf::Vector3(pose[0], pose[1], pose[2]);
  p.rotation = urdf::Rotation(pose[3], pose[4], pose[5], pose[6]);
  p.rotation.normalize();
  std::copy(linear.begin(), linear.end(), t.linear.begin());
  std::copy(angular.begin(), angular.end(), t.angular.begin());
}

}  // namespace

py::class_<RobotRef> init_robot(py::module_& m)
{
  py::class_<RobotRef> robot(m, "Robot");
  robot
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
      .def_property_readonly("joint_names", onRobot([](Robot& r) { return r.jointNames(); }),
                             "every movable joint of the URDF with one position (an SDF screw: its turn; not ball joints)")
      .def("joint_state", onRobot([](Robot& r, const std::string& joint) {
        double p, v, e;
        if (!r.jointState(joint, p, v, e))
          throw py::key_error("robot '" + r.name() + "' has no movable joint '" + joint + "'");
        return py::make_tuple(p, v, e);
      }), "(position, velocity, effort) of a movable joint; of an SDF ball joint (nan, 0, 0), as Gazebo 11's")
      .def_property_readonly("link_names", onRobot([](Robot& r) { return r.linkNames(); }),
                             "the model's links (every tree's, as gazebo_ros's get_model_properties lists them)")
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
      .def("set_link_state", onRobot([](Robot& r, const std::string& link, const std::vector<double>& pose,
                                        const std::vector<double>& linear, const std::vector<double>& angular) {
        urdf::Pose p;
        Twist t;
        stateFrom("set_link_state", pose, linear, angular, p, t);
        try
        {
          r.setLinkState(link, p, t);
        }
        catch (const std::out_of_range& e)
        {
          throw py::key_error(e.what());
        }
      }), py::arg("link"), py::arg("pose"), py::arg("linear") = std::vector<double>{0, 0, 0},
           py::arg("angular") = std::vector<double>{0, 0, 0},
           "gazebo_ros's set_link_state: the whole robot moved rigidly so that `link` is at `pose` (x y z qx qy qz "
           "qw, world), every body moving with (linear, angular) (of the link's origin, world frame)")
      .def("set_model_state", onRobot([](Robot& r, const std::vector<double>& pose, const std::vector<double>& linear,
                                         const std::vector<double>& angular) {
        urdf::Pose p;
        Twist t;
        stateFrom("set_model_state", pose, linear, angular, p, t);
        r.setModelState(p, t);
      }), py::arg("pose"), py::arg("linear") = std::vector<double>{0, 0, 0},
           py::arg("angular") = std::vector<double>{0, 0, 0},
           "gazebo_ros's set_model_state: the model frame (base_pose) at `pose` (x y z qx qy qz qw, world), moving "
           "with (linear, angular); a model's free links (trees no joint joins) move with it, rigidly")
      .def("apply_link_wrench", onRobot([](Robot& r, const std::string& link, const std::vector<double>& force,
                                           const std::vector<double>& torque, double start, double duration) {
        if (force.size() != 3 || torque.size() != 3)
          throw py::value_error("apply_link_wrench takes a force and a torque of three numbers each");
        try
        {
          r.applyLinkWrench(link, urdf::Vector3(force[0], force[1], force[2]), urdf::Vector3(torque[0], torque[1], torque[2]),
                            std::llround(start * 1e9), duration < 0 ? -1 : std::llround(duration * 1e9));
        }
        catch (const std::out_of_range& e)
        {
          throw py::key_error(e.what());
        }
      }), py::arg("link"), py::arg("force"), py::arg("torque") = std::vector<double>{0, 0, 0}, py::arg("start") = 0.0,
           py::arg("duration") = -1.0,
           "gazebo_ros's apply_body_wrench: force (at the link's centre of mass) and torque in world axes, added "
           "every step from simulated time `start` (s) for `duration` (s; negative: until clear_link_wrenches)")
      .def("clear_link_wrenches", onRobot([](Robot& r, const std::string& link) { r.clearLinkWrenches(link); }))
      .def_property_readonly("asleep", onRobot([](Robot& r) { return r.asleep(); }),
                             "at rest and left out of the step until touched, pushed or set (free models only)")
      .def_property("e_stop", onRobot([](Robot& r) { return r.eStop(); }), onRobot([](Robot& r, bool on) { r.setEStop(on); }))
      .def_property_readonly("recoveries", onRobot([](Robot& r) { return r.recoveries(); }))
      .def_property_readonly("disabled", onRobot([](Robot& r) { return r.disabled(); }), "taken out of the physics after diverging step after step")
      .def_property_readonly("controller_manager", py::cpp_function([](const RobotRef& ref) {
        managerOf(ref.get());  // a robot without one says so here, not at first use
        return ManagerRef{ref};
      }, py::keep_alive<0, 1>()))
      .def_property_readonly("control_period", onRobot([](Robot& r) { return r.controlPeriod(); }))
;
  return robot;
}

}  // namespace python
}  // namespace bullet_plant
