// The ROS-free half of gazebo_ros_triggered_camera: a camera sensor's images, named as
// gazebo_ros_camera's (sensor_plugin_file.h); its ROS half is
// src/node/sensor_plugins/gazebo_ros_triggered_camera.cpp.
#include "sensor_plugin_file.h"

namespace bullet_plant
{
GAZEBO_ROS_SENSOR_PLUGIN_FILE(camera, sensorPluginFile(PluginNaming::Default), "libgazebo_ros_triggered_camera.so");

}  // namespace bullet_plant
