// Gazebo 11's plugins of the user's own in a world, hosted as Gazebo hosts them: world plugins (a
// <plugin> in the world file), system plugins (gzserver -s) and model plugins (a robot's <plugin>
// whose library was found: createGazeboModelPlugin, model_plugin.h), all over one physics::World.
// The world makes its host when the first such plugin comes, so that a world without one pays
// nothing; the host reaches the world through WorldPluginContext, implemented by the simulation.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <urdf_model/pose.h>

#include "bullet_plant/run_time_joint.h"
#include "bullet_plant/world_description.h"

namespace bullet_plant
{
class Log;
class ModelPluginContext;
class Sensor;

// What Gazebo's physics::World, and the joints plugins make at run time, reach of the world.
// The sensor types Gazebo's API measures itself from the physics, as Gazebo's own classes do
// (AltimeterSensor, MagnetometerSensor, GpsSensor read their link's pose and velocity,
// ForceTorqueSensor its joint's wrench): the plant makes no sensor of its own under them, and
// measures them only for a sensor plugin of the user's.
inline bool measuredByGazeboApi(const std::string& sensor_type)
{
  return sensor_type == "altimeter" || sensor_type == "magnetometer" || sensor_type == "gps" ||
         sensor_type == "force_torque";
}

class WorldPluginContext
{
public:
  virtual const std::string& worldName() const = 0;
  virtual int64_t timeNs() const = 0;
  virtual uint64_t iterations() const = 0;
  virtual double stepSize() const = 0;
  // PhysicsEngine::SetMaxStepSize: within the plant's bounds (world_description.h); false otherwise.
  virtual bool setStepSize(double seconds) = 0;
  virtual double realTimeUpdateRate() const = 0;
  virtual double realTimeFactor() const = 0;
  virtual urdf::Vector3 gravity() const = 0;
  // From the next step on (m/s^2, world frame).
  virtual void setGravity(const urdf::Vector3& gravity) = 0;
  // The world file's <magnetic_field> and <spherical_coordinates> (world_description.h).
  virtual urdf::Vector3 magneticField() const = 0;
  virtual const WorldDescription::SphericalCoordinates& sphericalCoordinates() const = 0;
  // The models that move (the robots), in the order they came; the plugin context of one by name,
  // or null for a name that is none of them.
  virtual std::vector<std::string> modelNames() const = 0;
  virtual ModelPluginContext* model(const std::string& name) = 0;
  virtual bool paused() const = 0;
  virtual void setPaused(bool paused) = 0;
  // World::SetPhysicsEnabled: without physics time goes on, nothing moves unless set.
  virtual bool physicsEnabled() const = 0;
  virtual void setPhysicsEnabled(bool enable) = 0;
  // World::Reset: models to where they started, time to 0 (gazebo_ros's reset_simulation).
  virtual void resetSimulation() = 0;
  // A joint made at run time (Joint::Load, Attach): an id to read, drive and release it with
  // (Joint::Detach), or -1 with the reason logged (an unknown model or link, both links one body, an
  // anchor, axis or limits that are no such thing).
  virtual int attach(const RunTimeJoint& joint) = 0;
  virtual void detach(int joint) = 0;
  // Its position (m or rad, 0 where it was made) and rate; 0 for a joint released or that neither
  // slides nor turns.
  virtual double jointPosition(int joint) const = 0;
  virtual double jointVelocity(int joint) const = 0;
  // Its axis in the world now, as its parent carries it (unit); zero for a joint released.
  virtual urdf::Vector3 jointAxis(int joint) const = 0;
  // An effort along or about its axis for the coming step (Joint::SetForce), added to any before.
  virtual void addJointEffort(int joint, double effort) = 0;
  // World::InsertModelString / InsertModelFile / InsertModelSDF: a model as SDF text, added between
  // steps (World::insertModel).
  virtual void insertModel(const std::string& sdf_xml) = 0;
  virtual Log& log() = 0;

protected:
  ~WorldPluginContext() = default;
};

class GazeboHost
{
public:
  virtual ~GazeboHost() = default;
  // WorldPlugin: made from its library, Load(World, its <plugin> element read by sdformat), Init.
  // False, with Gazebo's error naming the plugin, the file and why, where it cannot be; the world
  // runs without it.
  virtual bool loadWorldPlugin(const WorldPluginDescription& plugin) = 0;
  // SensorPlugin (a <sensor>'s <plugin> whose file was found: the description's `library`): Gazebo's
  // sensor of its type over `sensors`, the plant's simulation of it (gazebo_host/gazebo_sensor_host.h:
  // the sensor, or a multicamera's cameras in their order, `d` the first one's description), then
  // Load(that sensor, its <plugin> element), Init. False as above; the robot runs without it.
  virtual bool loadSensorPlugin(const SensorDescription& d, const std::vector<Sensor*>& sensors,
                                ModelPluginContext& model) = 0;
  // SystemPlugin (gzserver -s FILE): found on the plugin paths, Load(argc, argv), Init. False as above.
  virtual bool loadSystemPlugin(const std::string& filename, const std::vector<std::string>& arguments) = 0;
  // Each step: event::Events::worldUpdateBegin and beforePhysicsUpdate before the plugins' and the
  // controllers' updates, worldUpdateEnd after the physics, then the Gazebo sensors' new readings.
  virtual void beginStep() = 0;
  virtual void endStep() = 0;
  // reset_world / reset_simulation: the world plugins' Reset and Events::worldReset (timeReset too
  // for a simulation reset).
  virtual void reset(bool simulation) = 0;
  // A model left the world (delete_model): its physics::Model answers nothing from now on, and the
  // joints made at run time on it are released.
  virtual void modelRemoved(const std::string& name) = 0;
};

std::unique_ptr<GazeboHost> createGazeboHost(WorldPluginContext& world);

// gzserver --verbose: Gazebo's console (gzmsg, gzdbg) writes what plugins say; without it only
// their warnings and errors, as Gazebo's. The process's, as Gazebo's console is.
void setGazeboVerbose(bool verbose);

}  // namespace bullet_plant
