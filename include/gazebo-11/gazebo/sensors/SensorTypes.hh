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
class AltimeterSensor;
class MagnetometerSensor;
class GpsSensor;
class ForceTorqueSensor;
class SonarSensor;
class Noise;
class GaussianNoiseModel;
typedef std::shared_ptr<Sensor> SensorPtr;
typedef std::shared_ptr<RaySensor> RaySensorPtr;
typedef std::shared_ptr<CameraSensor> CameraSensorPtr;
typedef std::shared_ptr<ContactSensor> ContactSensorPtr;
typedef std::shared_ptr<DepthCameraSensor> DepthCameraSensorPtr;
typedef std::shared_ptr<GpuRaySensor> GpuRaySensorPtr;
typedef std::shared_ptr<ImuSensor> ImuSensorPtr;
typedef std::shared_ptr<MultiCameraSensor> MultiCameraSensorPtr;
typedef std::shared_ptr<AltimeterSensor> AltimeterSensorPtr;
typedef std::shared_ptr<MagnetometerSensor> MagnetometerSensorPtr;
typedef std::shared_ptr<GpsSensor> GpsSensorPtr;
typedef std::shared_ptr<ForceTorqueSensor> ForceTorqueSensorPtr;
typedef std::shared_ptr<SonarSensor> SonarSensorPtr;
typedef std::shared_ptr<Noise> NoisePtr;
typedef std::shared_ptr<GaussianNoiseModel> GaussianNoiseModelPtr;
typedef std::vector<SensorPtr> Sensor_V;

// What Gazebo 11 casts sensor handles with (std::shared_ptr's).
#define GAZEBO_SENSORS_USING_DYNAMIC_POINTER_CAST using std::dynamic_pointer_cast

// Which of a sensor's noise models (Sensor::Noise), as Gazebo 11 numbers them.
enum SensorNoiseType
{
  SENSOR_NOISE_TYPE_BEGIN = 0,
  NO_NOISE = SENSOR_NOISE_TYPE_BEGIN,
  CAMERA_NOISE = 1,
  GPU_RAY_NOISE = 2,
  GPS_POSITION_LATITUDE_NOISE_METERS = 3,
  GPS_POSITION_LONGITUDE_NOISE_METERS = 4,
  GPS_POSITION_ALTITUDE_NOISE_METERS = 5,
  GPS_VELOCITY_LATITUDE_NOISE_METERS = 6,
  GPS_VELOCITY_LONGITUDE_NOISE_METERS = 7,
  GPS_VELOCITY_ALTITUDE_NOISE_METERS = 8,
  RAY_NOISE = 9,
  MAGNETOMETER_X_NOISE_TESLA = 10,
  MAGNETOMETER_Y_NOISE_TESLA = 11,
  MAGNETOMETER_Z_NOISE_TESLA = 12,
  ALTIMETER_POSITION_NOISE_METERS = 13,
  ALTIMETER_VELOCITY_NOISE_METERS_PER_S = 14,
  IMU_ANGVEL_X_NOISE_RADIANS_PER_S = 15,
  IMU_ANGVEL_Y_NOISE_RADIANS_PER_S = 16,
  IMU_ANGVEL_Z_NOISE_RADIANS_PER_S = 17,
  IMU_LINACC_X_NOISE_METERS_PER_S_SQR = 18,
  IMU_LINACC_Y_NOISE_METERS_PER_S_SQR = 19,
  IMU_LINACC_Z_NOISE_METERS_PER_S_SQR = 20,
  SENSOR_NOISE_TYPE_END
};

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
