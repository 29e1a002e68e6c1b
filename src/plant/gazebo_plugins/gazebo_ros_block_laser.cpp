// The ROS-free half of gazebo_ros_block_laser: a ray sensor's point cloud, named its own way
// (sensor_plugin_file.h); its ROS half is src/node/sensor_plugins/gazebo_ros_block_laser.cpp.
#include "sensor_plugin_file.h"

namespace bullet_plant
{
GAZEBO_ROS_SENSOR_PLUGIN_FILE(block_laser, sensorPluginFile(PluginNaming::BlockLaser, needsRaySensor),
                              "libgazebo_ros_block_laser.so");

}  // namespace bullet_plant
