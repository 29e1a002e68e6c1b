// sensors::SensorManager: the process's sensors, as Gazebo 11's singleton, by name: plugins find a
// sensor of their model with SensorManager::Instance()->GetSensor(name) (or sensors::get_sensor).
// The simulator adds each Gazebo sensor it makes and removes it with its model; it updates them
// after each physics step (Gazebo's sensor threads: docs/gazebo_api.md).
#pragma once

#include <mutex>
#include <string>
#include <vector>

#include "gazebo/sensors/SensorTypes.hh"
#include "gazebo/util/system.hh"

namespace gazebo
{
namespace sensors
{
class GZ_SENSORS_VISIBLE SensorManager
{
public:
  static SensorManager* Instance();

  // By its scoped name (WORLD::MODEL::LINK::SENSOR), else by its own name where one sensor has it;
  // null with an error where several do, null for none.
  SensorPtr GetSensor(const std::string& name) const;
  Sensor_V GetSensors() const;
  // The sensor types the simulator makes ("ray" ...).
  void GetSensorTypes(std::vector<std::string>& types) const;
  // Each sensor has been loaded and initialized before it is added: true.
  bool SensorsInitialized() { return true; }
  void ResetLastUpdateTimes();

  // The simulator's: a sensor it made and loaded, and gone with its model (Fini called).
  void AddSensor(SensorPtr sensor);
  void RemoveSensor(const std::string& scopedName);
  void RemoveSensors();

private:
  SensorManager() = default;
  mutable std::mutex mutex_;
  Sensor_V sensors_;
};
}  // namespace sensors
}  // namespace gazebo
