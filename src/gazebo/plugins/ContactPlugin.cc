// Gazebo 11's ContactPlugin (gazebo/plugins/ContactPlugin.hh).
#include "gazebo/plugins/ContactPlugin.hh"

#include "gazebo/common/Console.hh"

namespace gazebo
{
GZ_REGISTER_SENSOR_PLUGIN(ContactPlugin)

ContactPlugin::ContactPlugin() = default;

ContactPlugin::~ContactPlugin() = default;

void ContactPlugin::Load(sensors::SensorPtr _sensor, sdf::ElementPtr /*_sdf*/)
{
  parentSensor = std::dynamic_pointer_cast<sensors::ContactSensor>(_sensor);
  if (!parentSensor)
  {
    gzerr << "ContactPlugin requires a ContactSensor.\n";
    return;
  }
  updateConnection = parentSensor->ConnectUpdated([this] { OnUpdate(); });
  parentSensor->SetActive(true);
}

void ContactPlugin::OnUpdate() {}
}  // namespace gazebo
