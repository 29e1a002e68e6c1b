// Gazebo 11's ForceTorquePlugin (libForceTorquePlugin.so), the base of force-torque sensor plugins:
// on a ForceTorqueSensor (else Gazebo's error, and nothing), OnUpdate called with each of its
// sensor's measurements.
#pragma once

#include <sdf/sdf.hh>

#include "gazebo/common/Events.hh"
#include "gazebo/common/Plugin.hh"
#include "gazebo/sensors/sensors.hh"
#include "gazebo/util/system.hh"

namespace gazebo
{
class GZ_PLUGIN_VISIBLE ForceTorquePlugin : public SensorPlugin
{
public:
  ForceTorquePlugin();
  virtual ~ForceTorquePlugin();
  virtual void Load(sensors::SensorPtr _parent, sdf::ElementPtr _sdf);

protected:
  // Each measurement (a derived plugin's; nothing here).
  virtual void OnUpdate(msgs::WrenchStamped _msg);
  sensors::ForceTorqueSensorPtr parentSensor;

private:
  event::ConnectionPtr connection;
};
}  // namespace gazebo
