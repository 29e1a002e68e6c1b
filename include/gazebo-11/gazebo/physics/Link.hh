// physics::Link as a model plugin reads and pushes it: its pose and velocities in the world, and
// forces and torques for the coming step in world or link axes.
#pragma once

#include <memory>
#include <string>

#include <boost/weak_ptr.hpp>
#include <ignition/math/Pose3.hh>
#include <ignition/math/Vector3.hh>

#include "gazebo/physics/PhysicsTypes.hh"
#include "gazebo/util/system.hh"

namespace gazebo
{
namespace physics
{
class ModelBridge;

class GZ_PHYSICS_VISIBLE Link
{
public:
  Link(const std::string& name, std::shared_ptr<ModelBridge> bridge);
  std::string GetName() const;
  std::string GetScopedName(bool prependWorldName = false) const;
  // Null once its model has left the world and no one holds it.
  ModelPtr GetModel() const;
  ignition::math::Pose3d WorldPose() const;
  ignition::math::Vector3d WorldLinearVel() const;
  ignition::math::Vector3d WorldAngularVel() const;
  ignition::math::Vector3d RelativeLinearVel() const;
  ignition::math::Vector3d RelativeAngularVel() const;
  // At the centre of mass, world axes.
  void AddForce(const ignition::math::Vector3d& force);
  void AddTorque(const ignition::math::Vector3d& torque);
  // At the centre of mass, the link's axes.
  void AddRelativeForce(const ignition::math::Vector3d& force);
  void AddRelativeTorque(const ignition::math::Vector3d& torque);

private:
  friend class Model;  // which names itself their model once it is held
  std::string name_;
  boost::weak_ptr<Model> model_;
  std::shared_ptr<ModelBridge> bridge_;
};
}  // namespace physics
}  // namespace gazebo
