// The ROS-free half of gazebo_ros_openni_kinect and gazebo_ros_depth_camera: named as a camera's
// (upstream's infrared image defaults are overwritten by GazeboRosCameraUtils::Load; plugin_names.cpp)
// (sensor_plugin_file.h); its ROS half is src/node/sensor_plugins/gazebo_ros_openni_kinect.cpp.
#include "sensor_plugin_file.h"

namespace bullet_plant
{
GAZEBO_ROS_SENSOR_PLUGIN_FILE(depth_camera, sensorPluginFile(PluginNaming::Default), "libgazebo_ros_openni_kinect.so",
                              "libgazebo_ros_depth_camera.so");

}  // namespace bullet_plant
