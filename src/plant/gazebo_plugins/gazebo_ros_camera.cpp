// The ROS-free half of gazebo_ros_camera: a camera sensor's images, named by its type's rules
// (sensor_plugin_file.h); its ROS half is src/node/sensor_plugins/gazebo_ros_camera.cpp.
#include "sensor_plugin_file.h"

namespace bullet_plant
{
GAZEBO_ROS_SENSOR_PLUGIN_FILE(camera, sensorPluginFile(PluginNaming::Default), "libgazebo_ros_camera.so");

}  // namespace bullet_plant
