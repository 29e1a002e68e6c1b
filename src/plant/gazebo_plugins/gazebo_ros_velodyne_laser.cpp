// The ROS-free half of velodyne_simulator's gazebo_ros_velodyne_(gpu_)laser: a ray sensor's point
// cloud, named its own way (sensor_plugin_file.h); its ROS half is
// src/node/sensor_plugins/gazebo_ros_velodyne_laser.cpp.
#include "sensor_plugin_file.h"

namespace bullet_plant
{
GAZEBO_ROS_SENSOR_PLUGIN_FILE(velodyne, sensorPluginFile(PluginNaming::Velodyne, needsRaySensor),
                              "libgazebo_ros_velodyne_laser.so", "libgazebo_ros_velodyne_gpu_laser.so");

}  // namespace bullet_plant
