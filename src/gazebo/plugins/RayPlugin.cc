// Gazebo 11's RayPlugin (gazebo/plugins/RayPlugin.hh).
#include "gazebo/plugins/RayPlugin.hh"

#include "gazebo/common/Exception.hh"
#include "gazebo/physics/PhysicsIface.hh"
#include "gazebo/physics/World.hh"

namespace gazebo
{
GZ_REGISTER_SENSOR_PLUGIN(RayPlugin)

RayPlugin::RayPlugin() = default;

RayPlugin::~RayPlugin()
{
  newLaserScansConnection.reset();
  parentSensor.reset();
  world.reset();
}

void RayPlugin::OnNewLaserScans() {}

void RayPlugin::Load(sensors::SensorPtr _parent, sdf::ElementPtr /*_sdf*/)
{
  parentSensor = std::dynamic_pointer_cast<sensors::RaySensor>(_parent);
  if (!parentSensor)
    gzthrow("RayPlugin requires a Ray Sensor as its parent");
  world = physics::get_world(parentSensor->WorldName());
  newLaserScansConnection = parentSensor->LaserShape()->ConnectNewLaserScans([this] { OnNewLaserScans(); });
}
}  // namespace gazebo
