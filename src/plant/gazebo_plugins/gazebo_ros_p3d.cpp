// The ROS-free half of gazebo_ros_p3d: a model plugin following its <bodyName>, described as a p3d
// sensor of that link (sensor_plugin_file.h); its ROS half is
// src/node/sensor_plugins/gazebo_ros_p3d.cpp.
#include "sensor_plugin_file.h"

namespace bullet_plant
{
GAZEBO_ROS_SENSOR_PLUGIN_FILE(p3d, linkSensorPluginFile("p3d"), "libgazebo_ros_p3d.so");

}  // namespace bullet_plant
