// Gazebo model plugins that act on the physics (gazebo_plugins' drives), hosted by the plant as the
// controllers are: Load reads the <plugin> block once with upstream's names and defaults, OnUpdate
// runs at the start of every step (Gazebo's world update begin), and what they subscribe to and
// publish goes through their ports (message_ports.h), which the ROS node and Python carry. A new
// plugin is its own file under src/plant/gazebo_plugins/, registered there (GAZEBO_ROS_MODEL_PLUGIN),
// and a line in CMakeLists.txt.
#pragma once

#include <cstdint>
#include <functional>
#include <initializer_list>
#include <memory>
#include <string>
#include <vector>

#include <urdf_model/pose.h>

#include "bullet_plant/geometry.h"
#include "bullet_plant/inertial_sensors.h"
#include "bullet_plant/message_ports.h"
#include "bullet_plant/messages.h"
#include "bullet_plant/registry.h"
#include "bullet_plant/robot_description.h"

namespace bullet_plant
{
class GazeboHost;
class Log;
class Param;

// A movable joint as Gazebo's physics::Joint offers it to a model plugin that drives it. A
// non-finite value is ignored (the plant never takes NaN into its physics).
// One collision of a link as its model gives it (Gazebo's physics::Collision): its SDF name
// (sdformat's for a URDF's, lumped names included), its shape and pose in the link, its <surface>.
struct LinkCollision
{
  std::string name;
  urdf::GeometrySharedPtr geometry;
  urdf::Pose origin;
  SurfaceDescription surface;
};

// What a plugin changes of a collision's surface while the world runs: the friction coefficients
// along the first friction direction and across it, and ODE's force-dependent slips (m/s per N).
struct CollisionFriction
{
  double mu1 = 1.0, mu2 = 1.0, slip1 = 0.0, slip2 = 0.0;
};

class ModelJoint
{
public:
  // SetParam("vel") and ("fmax"): the joint is driven to the velocity (rad/s or m/s) by at most the
  // force (N m or N) every step until told otherwise.
  virtual void setVelocity(double velocity) = 0;
  virtual void setMaxForce(double force) = 0;
  // SetForce: an effort added to the joint in the coming step only; the efforts of the calls before
  // one step add up, as Gazebo's.
  virtual void setForce(double effort) = 0;
  // GetForce: the efforts set for the coming step, or those the last step applied until the next
  // SetForce.
  virtual double appliedForce() const = 0;
  // SetPosition: the joint put at the position now, moving at the velocity (the rest of the model
  // keeps its motion). Within the URDF limits only as far as the limit rows push it back.
  virtual void setPosition(double position, double velocity) = 0;
  virtual double position() const = 0;
  virtual double velocity() const = 0;
  // GetEffortLimit: the URDF's <limit effort>, infinite where none is given.
  virtual double effortLimit() const = 0;

protected:
  ~ModelJoint() = default;
};

// What a model plugin reaches of its model.
class ModelPluginContext
{
public:
  virtual const std::string& modelName() const = 0;
  virtual const RobotDescription& robotDescription() const = 0;
  // The model frame: Gazebo's model pose is that of its canonical (the URDF root) link.
  virtual const std::string& rootLink() const = 0;
  // spawn_model's -robot_namespace, as given; empty for none.
  virtual const std::string& spawnNamespace() const = 0;
  // A movable joint to drive; null (with the reason logged, naming `plugin`) for a joint the robot
  // does not have, a fixed one, or one a gazebo_ros_control handle drives.
  virtual ModelJoint* modelJoint(const std::string& joint, const std::string& plugin) = 0;
  // Any movable joint's state, driven or not (joint_state_publisher reads them); false for a joint
  // the robot does not have or a fixed one.
  virtual bool jointState(const std::string& joint, double& position, double& velocity) const = 0;
  // A link frame's pose and velocities in the world.
  virtual LinkMotion linkMotion(const std::string& link) const = 0;
  // Model::SetLinearVel and SetAngularVel: the root body's centre of mass moves with `linear` and
  // turns with `angular` (world frame) from now on, its joints keeping their rates. Nothing for a
  // static model or one fixed to the world.
  virtual void setModelVelocity(const urdf::Vector3& linear, const urdf::Vector3& angular) = 0;
  // The seed of the plugin's noise generator: the same on every run, from the model's and the
  // plugin's names, as the sensors' generators are seeded.
  virtual uint32_t noiseSeed(const ModelPluginDescription& plugin) const = 0;
  // Link::AddForce and AddTorque: a force at the centre of mass of `link`'s body and a torque, both
  // in world axes, for the coming step only. An unknown link or a non-finite value does nothing.
  virtual void addLinkWrench(const std::string& link, const urdf::Vector3& force, const urdf::Vector3& torque) = 0;
  // Link::WorldForce and WorldTorque: what has been added to `link`'s body for the coming step so far
  // (addLinkWrench, gazebo_ros's apply_body_wrench), world axes, the torque about its centre of mass;
  // neither gravity nor contacts, which the physics adds later, as in ODE's accumulators. Zero for
  // an unknown link.
  virtual void addedLinkWrench(const std::string& link, urdf::Vector3& force, urdf::Vector3& torque) const = 0;
  // Where addLinkWrench's force acts: the centre of mass of `link`'s body (world); the world's
  // origin for an unknown link.
  virtual urdf::Vector3 bodyCentreOfMass(const std::string& link) const = 0;
  // Joint::SetPosition on any movable joint (a controller's too), the joint then at rest; false for
  // a joint the robot lacks or a fixed one. Within the URDF limits.
  virtual bool setJointPosition(const std::string& joint, double position) = 0;
  // Whether a gazebo_ros_control transmission drives the joint (modelJoint refuses it then).
  virtual bool transmissionDrives(const std::string& joint) const = 0;
  // Model::SetLinkWorldPose: the model moved, joints as they are and at rest, so that `link` is at
  // `pose` (world). Nothing for a model fixed to the world.
  virtual void setLinkWorldPose(const std::string& link, const urdf::Pose& pose) = 0;
  // World::SetPhysicsEnabled / PhysicsEnabled: the whole world's. Without physics time goes on and
  // controllers, plugins and sensors run, but nothing moves unless set by hand.
  virtual void setPhysicsEnabled(bool enabled) = 0;
  virtual bool physicsEnabled() const = 0;
  // Joint::GetForceTorque(0) as gazebo_ros_ft_sensor reads it: watch a movable joint once (at
  // Load; false for a joint the robot lacks or a fixed one), then after each step the wrench the
  // child's side of the robot passed to the joint over that step, with Gazebo's sign (JointWrench's
  // body2: a joint holding a load up reads its weight, pointing down): the force and the torque
  // about the child link's origin (the joint's), both in the child link's frame. It is the negation
  // of what the child's subtree needed for its motion less gravity, contacts and the forces added
  // to it: everything the parent passed on, the joint's own drive and limits included.
  virtual bool watchJointWrench(const std::string& joint) = 0;
  virtual void jointWrench(const std::string& joint, urdf::Vector3& force, urdf::Vector3& torque) const = 0;
  // The world's gravity (m/s^2, world frame).
  virtual urdf::Vector3 gravity() const = 0;
  // The mass (kg) of `link`'s body (with what fixed joints merge into it, as Gazebo's lumped
  // link) and the link's own URDF <inertia ixx> (kg m^2); 0 for an unknown link.
  virtual double linkMass(const std::string& link) const = 0;
  virtual double linkIxx(const std::string& link) const = 0;
  // The link's own collisions, in its <collision> order; empty for an unknown link.
  virtual std::vector<LinkCollision> linkCollisions(const std::string& link) const = 0;
  // The friction of `link`'s collision named `collision` from the next step on. False, changing
  // nothing, for a collision the link lacks or a coefficient or slip that is negative or not finite.
  virtual bool setCollisionFriction(const std::string& link, const std::string& collision,
                                    const CollisionFriction& friction) = 0;
  // Whether gravity pulls `link` from the next step on (Gazebo's Link::SetGravityMode); false for a
  // link the model lacks.
  virtual bool setLinkGravity(const std::string& link, bool gravity) = 0;
  // The inertial of `link` as Gazebo has it for a URDF robot, whose links fixed to it sdformat lumps
  // into it: its body's mass, centre of mass and principal axes (in the link frame) and principal
  // moments. False where that is the link's own <inertial> (an SDF model, whose fixed links Gazebo
  // keeps apart, or a link lumped into another).
  virtual bool lumpedInertia(const std::string& link, double& mass, urdf::Pose& com, urdf::Vector3& moments) const = 0;
  // The world's physics step (s): what plugins that integrate per update use as their period.
  virtual double stepSize() const = 0;
  // The world's parameter tree (params.h): where the node has copied the ROS parameters a plugin
  // reads (the mimic joint plugin's pid gains).
  virtual const Param& params() const = 0;
  // The namespace of the plugin's node handle, by its file's naming rule (plugin_names.h): where the node
  // puts its ports' topics and where it reads parameters.
  virtual std::string pluginNamespace(const ModelPluginDescription& plugin) const = 0;
  // What the plugin's frame ids resolve against, by its file's naming rule (plugin_names.h).
  virtual std::string tfPrefix(const ModelPluginDescription& plugin) const = 0;
  // The world's host of Gazebo plugins (gazebo_host.h), made at the first call.
  virtual GazeboHost& gazeboHost() = 0;
  virtual Log& log() = 0;

protected:
  ~ModelPluginContext() = default;
};

class ModelPlugin : public MessagePorts
{
public:
  // Reads its parameters, takes its joints and opens its ports; false (the reason logged) when it
  // cannot run, and the robot runs without it.
  virtual bool Load(const ModelPluginDescription& description, ModelPluginContext& context, int64_t time_ns) = 0;
  // At the start of each step, before the physics, at simulated time_ns.
  virtual void OnUpdate(int64_t time_ns) = 0;
  // reset_simulation / reset_world: back to how Load left it.
  virtual void Reset(int64_t time_ns) {}

