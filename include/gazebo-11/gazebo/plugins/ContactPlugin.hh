// Gazebo 11's ContactPlugin (libContactPlugin.so), which gazebo_ros_pkgs' gazebo_ros_bumper links:
// on a ContactSensor (anything else: Gazebo's error, and nothing more), its sensor set active and
// OnUpdate called after each of its measurements.
#pragma once

#include <sdf/sdf.hh>

#include "gazebo/common/Plugin.hh"
#include "gazebo/sensors/ContactSensor.hh"
#include "gazebo/sensors/SensorTypes.hh"
#include "gazebo/util/system.hh"

namespace gazebo
{
class GZ_PLUGIN_VISIBLE ContactPlugin : public SensorPlugin
{
public:
  ContactPlugin();
  virtual ~ContactPlugin();
  virtual void Load(sensors::SensorPtr _sensor, sdf::ElementPtr _sdf);

private:
  // After each measurement (a derived plugin's; nothing here).
  virtual void OnUpdate();
  sensors::ContactSensorPtr parentSensor;
  event::ConnectionPtr updateConnection;
};
}  // namespace gazebo
