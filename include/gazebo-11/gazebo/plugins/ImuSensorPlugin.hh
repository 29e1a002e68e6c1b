// Gazebo 11's ImuSensorPlugin (libImuSensorPlugin.so), the base of IMU sensor plugins: on an
// ImuSensor whose parent is a link (else Gazebo's exceptions), OnUpdate called after each of its
// sensor's measurements.
#pragma once

#include <sdf/sdf.hh>

#include "gazebo/common/Plugin.hh"
#include "gazebo/physics/PhysicsTypes.hh"
#include "gazebo/sensors/ImuSensor.hh"
#include "gazebo/sensors/SensorTypes.hh"
#include "gazebo/util/system.hh"

namespace gazebo
{
class GZ_PLUGIN_VISIBLE ImuSensorPlugin : public SensorPlugin
{
public:
  ImuSensorPlugin();
  virtual ~ImuSensorPlugin();
  virtual void Load(sensors::SensorPtr _parent, sdf::ElementPtr _sdf);

protected:
  // After each measurement (a derived plugin's; nothing here).
  virtual void OnUpdate(sensors::ImuSensorPtr _sensor);
  sensors::ImuSensorPtr parentSensor;

private:
  event::ConnectionPtr connection;
  physics::WorldPtr world;
  physics::LinkPtr link;
};
}  // namespace gazebo
