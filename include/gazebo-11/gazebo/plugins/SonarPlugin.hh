// Gazebo 11's SonarPlugin (libSonarPlugin.so), the base of sonar sensor plugins: on a SonarSensor
// (else Gazebo's exception), OnUpdate called with each of its sensor's measurements.
#pragma once

#include <sdf/sdf.hh>

#include "gazebo/common/Plugin.hh"
#include "gazebo/sensors/SensorTypes.hh"
#include "gazebo/sensors/SonarSensor.hh"
#include "gazebo/util/system.hh"

namespace gazebo
{
class GZ_PLUGIN_VISIBLE SonarPlugin : public SensorPlugin
{
public:
  SonarPlugin();
  virtual ~SonarPlugin();
  void Load(sensors::SensorPtr _parent, sdf::ElementPtr _sdf);

protected:
  // Each measurement (a derived plugin's; nothing here).
  virtual void OnUpdate(msgs::SonarStamped _msg);
  sensors::SonarSensorPtr parentSensor;

private:
  event::ConnectionPtr connection;
};
}  // namespace gazebo
