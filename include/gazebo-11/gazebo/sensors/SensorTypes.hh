// The sensor classes' names and handle types, as Gazebo 11 declares them (std::shared_ptr
// handles): what common/Plugin.hh's SensorPlugin needs to name a SensorPtr.
#pragma once

#include <memory>
#include <vector>

namespace gazebo
{
namespace sensors
{
class Sensor;
typedef std::shared_ptr<Sensor> SensorPtr;
typedef std::vector<SensorPtr> Sensor_V;
}  // namespace sensors
}  // namespace gazebo
