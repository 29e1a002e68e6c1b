// Gazebo 11's RayPlugin (libRayPlugin.so), the sensor plugin gazebo_ros_pkgs' gazebo_ros_laser,
// gazebo_ros_range and gazebo_ros_block_laser derive from: on a RaySensor (anything else throws,
// as Gazebo's), OnNewLaserScans called after each scan its sensor makes.
#pragma once

#include <sdf/sdf.hh>

#include "gazebo/common/Plugin.hh"
#include "gazebo/physics/PhysicsTypes.hh"
#include "gazebo/sensors/RaySensor.hh"
#include "gazebo/sensors/SensorTypes.hh"
#include "gazebo/util/system.hh"

namespace gazebo
{
class GZ_PLUGIN_VISIBLE RayPlugin : public SensorPlugin
{
public:
  RayPlugin();
  virtual ~RayPlugin();
  // After each scan (a derived plugin's; nothing here).
  virtual void OnNewLaserScans();
  void Load(sensors::SensorPtr _parent, sdf::ElementPtr _sdf);

protected:
  physics::WorldPtr world;

private:
  sensors::RaySensorPtr parentSensor;
  event::ConnectionPtr newLaserScansConnection;
};
}  // namespace gazebo
