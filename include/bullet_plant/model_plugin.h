// Gazebo model plugins that act on the physics (gazebo_plugins' drives), hosted by the plant as the
// controllers are: Load reads the <plugin> block once with upstream's names and defaults, OnUpdate
// runs at the start of every step (Gazebo's world update begin), and what they subscribe to and
// publish goes through their ports (message_ports.h), which the ROS node and Python carry. A new
// plugin is its own file under src/plant/gazebo_plugins/ and a line in the registry there.
#pragma once

#include <memory>
#include <string>

#include <urdf_model/pose.h>

#include "bullet_plant/controllers.h"
#include "bullet_plant/inertial_sensors.h"
#include "bullet_plant/message_ports.h"
#include "bullet_plant/robot_description.h"

namespace bullet_plant
{
class Log;

// A joint's velocity motor, as Gazebo's Joint::SetParam("vel") and ("fmax") set it: the joint is
// driven to the velocity by at most the force (N m or N) every step until told otherwise.
class JointMotor
{
public:
  virtual void setVelocity(double velocity) = 0;  // rad/s or m/s; a non-finite value is ignored
  virtual void setMaxForce(double force) = 0;
  virtual double position() const = 0;
  virtual double velocity() const = 0;

protected:
  ~JointMotor() = default;
};

// What a model plugin reaches of its model.
class ModelPluginContext
{
public:
  virtual const std::string& modelName() const = 0;
  virtual const RobotDescription& robotDescription() const = 0;
  // The model frame: Gazebo's model pose is that of its canonical (the URDF root) link.
  virtual const std::string& rootLink() const = 0;
  // The motor of a movable joint; null (with the reason logged, naming `plugin`) for a joint the
  // robot does not have, a fixed one, or one a gazebo_ros_control handle drives.
  virtual JointMotor* jointMotor(const std::string& joint, const std::string& plugin) = 0;
  // A link frame's pose and velocities in the world.
  virtual LinkMotion linkMotion(const std::string& link) const = 0;
  // What the plugin's frame ids resolve against: gazebo_ros's GazeboRos helper's tf prefix (its
  // namespace without trailing '/'), plugin_names.h.
  virtual std::string tfPrefix(const ModelPluginDescription& plugin) const = 0;
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

// The plugin a kind names; null for kinds that are no model plugin.
std::unique_ptr<ModelPlugin> createModelPlugin(PluginKind kind);

}  // namespace bullet_plant
