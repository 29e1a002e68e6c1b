// What Gazebo's physics::World reaches of the simulated world (WorldPluginContext, gazebo_host.h),
// as its own object beside the robots' plugin contexts: the world's time, step and pace, its
// robots as models, pause and reset, and joints made at run time between robots' links and the world.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "bullet_plant/gazebo_host.h"
#include "bullet_plant/world.h"

namespace bullet_plant
{
class PlantWorldPluginContext final : public WorldPluginContext
{
public:
  PlantWorldPluginContext(World& world, World::Internals& internals) : world_(world), w_(internals) {}

  const std::string& worldName() const override;
  int64_t timeNs() const override;
  uint64_t iterations() const override;
  double stepSize() const override;
  bool setStepSize(double seconds) override;
  void setGravity(const urdf::Vector3& gravity) override;
  double realTimeUpdateRate() const override;
  double realTimeFactor() const override;
  urdf::Vector3 gravity() const override;
  urdf::Vector3 magneticField() const override;
  const WorldDescription::SphericalCoordinates& sphericalCoordinates() const override;
  std::vector<std::string> modelNames() const override;
  ModelPluginContext* model(const std::string& name) override;
  bool paused() const override;
  void setPaused(bool paused) override;
  bool physicsEnabled() const override;
  void setPhysicsEnabled(bool enable) override;
  void resetSimulation() override;
  int attach(const RunTimeJoint& joint) override;
  void detach(int joint) override;
  double jointPosition(int joint) const override;
  double jointVelocity(int joint) const override;
  urdf::Vector3 jointAxis(int joint) const override;
  void addJointEffort(int joint, double effort) override;
  void insertModel(const std::string& sdf_xml) override;
  Log& log() override;

private:
  World& world_;
  World::Internals& w_;
};
}  // namespace bullet_plant
