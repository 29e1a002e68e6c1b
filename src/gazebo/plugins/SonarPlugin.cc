// Gazebo 11's SonarPlugin (gazebo/plugins/SonarPlugin.hh).
#include "gazebo/plugins/SonarPlugin.hh"

#include "gazebo/common/Exception.hh"

namespace gazebo
{
GZ_REGISTER_SENSOR_PLUGIN(SonarPlugin)

SonarPlugin::SonarPlugin() = default;

SonarPlugin::~SonarPlugin()
{
  connection.reset();
  parentSensor.reset();
}

void SonarPlugin::Load(sensors::SensorPtr _parent, sdf::ElementPtr /*_sdf*/)
{
  parentSensor = std::dynamic_pointer_cast<sensors::SonarSensor>(_parent);
  if (!parentSensor)
    gzthrow("SonarPlugin requires a sonar sensor as its parent.");
  connection = parentSensor->ConnectUpdate([this](msgs::SonarStamped message) { OnUpdate(message); });
}

void SonarPlugin::OnUpdate(msgs::SonarStamped /*_msg*/) {}
}  // namespace gazebo
