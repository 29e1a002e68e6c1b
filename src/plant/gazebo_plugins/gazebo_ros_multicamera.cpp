// The ROS-free half of gazebo_ros_multicamera: its topics under <cameraName>/left and /right
// (sensor_plugin_file.h); its ROS half is src/node/sensor_plugins/gazebo_ros_multicamera.cpp.
#include "sensor_plugin_file.h"

namespace bullet_plant
{
GAZEBO_ROS_SENSOR_PLUGIN_FILE(multicamera, sensorPluginFile(PluginNaming::MultiCamera), "libgazebo_ros_multicamera.so");

}  // namespace bullet_plant
