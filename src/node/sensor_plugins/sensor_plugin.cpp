#include "sensor_plugin.h"

#include "bullet_plant/sensors.h"
#include "ros_names.h"

namespace bullet_plant
{
std::unique_ptr<SensorPlugin> SensorPlugin::create(Sensor& sensor, const Robot& robot, double step_size, Outbox& outbox)
{
  if (!sensor.publishesOnRos())
    return nullptr;
  const SensorPluginFactory* make = Registry<SensorPluginFactory>::instance().find(sensor.description().plugin_filename);
  if (!make)
    return nullptr;
  std::unique_ptr<SensorPlugin> plugin = (*make)();
  plugin->namespace_ = pluginNamespace(sensor.description(), robot.spawnNamespace(), robot.name());
  plugin->step_size_ = step_size;
  plugin->outbox_ = &outbox;
  plugin->Load(sensor);
  return plugin;
}

ros::NodeHandle SensorPlugin::nodeHandle(const Sensor& sensor) const
{
  const std::string& ns = namespace_;
  return ros::NodeHandle(ns.empty() ? "/" : requireValidRosName(ns, "sensor '" + sensor.name() + "' robotNamespace"));
}

std::string SensorPlugin::searchedTfPrefix(const ros::NodeHandle& nh)
{
  std::string key, prefix;
  if (nh.searchParam("tf_prefix", key) && nh.getParam(key, prefix))
    return prefix;
  return "";
}

bool SensorPlugin::takeUpdate(const Sensor& sensor)
{
  if (sensor.updates() == seen_updates_)
    return false;
  seen_updates_ = sensor.updates();
  return true;
}

}  // namespace bullet_plant
