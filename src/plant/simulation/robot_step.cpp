// A robot's own phases of World::step, one named function each: the controllers whose control
// period has come, the model plugins' OnUpdate, the sensors. A step in gazebo_ros_control's order:
// [wrench and effort jobs (external_efforts.h)], updateControllers, updateModelPlugins, writeSim
// (the joint layer), the physics step (joint wrenches watched around it, joint_wrench_watch.h),
// recoverIfDiverged (divergence_recovery.h), readSim, updateSensors; World::step runs each phase
// for every robot before the next.
#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>

#include "simulation/internals.h"

namespace bullet_plant
{
void Robot::Internals::updateControllers(int64_t time_ns)
{
  if (!controller_manager || time_ns - last_control_ns < control_period_ns)
    return;
  controller_manager->update(time_ns, (time_ns - last_control_ns) * 1e-9);
  last_control_ns = time_ns;
}

void Robot::Internals::updateModelPlugins(int64_t time_ns)
{
  for (std::unique_ptr<ModelPlugin>& plugin : model_plugins)
    plugin->OnUpdate(time_ns);
  for (auto& joint : model_joints)
    joint.second->apply(world->step_s);
}

bool Robot::Internals::asleep() const
{
  const btMultiBodyLinkCollider* base = multibody.bullet->getBaseCollider();
  return multibody.bullet->getCanSleep() && base && base->getActivationState() == ISLAND_SLEEPING;
}

void Robot::Internals::updateSensors(int64_t time_ns)
{
  for (auto& sensor : sensors)
  {
    if (sensor->active())
      sensor->updateIfDue(sensor_context, time_ns);
    sensor->collect(false);  // a frame rendered while the simulation went on, when it is done
  }
}

}  // namespace bullet_plant
