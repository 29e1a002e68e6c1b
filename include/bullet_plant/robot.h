// A robot in the world: a Bullet multibody built from URDF, its gazebo_ros_control joint layer and
// its sensors. Created by World::spawn.
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "bullet_plant/controller_manager.h"
#include "bullet_plant/hardware_interface.h"
#include "bullet_plant/inertial_sensors.h"
#include "bullet_plant/joint_layer.h"
#include "bullet_plant/robot_description.h"
#include "bullet_plant/sensors.h"

namespace bullet_plant
{
class ModelPlugin;
class World;

struct Twist
{
  std::array<double, 3> linear{{0, 0, 0}};   // m/s
  std::array<double, 3> angular{{0, 0, 0}};  // rad/s
};

// gazebo_ros's set_joint_properties, ODE's joint parameters of the joint's one axis; NaN leaves a
// value as it is. damping: N m s/rad (N s/m); lower, upper: ODE's stops (a stop may be infinite,
// lower == upper holds the joint there, lower > upper is no stop); fmax, vel: ODE's joint motor, at
// most fmax N m (N) towards the velocity vel, which Gazebo's joint friction is (vel 0).
struct JointProperties
{
  double damping = std::numeric_limits<double>::quiet_NaN();
  double lower = std::numeric_limits<double>::quiet_NaN(), upper = std::numeric_limits<double>::quiet_NaN();
  double fmax = std::numeric_limits<double>::quiet_NaN(), vel = std::numeric_limits<double>::quiet_NaN();
};

// gazebo_ros's get/set_link_properties: a link's own <inertial> (mass, kg; centre of mass in the
// link frame, m; inertia about it along the inertial frame's axes, kg m^2) and whether it feels
// gravity.
struct LinkProperties
{
  double mass = 0.0;
  urdf::Vector3 com{0, 0, 0};
  double ixx = 0.0, ixy = 0.0, ixz = 0.0, iyy = 0.0, iyz = 0.0, izz = 0.0;
  bool gravity = true;
};

class Robot
{
public:
  ~Robot();
  Robot(const Robot&) = delete;
  Robot& operator=(const Robot&) = delete;

  const std::string& name() const;
  // The gazebo_ros_control namespace: the plugin's robotNamespace, else the spawn namespace.
  const std::string& controlNamespace() const;
  // spawn_model's -robot_namespace: what the gazebo_ros plugins without <robotNamespace> get
  // (plugin_names.h).
  const std::string& spawnNamespace() const;
  // Its gazebo_plugins model plugins that loaded (model_plugin.h), in URDF order.
  std::vector<ModelPlugin*> modelPlugins();
  const RobotDescription& description() const;
  // The description of each of its trees, this one's first: an SDF model's links that no joint joins
  // are trees of their own (RobotDescription::other_trees), each with its links' visuals.
  std::vector<const RobotDescription*> treeDescriptions() const;

  // gazebo_ros_control's joint handles, in transmission order: what its controllers see (through
  // the JointHandles interface of the robot's joint layer).
  std::vector<JointHandle>& handles();
  JointHandle* handle(const std::string& joint);

  // Every movable joint of the URDF (transmitted or not), in URDF order, and its state: the joints
  // with one position (an SDF screw is its turn, a gearbox no joint of its own). An SDF ball joint's
  // state is Gazebo 11's ODE ball joint's: position NaN, velocity and effort 0.
  std::vector<std::string> jointNames() const;
  bool jointState(const std::string& joint, double& position, double& velocity, double& effort) const;
  // SDF's ball joints (get_model_properties lists them with jointNames, as Gazebo lists every joint).
  std::vector<std::string> ballJointNames() const;

  // Pose of the URDF root link in the world, and the twist of its origin (world frame).
  urdf::Pose basePose() const;
  Twist baseTwist() const;
  urdf::Pose linkPose(const std::string& link) const;  // throws std::out_of_range for an unknown link

