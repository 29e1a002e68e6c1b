#include "simulation/world_plugin_context.h"

#include <cmath>
#include <stdexcept>

#include "bullet_plant/log.h"
#include "physics/bullet_conversions.h"
#include "simulation/internals.h"

namespace bullet_plant
{
const std::string& PlantWorldPluginContext::worldName() const { return w_.description.name; }

int64_t PlantWorldPluginContext::timeNs() const { return w_.time_ns; }

uint64_t PlantWorldPluginContext::iterations() const { return w_.steps; }

double PlantWorldPluginContext::stepSize() const { return w_.step_s; }

bool PlantWorldPluginContext::setStepSize(double seconds)
{
  try
  {
    world_.setTimeStep(seconds);
    return true;
  }
  catch (const std::invalid_argument&)
  {
    return false;
  }
}

double PlantWorldPluginContext::realTimeUpdateRate() const { return w_.description.real_time_update_rate; }

double PlantWorldPluginContext::realTimeFactor() const { return w_.description.real_time_factor; }

urdf::Vector3 PlantWorldPluginContext::gravity() const { return world_.gravity(); }

urdf::Vector3 PlantWorldPluginContext::magneticField() const { return w_.description.magnetic_field; }

const WorldDescription::SphericalCoordinates& PlantWorldPluginContext::sphericalCoordinates() const
{
  return w_.description.spherical_coordinates;
}

void PlantWorldPluginContext::setGravity(const urdf::Vector3& gravity) { world_.setGravity(gravity); }

std::vector<std::string> PlantWorldPluginContext::modelNames() const
{
  std::vector<std::string> names;
  for (Robot* robot : world_.robots())
    names.push_back(robot->name());
  return names;
}

ModelPluginContext* PlantWorldPluginContext::model(const std::string& name)
{
  Robot* robot = world_.robot(name);
  return robot ? &internalsOf(*robot).model_plugin_context : nullptr;
}

bool PlantWorldPluginContext::paused() const { return world_.paused(); }

void PlantWorldPluginContext::setPaused(bool paused) { world_.setPaused(paused); }

bool PlantWorldPluginContext::physicsEnabled() const { return w_.physics_enabled; }

void PlantWorldPluginContext::setPhysicsEnabled(bool enable) { w_.physics_enabled = enable; }

void PlantWorldPluginContext::resetSimulation() { world_.resetSimulation(); }

int PlantWorldPluginContext::attach(const RunTimeJoint& joint) { return w_.attach(joint); }

void PlantWorldPluginContext::detach(int joint) { w_.detach(joint); }

double PlantWorldPluginContext::jointPosition(int joint) const
{
  const World::Internals::Attachment* held = w_.attachment(joint);
  return held ? double(held->constraint->position()) : 0.0;
}

double PlantWorldPluginContext::jointVelocity(int joint) const
{
  const World::Internals::Attachment* held = w_.attachment(joint);
  return held ? double(held->constraint->velocity()) : 0.0;
}

urdf::Vector3 PlantWorldPluginContext::jointAxis(int joint) const
{
  const World::Internals::Attachment* held = w_.attachment(joint);
  return held ? fromBullet(held->constraint->axisInWorld()) : urdf::Vector3();
}

void PlantWorldPluginContext::addJointEffort(int joint, double effort)
{
  auto found = w_.attachments.find(joint);
  if (found != w_.attachments.end() && std::isfinite(effort))
    found->second.effort += effort;
}

void PlantWorldPluginContext::insertModel(const std::string& sdf_xml) { world_.insertModel(sdf_xml); }

Log& PlantWorldPluginContext::log() { return w_.log; }
}  // namespace bullet_plant
