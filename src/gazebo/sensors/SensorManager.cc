// sensors::SensorManager and get_sensor (gazebo/sensors/SensorManager.hh, SensorsIface.hh).
#include "gazebo/sensors/SensorManager.hh"

#include <algorithm>

#include "gazebo/common/Console.hh"
#include "gazebo/sensors/Sensor.hh"
#include "gazebo/sensors/SensorsIface.hh"

namespace gazebo
{
namespace sensors
{
SensorManager* SensorManager::Instance()
{
  static SensorManager manager;
  return &manager;
}

SensorPtr SensorManager::GetSensor(const std::string& name) const
{
  std::lock_guard<std::mutex> lock(mutex_);
  for (const SensorPtr& sensor : sensors_)
    if (sensor->ScopedName() == name)
      return sensor;
  SensorPtr found;
  for (const SensorPtr& sensor : sensors_)
    if (sensor->Name() == name)
    {
      if (found)
      {
        gzerr << "Unable to get a sensor, multiple sensors with the same name[" << name
              << "]. Use a scoped name instead, world_name::model_name::link_name::sensor_name.\n";
        return SensorPtr();
      }
      found = sensor;
    }
  return found;
}

Sensor_V SensorManager::GetSensors() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return sensors_;
}

void SensorManager::GetSensorTypes(std::vector<std::string>& types) const { types = {"ray"}; }

void SensorManager::ResetLastUpdateTimes()
{
  for (const SensorPtr& sensor : GetSensors())
    sensor->ResetLastUpdateTime();
}

void SensorManager::AddSensor(SensorPtr sensor)
{
  std::lock_guard<std::mutex> lock(mutex_);
  sensors_.push_back(std::move(sensor));
}

void SensorManager::RemoveSensor(const std::string& scopedName)
{
  SensorPtr removed;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    auto it = std::find_if(sensors_.begin(), sensors_.end(),
                           [&](const SensorPtr& s) { return s->ScopedName() == scopedName; });
    if (it == sensors_.end())
      return;
    removed = *it;
    sensors_.erase(it);
  }
  removed->Fini();
}

void SensorManager::RemoveSensors()
{
  Sensor_V removed;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    removed.swap(sensors_);
  }
  for (const SensorPtr& sensor : removed)
    sensor->Fini();
}

SensorPtr get_sensor(const std::string& name) { return SensorManager::Instance()->GetSensor(name); }
}  // namespace sensors
}  // namespace gazebo
