// What a gazebo_ros sensor plugin's ROS-free half registers (GAZEBO_ROS_SENSOR_PLUGIN_FILE): the
// <sensor> it loads in and whose naming rules it follows (plugin_names.h), which the description and
// the Python module read without ROS. Each plugin's half is a file of this room named as its ROS half
// in src/node/sensor_plugins/, as upstream keeps a plugin's .h beside its .cpp; a model plugin
// registers the same facts with its factory (GAZEBO_ROS_MODEL_PLUGIN).
#pragma once

#include <string>

#include "bullet_plant/registry.h"
#include "bullet_plant/robot_description.h"

namespace bullet_plant
{
// A plugin inside a <sensor>, refused (why, in upstream's words) where `refusal` says so.
inline PluginFile sensorPluginFile(PluginNaming naming, std::string (*refusal)(const SensorDescription&) = nullptr)
{
  PluginFile file;
  file.role = PluginRole::Sensor;
  file.naming = naming;
  file.refusal = refusal;
  return file;
}

// A model plugin following one link (<bodyName>), described as a sensor of `sensor_type`.
inline PluginFile linkSensorPluginFile(const std::string& sensor_type)
{
  PluginFile file;
  file.role = PluginRole::LinkSensor;
  file.sensor_type = sensor_type;
  return file;
}

// gazebo_ros_range, velodyne_simulator, gazebo_ros_block_laser and hector's sonar refuse to load on
// anything but a ray sensor.
inline std::string needsRaySensor(const SensorDescription& d)
{
  if (d.type == "ray" || d.type == "gpu_ray")
    return "";
  return d.plugin_filename + " needs a <sensor type=\"ray\"> or \"gpu_ray\" (\"requires a Ray Sensor as its parent\"), not '" +
         d.type + "'";
}

}  // namespace bullet_plant

// In a sensor plugin's ROS-free half: `plugin_file` (sensorPluginFile(...)) for each of the plugin
// files that follow (libgazebo_ros_*.so). `id` names the registration, unique in its file.
#define GAZEBO_ROS_SENSOR_PLUGIN_FILE(id, plugin_file, ...) \
  BULLET_PLANT_REGISTER(::bullet_plant::PluginFile, id, plugin_file, __VA_ARGS__)
