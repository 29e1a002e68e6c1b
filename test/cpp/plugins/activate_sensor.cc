// A sensor plugin of the tests' own (libtest_activate_sensor.so): it sets its sensor active in Load,
// as gazebo_ros_pkgs' MultiCameraPlugin does, for the sensor types Gazebo ships no plugin library
// of its own for (test_gazebo_multicamera_sensor.cpp).
#include <gazebo/common/Plugin.hh>
#include <gazebo/sensors/Sensor.hh>

namespace gazebo
{
class ActivateSensor : public SensorPlugin
{
public:
  void Load(sensors::SensorPtr sensor, sdf::ElementPtr /*sdf*/) override { sensor->SetActive(true); }
};
GZ_REGISTER_SENSOR_PLUGIN(ActivateSensor)
}  // namespace gazebo
