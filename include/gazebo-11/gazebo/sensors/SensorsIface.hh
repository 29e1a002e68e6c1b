// The sensors library's free functions plugins call (Gazebo 11's SensorsIface.hh).
#pragma once

#include <string>

#include "gazebo/sensors/SensorTypes.hh"
#include "gazebo/util/system.hh"

namespace gazebo
{
namespace sensors
{
// SensorManager::Instance()->GetSensor(name).
GZ_SENSORS_VISIBLE SensorPtr get_sensor(const std::string& name);
}  // namespace sensors
}  // namespace gazebo
