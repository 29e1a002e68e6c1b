// The ROS-free half of gazebo_ros_imu_sensor, inside an imu sensor, and gazebo_ros_imu, a model
// plugin following its <bodyName>, described as an imu sensor of that link (sensor_plugin_file.h);
// its ROS half is src/node/sensor_plugins/gazebo_ros_imu.cpp.
#include "sensor_plugin_file.h"

namespace bullet_plant
{
namespace
{
std::string imuSensorNeedsFrameName(const SensorDescription& d)
{
  if (d.type != "imu" || d.hasPluginParam("frameName"))
    return "";
  return "gazebo_ros_imu_sensor needs <frameName> (\"missing <frameName>, cannot proceed\")";
}
}  // namespace

GAZEBO_ROS_SENSOR_PLUGIN_FILE(imu_sensor, sensorPluginFile(PluginNaming::Default, imuSensorNeedsFrameName),
                              "libgazebo_ros_imu_sensor.so");
GAZEBO_ROS_SENSOR_PLUGIN_FILE(imu, linkSensorPluginFile("imu"), "libgazebo_ros_imu.so");

}  // namespace bullet_plant
