// physics::Link as a model plugin reads and pushes it: its pose and velocities in the world, and
// forces and torques for the coming step in world or link axes.
#pragma once

#include <memory>
#include <string>

#include <boost/enable_shared_from_this.hpp>
#include <boost/weak_ptr.hpp>
#include <ignition/math/Pose3.hh>
#include <ignition/math/Vector3.hh>

#include "gazebo/physics/Entity.hh"
#include "gazebo/physics/PhysicsTypes.hh"
#include "gazebo/util/system.hh"

namespace gazebo
{
namespace physics
{
class ModelBridge;

class GZ_PHYSICS_VISIBLE Link : public Entity, public boost::enable_shared_from_this<Link>
{
public:
  Link(const std::string& name, std::shared_ptr<ModelBridge> bridge);
  std::string GetName() const override;
  std::string GetScopedName(bool prependWorldName = false) const override;
  // Null once its model has left the world and no one holds it.
  ModelPtr GetModel() const;
  ModelPtr GetParentModel() const { return GetModel(); }
  // The pose the physics left it at: its world pose (Gazebo's, read from a world update callback).
  ignition::math::Pose3d DirtyPose() const { return WorldPose(); }
  // The canonical link's velocity set as Model::SetLinearVel / SetAngularVel sets it; another
  // link's is one gzerr (the plant sets a model's velocity at its canonical link only).
  void SetLinearVel(const ignition::math::Vector3d& velocity);
  void SetAngularVel(const ignition::math::Vector3d& velocity);
  // The model moved so that the link is at `pose` (world), its joints as they are, at rest.
  void SetWorldPose(const ignition::math::Pose3d& pose, bool notify = true, bool publish = true);
  // ODE's body switch (dBodyDisable): the plant keeps every link of a model in its simulation, so
  // SetEnabled(false) is one gzwarn naming the link and changes nothing; GetEnabled is true.
  void SetEnabled(bool enable) const;
  bool GetEnabled() const { return true; }
  // Whether gravity pulls it: its model's <gravity>, or what SetGravityMode made it (from the next
  // step on; the links fixed to it in one body feel their own).
  void SetGravityMode(bool mode);
  bool GetGravityMode() const;
  ignition::math::Pose3d WorldPose() const override;
  ignition::math::Pose3d RelativePose() const override;
  // Of its frame's origin, world axes.
  ignition::math::Vector3d WorldLinearVel() const override;
  // Of the point at `_offset` from its frame's origin, given in its frame, or in the frame `_q`
  // rotates to the world's.
  ignition::math::Vector3d WorldLinearVel(const ignition::math::Vector3d& _offset) const;
  ignition::math::Vector3d WorldLinearVel(const ignition::math::Vector3d& _offset,
                                          const ignition::math::Quaterniond& _q) const;
  ignition::math::Vector3d WorldAngularVel() const override;
  ignition::math::Vector3d RelativeLinearVel() const;
  ignition::math::Vector3d RelativeAngularVel() const;
  // At the centre of mass, world axes.
  void AddForce(const ignition::math::Vector3d& force);
  void AddTorque(const ignition::math::Vector3d& torque);
  // At the centre of mass, the link's axes.
  void AddRelativeForce(const ignition::math::Vector3d& force);
  void AddRelativeTorque(const ignition::math::Vector3d& torque);
  // A force in world axes at a point of the link: given in the link frame, or in the world.
  void AddForceAtRelativePosition(const ignition::math::Vector3d& force, const ignition::math::Vector3d& position);
  void AddForceAtWorldPosition(const ignition::math::Vector3d& force, const ignition::math::Vector3d& position);
  // The force (torque) on the link for the coming step made `force`, whatever was added so far.
  void SetForce(const ignition::math::Vector3d& force);
  void SetTorque(const ignition::math::Vector3d& torque);
  // What has been added for the coming step (world axes; the torque about the centre of mass):
  // neither gravity nor contacts, as in Gazebo's ODE.
  ignition::math::Vector3d WorldForce() const;
  ignition::math::Vector3d WorldTorque() const;
  // The centre of mass where forces act (of the link and the links fixed to it), the link's axes.
  ignition::math::Pose3d WorldCoGPose() const;
  // The link's <inertial>, a copy: for a URDF robot with the links fixed to it lumped in, as
  // Gazebo's (sdformat lumps them); for an SDF model its own.
  InertialPtr GetInertial() const;
  // Its own collisions, in its <collision> order (made at the first call, the same ones after), and
  // one by name or index (null for none).
  Collision_V GetCollisions() const;
  CollisionPtr GetCollision(const std::string& name) const;
  CollisionPtr GetCollision(unsigned int index) const;
  // The movable joints whose child, or whose parent, the link is.
  Joint_V GetParentJoints() const;
  Joint_V GetChildJoints() const;

private:
  friend class Model;  // which names itself their model once it is held
  std::string name_;
  boost::weak_ptr<Model> model_;
  std::shared_ptr<ModelBridge> bridge_;
  mutable Collision_V collisions_;
  mutable bool collisions_made_ = false;
};
}  // namespace physics
}  // namespace gazebo
