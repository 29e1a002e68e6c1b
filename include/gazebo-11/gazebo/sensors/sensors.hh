// Gazebo's sensors library, as a plugin includes it whole.
#pragma once

#include "gazebo/sensors/AltimeterSensor.hh"
#include "gazebo/sensors/CameraSensor.hh"
#include "gazebo/sensors/ContactSensor.hh"
#include "gazebo/sensors/DepthCameraSensor.hh"
#include "gazebo/sensors/GaussianNoiseModel.hh"
#include "gazebo/sensors/GpsSensor.hh"
#include "gazebo/sensors/GpuRaySensor.hh"
#include "gazebo/sensors/ImuSensor.hh"
#include "gazebo/sensors/MagnetometerSensor.hh"
#include "gazebo/sensors/MultiCameraSensor.hh"
#include "gazebo/sensors/Noise.hh"
#include "gazebo/sensors/RaySensor.hh"
#include "gazebo/sensors/Sensor.hh"
#include "gazebo/sensors/SensorManager.hh"
#include "gazebo/sensors/SensorTypes.hh"
#include "gazebo/sensors/SensorsIface.hh"
