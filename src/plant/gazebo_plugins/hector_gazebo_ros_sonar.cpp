// The ROS-free half of hector_gazebo_plugins' sonar: a ray sensor's nearest ray as a
// sensor_msgs/Range, named its own way (sensor_plugin_file.h); its ROS half is
// src/node/sensor_plugins/hector_gazebo_ros_sonar.cpp.
#include "sensor_plugin_file.h"

namespace bullet_plant
{
GAZEBO_ROS_SENSOR_PLUGIN_FILE(hector_sonar, sensorPluginFile(PluginNaming::HectorSonar, needsRaySensor),
                              "libhector_gazebo_ros_sonar.so");

}  // namespace bullet_plant