  // What gazebo_ros's model and link services see and set (docs/interfaces.md section 10). Links
  // are the URDF's, by name, those of an SDF model's every tree (RobotDescription::other_trees); an unknown link or joint throws std::out_of_range naming it and the
  // robot, and nothing changes then.
  std::vector<std::string> linkNames() const;
  // The velocity of the link frame's origin and the link's angular velocity, world frame.
  Twist linkTwist(const std::string& link) const;
  // The one kinematics query, as MuJoCo's mj_objectVelocity: the pose of the frame at `offset` in
  // `link` and that frame's velocity, world frame. baseTwist and linkTwist read it, the IMU and
  // gazebo_ros_p3d sample it, get_link_state and link_states report it.
  LinkMotion linkMotion(const std::string& link, const urdf::Pose& offset = urdf::Pose()) const;
  // set_model_state / set_link_state: the whole robot moved rigidly so that `link` is at `pose`
  // (world), every body moving with `twist` (of the link's origin, world frame): the joints keep
  // their positions, at rest relative to each other. A plant multibody cannot pull one link away
  // from its joints, as Gazebo's set_link_state does.
  void setLinkState(const std::string& link, const urdf::Pose& pose, const Twist& twist);
  // set_model_state: the model frame (basePose) at `pose`, moving with `twist` (of its origin, world
  // frame), as setLinkState does for the root link; a model's trees that no joint joins (SDF's free
  // links) move with it as one rigid body, keeping where they are relative to each other.
  void setModelState(const urdf::Pose& pose, const Twist& twist);
  // The normals (world frame, pointing into this robot) of its touching contacts with anything
  // else, the world's shapes or another robot, at the end of the last step: what a check for a
  // collision needs (bullet_plant.CarBatch's "crashed"), without World::contacts' names.
  std::vector<urdf::Vector3> contactNormals() const;
  // set_model_configuration (spawn_model -J): joint positions, held to the URDF limits with a
  // warning, the joints at rest. reset_simulation goes back to the spawn positions.
  void setJointPositions(const std::map<std::string, double>& positions);
  // apply_body_wrench and apply_joint_effort: a force (at the link's body's centre of mass) and
  // torque in world axes, or a joint effort, added every step from simulated time start_ns on
  // for duration_ns (negative: until cleared), as gazebo_ros's wrench and effort jobs.
  void applyLinkWrench(const std::string& link, const urdf::Vector3& force, const urdf::Vector3& torque,
                       int64_t start_ns, int64_t duration_ns);
  void clearLinkWrenches(const std::string& link);
  void applyJointEffort(const std::string& joint, double effort, int64_t start_ns, int64_t duration_ns);
  void clearJointEfforts(const std::string& joint);

  // set_joint_properties, from the next step on; std::invalid_argument for a value the plant cannot
  // take (negative damping or fmax, a NaN-free value that is not finite), nothing changed then.
  void setJointProperties(const std::string& joint, const JointProperties& properties);
  // get/set_link_properties. Setting: std::invalid_argument for values no link can have (not finite,
  // a negative mass or moment, beyond the plant's limits), nothing changed then. The link's mass and
  // inertia change its body's (the links fixed together), its gravity from the next step on; a new
  // centre of mass is not taken (the link keeps its own; Bullet's body frame is built on it) and the
  // body keeps its centre of mass and principal axes: what that leaves out is returned, a sentence
  // each ("" when all is taken).
  LinkProperties linkProperties(const std::string& link) const;
  std::string setLinkProperties(const std::string& link, const LinkProperties& properties);

  // At rest and taken out of the step until something wakes it (a moving body's touch, a wrench or
  // effort, a new state or gravity), as ODE's auto-disable takes Gazebo's resting bodies out. Only
  // a model with no controller manager, model plugins or sensors sleeps.
  bool asleep() const;

  // gazebo_ros_control's e-stop: while on, efforts are 0 and velocity commands 0.
  void setEStop(bool on);
  bool eStop() const;

  // The controller manager gazebo_ros_control would host for this robot; null when the URDF has no
  // gazebo_ros_control plugin block.
  ControllerManager* controllerManager();
  double controlPeriod() const;  // s

  std::vector<Sensor*> sensors();
  Sensor* sensor(const std::string& name);

  // Steps where the physics produced a non-finite state and the robot was put back to its last
  // good state (the world keeps running).
  long recoveries() const;
  // A robot whose physics diverged on kRecoveriesBeforeDisabling steps within a simulated second is
  // taken out of the physics (it stays in the world, frozen, until removed): said once, as an error.
  static constexpr int kRecoveriesBeforeDisabling = 50;
  bool disabled() const;

  struct Internals;  // the plant's side, private to the library

private:
  friend class World;
  friend Internals& internalsOf(Robot& robot);
  explicit Robot(std::unique_ptr<Internals> internals);
  std::unique_ptr<Internals> in_;
};

}  // namespace bullet_plant