  // Its <plugin> block (the robot's description holds it), set before Load.
  void setDescription(const ModelPluginDescription& d) { description_ = &d; }
  const ModelPluginDescription& description() const { return *description_; }

private:
  const ModelPluginDescription* description_ = nullptr;
};

// "plugin 'NAME' (FILENAME)": how every message about a model plugin names it.
inline std::string pluginLabel(const ModelPluginDescription& d) { return "plugin '" + d.name + "' (" + d.filename + ")"; }

// True when every one of `elements` has text; otherwise false with the first missing one logged with
// `purpose` (what to put there) and that the plugin is not loaded, as upstream refuses to load.
bool requireElements(const ModelPluginDescription& d, ModelPluginContext& context,
                     std::initializer_list<const char*> elements, const std::string& purpose);

// True when `link`, read from `element`, is a link of the model; otherwise false with the error
// logged (`role` says what the plugin wanted it for) and that the plugin is not loaded.
bool requireLink(const ModelPluginDescription& d, ModelPluginContext& context, const std::string& element,
                 const std::string& link, const std::string& role = "");

using ModelPluginFactory = std::function<std::unique_ptr<ModelPlugin>()>;

// The plugin registered for `filename`; null for a file no model plugin registered.
inline std::unique_ptr<ModelPlugin> createModelPlugin(const std::string& filename)
{
  const ModelPluginFactory* make = Registry<ModelPluginFactory>::instance().find(filename);
  return make ? (*make)() : nullptr;
}

// The host of a Gazebo model plugin library of the user's own (ModelPluginDescription::library):
// its Load loads the library and the plugin as Gazebo does (src/plant/gazebo_host/).
std::unique_ptr<ModelPlugin> createGazeboModelPlugin();

// The description's facts of a model plugin's file: whose naming rules (plugin_names.h) and, for the
// mimic joint plugin, the element naming where it reads pid gains.
inline PluginFile modelPluginFile(PluginNaming naming = PluginNaming::Default, const std::string& pid_gains_element = "")
{
  PluginFile file;
  file.role = PluginRole::Model;
  file.naming = naming;
  file.pid_gains_element = pid_gains_element;
  return file;
}

}  // namespace bullet_plant

// In a model plugin's .cpp, as GZ_REGISTER_MODEL_PLUGIN in Gazebo: `Class` made for each of the
// plugin files that follow (libgazebo_ros_*.so), with `plugin_file` (modelPluginFile(...)) as what
// the description makes of them. The only place a model plugin is named.
#define GAZEBO_ROS_MODEL_PLUGIN(Class, plugin_file, ...)                                                           \
  BULLET_PLANT_REGISTER(                                                                                           \
      ::bullet_plant::ModelPluginFactory, Class,                                                                   \
      [] { return std::unique_ptr<::bullet_plant::ModelPlugin>(new Class()); }, __VA_ARGS__);                      \
  BULLET_PLANT_REGISTER(::bullet_plant::PluginFile, Class##_file, plugin_file, __VA_ARGS__)
