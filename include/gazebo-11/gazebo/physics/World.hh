// physics::World as a plugin reads it: its name, simulated time, iterations and gravity.
#pragma once

#include <memory>
#include <string>

#include <boost/enable_shared_from_this.hpp>
#include <ignition/math/Vector3.hh>

#include "gazebo/common/Time.hh"
#include "gazebo/physics/PhysicsTypes.hh"
#include "gazebo/util/system.hh"

namespace gazebo
{
namespace physics
{
class WorldBridge;

class GZ_PHYSICS_VISIBLE World : public boost::enable_shared_from_this<World>
{
public:
  explicit World(std::shared_ptr<WorldBridge> bridge);
  std::string Name() const;
  common::Time SimTime() const;
  uint32_t Iterations() const;
  ignition::math::Vector3d Gravity() const;

private:
  std::shared_ptr<WorldBridge> bridge_;
};
}  // namespace physics
}  // namespace gazebo
