// physics::Entity: what Gazebo's models and links have in common (World::EntityByName gives one,
// which a plugin casts to the Model or Link it is: boost::dynamic_pointer_cast).
#pragma once

#include <string>

#include <ignition/math/Pose3.hh>
#include <ignition/math/Vector3.hh>

#include "gazebo/physics/Base.hh"
#include "gazebo/physics/PhysicsTypes.hh"
#include "gazebo/util/system.hh"

namespace gazebo
{
namespace physics
{
class GZ_PHYSICS_VISIBLE Entity : public Base
{
public:
  Entity() { AddType(ENTITY); }
  ~Entity() override;
  virtual std::string GetName() const = 0;
  virtual std::string GetScopedName(bool prependWorldName = false) const = 0;
  virtual ignition::math::Pose3d WorldPose() const = 0;
  // The pose in the parent's frame: a link's in its model's, a model's in the world.
  virtual ignition::math::Pose3d RelativePose() const = 0;
  virtual ignition::math::Vector3d WorldLinearVel() const = 0;
  virtual ignition::math::Vector3d WorldAngularVel() const = 0;
};
}  // namespace physics
}  // namespace gazebo
