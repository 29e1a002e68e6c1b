// The ROS-free half of gazebo_ros_laser and gazebo_ros_gpu_laser: a LaserScan of a ray sensor,
// named by its type's rules (sensor_plugin_file.h); its ROS half is
// src/node/sensor_plugins/gazebo_ros_laser.cpp.
#include "sensor_plugin_file.h"

namespace bullet_plant
{
GAZEBO_ROS_SENSOR_PLUGIN_FILE(laser, sensorPluginFile(PluginNaming::Default), "libgazebo_ros_laser.so",
                              "libgazebo_ros_gpu_laser.so");

}  // namespace bullet_plant
