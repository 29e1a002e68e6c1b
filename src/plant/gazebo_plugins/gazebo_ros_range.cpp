// The ROS-free half of gazebo_ros_range: a ray sensor's nearest ray as a sensor_msgs/Range, named
// its own way (sensor_plugin_file.h); its ROS half is src/node/sensor_plugins/gazebo_ros_range.cpp.
#include "sensor_plugin_file.h"

namespace bullet_plant
{
GAZEBO_ROS_SENSOR_PLUGIN_FILE(range, sensorPluginFile(PluginNaming::Range, needsRaySensor), "libgazebo_ros_range.so");

}  // namespace bullet_plant
