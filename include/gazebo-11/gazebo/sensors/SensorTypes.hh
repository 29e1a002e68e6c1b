// The sensor classes' names, handle types and categories, as Gazebo 11 declares them (std::shared_ptr
// handles): what common/Plugin.hh's SensorPlugin and sensors/Sensor.hh name.
#pragma once

#include <memory>
#include <vector>

namespace gazebo
{
namespace sensors
{
class Sensor;
class RaySensor;
class CameraSensor;
class ContactSensor;
class DepthCameraSensor;
class GpuRaySensor;
class ImuSensor;
class MultiCameraSensor;
typedef std::shared_ptr<Sensor> SensorPtr;
typedef std::shared_ptr<RaySensor> RaySensorPtr;
typedef std::shared_ptr<CameraSensor> CameraSensorPtr;
typedef std::shared_ptr<ContactSensor> ContactSensorPtr;
typedef std::shared_ptr<DepthCameraSensor> DepthCameraSensorPtr;
typedef std::shared_ptr<GpuRaySensor> GpuRaySensorPtr;
typedef std::shared_ptr<ImuSensor> ImuSensorPtr;
typedef std::shared_ptr<MultiCameraSensor> MultiCameraSensorPtr;
typedef std::vector<SensorPtr> Sensor_V;

// What Gazebo 11 casts sensor handles with (std::shared_ptr's).
#define GAZEBO_SENSORS_USING_DYNAMIC_POINTER_CAST using std::dynamic_pointer_cast

// Gazebo updates the sensors of each category in a thread of their own.
enum SensorCategory
{
  IMAGE = 0,  // needs the rendering engine
  RAY = 1,
  OTHER = 2,
  CATEGORY_COUNT = 3
};
}  // namespace sensors
}  // namespace gazebo
