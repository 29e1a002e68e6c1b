// Gazebo 11's ImuSensorPlugin (gazebo/plugins/ImuSensorPlugin.hh).
#include "gazebo/plugins/ImuSensorPlugin.hh"

#include "gazebo/common/Exception.hh"
#include "gazebo/physics/Link.hh"
#include "gazebo/physics/PhysicsIface.hh"
#include "gazebo/physics/World.hh"

namespace gazebo
{
GZ_REGISTER_SENSOR_PLUGIN(ImuSensorPlugin)

ImuSensorPlugin::ImuSensorPlugin() = default;

ImuSensorPlugin::~ImuSensorPlugin()
{
  connection.reset();
  parentSensor.reset();
}

void ImuSensorPlugin::Load(sensors::SensorPtr _parent, sdf::ElementPtr /*_sdf*/)
{
  parentSensor = std::dynamic_pointer_cast<sensors::ImuSensor>(_parent);
  world = physics::get_world(_parent->WorldName());
  link = boost::dynamic_pointer_cast<physics::Link>(world->EntityByName(_parent->ParentName()));
  if (!link)
    gzthrow("Imu sensor parent is not a Link.");
  if (!parentSensor)
    gzthrow("ImuSensorPlugin requires a imu sensor as its parent.");
  const sensors::ImuSensorPtr sensor = parentSensor;
  connection = parentSensor->ConnectUpdated([this, sensor] { OnUpdate(sensor); });
}

void ImuSensorPlugin::OnUpdate(sensors::ImuSensorPtr /*_sensor*/) {}
}  // namespace gazebo
