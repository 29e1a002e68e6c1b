// physics::World (gazebo/physics/World.hh), over the simulator's WorldBridge.
#include "gazebo/physics/World.hh"

#include "gazebo/physics/PlantBridge.hh"

namespace gazebo
{
namespace physics
{
World::World(std::shared_ptr<WorldBridge> bridge) : bridge_(std::move(bridge)) {}

std::string World::Name() const { return bridge_->name(); }

common::Time World::SimTime() const { return bridge_->simTime(); }

uint32_t World::Iterations() const { return static_cast<uint32_t>(bridge_->iterations()); }

ignition::math::Vector3d World::Gravity() const { return bridge_->gravity(); }
}  // namespace physics
}  // namespace gazebo
