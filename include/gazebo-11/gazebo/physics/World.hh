// physics::World as a plugin reads and runs it: its name, time, gravity and physics engine, its
// models by name, pause and reset.
#pragma once

#include <map>
#include <memory>
#include <string>

#include <boost/enable_shared_from_this.hpp>
#include <ignition/math/Vector3.hh>
#include <sdf/SDFImpl.hh>

#include "gazebo/common/CommonTypes.hh"
#include "gazebo/common/Time.hh"
#include "gazebo/physics/PhysicsTypes.hh"
#include "gazebo/transport/TransportTypes.hh"
#include "gazebo/util/system.hh"

namespace gazebo
{
namespace msgs
{
class Factory;
}
namespace physics
{
class WorldBridge;

class GZ_PHYSICS_VISIBLE World : public boost::enable_shared_from_this<World>
{
public:
  explicit World(std::shared_ptr<WorldBridge> bridge);
  ~World();
  std::string Name() const;
  common::Time SimTime() const;
  // Wall-clock time since the world was made, as Gazebo's (paused time included).
  common::Time RealTime() const;
  uint32_t Iterations() const;
  ignition::math::Vector3d Gravity() const;
  // From the next step on (PhysicsEngine::SetGravity).
  void SetGravity(const ignition::math::Vector3d& gravity);
  // The world's <magnetic_field> (tesla, world frame; SDF's default where it gives none).
  ignition::math::Vector3d MagneticField() const;
  // The world's <spherical_coordinates> (SDF's: latitude, longitude, elevation and heading 0 on
  // WGS84 where it gives none), the same object each time.
  common::SphericalCoordinatesPtr SphericalCoords() const;
  PhysicsEnginePtr Physics() const;
  // The model of that name (its scoped name too), the same handle each time; null for none.
  ModelPtr ModelByName(const std::string& name) const;
  Model_V Models() const;
  // A model by name, a link by its scoped name (MODEL::LINK), a collision by its own
  // (MODEL::LINK::COLLISION); null for none.
  EntityPtr EntityByName(const std::string& name) const;
  unsigned int ModelCount() const;
  void SetPaused(bool paused);
  bool IsPaused() const;
  // Without physics time goes on and plugins, controllers and sensors run, but nothing moves unless
  // set (gazebo_ros_joint_pose_trajectory turns it off while it sets poses).
  bool PhysicsEnabled() const;
  void SetPhysicsEnabled(bool enable);
  // The simulation back to its start (models where they came, time 0), as gazebo_ros's
  // reset_simulation.
  void Reset();
  // Gazebo's factory: a model added between steps, after the world's next update (paused or not),
  // under its own name made unique as Gazebo makes it (NAME_0, NAME_1 ...), where its <pose> puts it,
  // with its plugins. InsertModelFile takes a model:// URI (or a path) as a world's <include> does,
  // found in GAZEBO_MODEL_PATH and the packages' gazebo_model_path exports; InsertModelString SDF text
  // (<sdf><model>); InsertModelSDF what sdformat read. One that cannot be read or added is an error in
  // the simulator's log naming why; the world goes on.
  void InsertModelFile(const std::string& sdfFilename);
  void InsertModelString(const std::string& sdfString);
  void InsertModelSDF(const sdf::SDF& sdf);
  // The same from a msgs::Factory on ~/factory (Gazebo's factory topic): its sdf, else its
  // sdf_filename, placed at its pose where it has one; clone_model_name and edit_name are an error
  // naming them (the plant neither clones nor edits models).
  // The world's models let go (each holds the world): before the simulator drops the world.
  void Fini();

private:
  void OnFactoryMsg(const boost::shared_ptr<const msgs::Factory>& msg);

  std::shared_ptr<WorldBridge> bridge_;
  PhysicsEnginePtr physics_;
  int64_t started_ns_;  // the wall clock when it was made
  // One Model for each of the simulator's models, as Gazebo's world owns them (Fini lets them go).
  mutable std::map<std::string, ModelPtr> models_;
  mutable common::SphericalCoordinatesPtr spherical_;  // made at the first SphericalCoords
  transport::NodePtr node_;
  transport::SubscriberPtr factory_sub_;
  event::ConnectionPtr delete_entity_;  // a model gone from the simulation: its handle goes from models_
};
}  // namespace physics
}  // namespace gazebo
