// The gazebo_ros sensor plugins' ROS-free halves, registered by file name: which <sensor> each loads
// in and whose naming rules it follows (plugin_names.h). The description and the Python module need
// these facts without ROS; the plugins' ROS halves are src/node/sensor_plugins/, one file each. The
// model plugins register theirs in their own files (GAZEBO_ROS_MODEL_PLUGIN).
#include "bullet_plant/registry.h"
#include "bullet_plant/robot_description.h"

namespace bullet_plant
{
namespace
{
// gazebo_ros_range, velodyne_simulator, gazebo_ros_block_laser and hector's sonar refuse to load on
// anything but a ray sensor.
std::string needsRaySensor(const SensorDescription& d)
{
  if (d.type == "ray" || d.type == "gpu_ray")
    return "";
  return d.plugin_filename + " needs a <sensor type=\"ray\"> or \"gpu_ray\" (\"requires a Ray Sensor as its parent\"), not '" +
         d.type + "'";
}

std::string needsContactSensor(const SensorDescription& d)
{
  if (d.type == "contact")
    return "";
  return "libgazebo_ros_bumper.so needs a <sensor type=\"contact\"> (\"Contact sensor parent is not of type "
         "ContactSensor\"), not '" + d.type + "'";
}

std::string imuSensorNeedsFrameName(const SensorDescription& d)
{
  if (d.type != "imu" || d.hasPluginParam("frameName"))
    return "";
  return "gazebo_ros_imu_sensor needs <frameName> (\"missing <frameName>, cannot proceed\")";
}

PluginFile sensorPlugin(PluginNaming naming, std::string (*refusal)(const SensorDescription&) = nullptr)
{
  PluginFile file;
  file.role = PluginRole::Sensor;
  file.naming = naming;
  file.refusal = refusal;
  return file;
}

PluginFile linkSensorPlugin(const std::string& sensor_type)
{
  PluginFile file;
  file.role = PluginRole::LinkSensor;
  file.sensor_type = sensor_type;
  return file;
}
}  // namespace

BULLET_PLANT_REGISTER(PluginFile, laser, sensorPlugin(PluginNaming::Default), "libgazebo_ros_laser.so",
                      "libgazebo_ros_gpu_laser.so");
BULLET_PLANT_REGISTER(PluginFile, camera, sensorPlugin(PluginNaming::Default), "libgazebo_ros_camera.so");
BULLET_PLANT_REGISTER(PluginFile, depth_camera, sensorPlugin(PluginNaming::DepthCamera), "libgazebo_ros_openni_kinect.so",
                      "libgazebo_ros_depth_camera.so");
BULLET_PLANT_REGISTER(PluginFile, multicamera, sensorPlugin(PluginNaming::MultiCamera), "libgazebo_ros_multicamera.so");
BULLET_PLANT_REGISTER(PluginFile, imu_sensor, sensorPlugin(PluginNaming::Default, imuSensorNeedsFrameName),
                      "libgazebo_ros_imu_sensor.so");
BULLET_PLANT_REGISTER(PluginFile, range, sensorPlugin(PluginNaming::Range, needsRaySensor), "libgazebo_ros_range.so");
BULLET_PLANT_REGISTER(PluginFile, velodyne, sensorPlugin(PluginNaming::Velodyne, needsRaySensor),
                      "libgazebo_ros_velodyne_laser.so", "libgazebo_ros_velodyne_gpu_laser.so");
BULLET_PLANT_REGISTER(PluginFile, block_laser, sensorPlugin(PluginNaming::BlockLaser, needsRaySensor),
                      "libgazebo_ros_block_laser.so");
BULLET_PLANT_REGISTER(PluginFile, hector_sonar, sensorPlugin(PluginNaming::HectorSonar, needsRaySensor),
                      "libhector_gazebo_ros_sonar.so");
BULLET_PLANT_REGISTER(PluginFile, bumper, sensorPlugin(PluginNaming::Default, needsContactSensor), "libgazebo_ros_bumper.so");
// Model plugins in Gazebo; here sensors of the link they follow, published by the node's plugins.
BULLET_PLANT_REGISTER(PluginFile, imu, linkSensorPlugin("imu"), "libgazebo_ros_imu.so");
BULLET_PLANT_REGISTER(PluginFile, p3d, linkSensorPlugin("p3d"), "libgazebo_ros_p3d.so");

}  // namespace bullet_plant
