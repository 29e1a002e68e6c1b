// Gazebo 11's ForceTorquePlugin (gazebo/plugins/ForceTorquePlugin.hh).
#include "gazebo/plugins/ForceTorquePlugin.hh"

#include "gazebo/common/Console.hh"

namespace gazebo
{
GZ_REGISTER_SENSOR_PLUGIN(ForceTorquePlugin)

ForceTorquePlugin::ForceTorquePlugin() = default;

ForceTorquePlugin::~ForceTorquePlugin()
{
  connection.reset();
  parentSensor.reset();
}

void ForceTorquePlugin::Load(sensors::SensorPtr _parent, sdf::ElementPtr /*_sdf*/)
{
  parentSensor = std::dynamic_pointer_cast<sensors::ForceTorqueSensor>(_parent);
  if (!parentSensor)
  {
    gzerr << "ForceTorquePlugin requires a force_torque sensor as its parent.\n";
    return;
  }
  connection = parentSensor->ConnectUpdate([this](msgs::WrenchStamped message) { OnUpdate(message); });
}

void ForceTorquePlugin::OnUpdate(msgs::WrenchStamped /*_msg*/) {}
}  // namespace gazebo
