// The ROS-free half of gazebo_ros_bumper: a contact sensor's ContactsState, named by its type's
// rules (sensor_plugin_file.h); its ROS half is src/node/sensor_plugins/gazebo_ros_bumper.cpp.
#include "sensor_plugin_file.h"

namespace bullet_plant
{
namespace
{
std::string needsContactSensor(const SensorDescription& d)
{
  if (d.type == "contact")
    return "";
  return "libgazebo_ros_bumper.so needs a <sensor type=\"contact\"> (\"Contact sensor parent is not of type "
         "ContactSensor\"), not '" + d.type + "'";
}
}  // namespace

GAZEBO_ROS_SENSOR_PLUGIN_FILE(bumper, sensorPluginFile(PluginNaming::Default, needsContactSensor), "libgazebo_ros_bumper.so");

}  // namespace bullet_plant
