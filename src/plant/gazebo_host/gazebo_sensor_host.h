// Gazebo's sensors over the plant's (gazebo/sensors/SensorBridge.hh), for the sensor plugins of
// the user's own: a <sensor> whose <plugin> file was found on the plugin paths gets a
// sensors::Sensor of its type (RaySensor for "ray"), added to SensorManager, over the plant's one
// simulation of that sensor; then the plugin is made from its file, Load(sensor, its <plugin>
// element) and Init, as Gazebo's. After each step the plant's new readings become the Gazebo
// sensors' (their messages and events), and each sensor's IsActive decides whether the plant
// measures next step. Owned by the world's host (gazebo_world_host.h).
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <gazebo/common/Plugin.hh>
#include <gazebo/sensors/Sensor.hh>

#include "bullet_plant/robot_description.h"

namespace bullet_plant
{
class Log;
class ModelPluginContext;
class PlantGazeboHost;
class Sensor;

class GazeboSensorHost
{
public:
  explicit GazeboSensorHost(PlantGazeboHost& host) : host_(host) {}
  ~GazeboSensorHost();

  // `plant`: the plant's simulation of the <sensor> (one sensor; a multicamera's cameras in their
  // order, `d` the first one's description). False, with the error naming the sensor, the file and
  // why, where the plugin cannot be loaded (a sensor type without a Gazebo sensor here, a file that
  // is not a sensor plugin, a Load that throws); the robot runs, the sensor measuring nothing for it.
  bool load(const SensorDescription& d, const std::vector<Sensor*>& plant, ModelPluginContext& model);
  // After each step's sensors: new readings to the Gazebo sensors, the render events where an image
  // sensor is hosted (event::Events::preRender ...), then activity back to the plant.
  void update();
  // reset_world / reset_simulation: the plugins' Reset, the sensors' last update times.
  void reset();
  // The model left the world: its sensor plugins, then its sensors, go.
  void modelRemoved(const std::string& model);

private:
  struct Hosted
  {
    std::string model;
    std::vector<Sensor*> plant;
    std::vector<uint64_t> readings_seen;  // each plant sensor's updates() when last handed over
    gazebo::sensors::SensorPtr sensor;
    gazebo::SensorPlugin::TPtr plugin;
    sdf::ElementPtr document;  // the elements' ancestors, for GetParent()
  };
  // Whether each of its plant sensors has measured since the last hand-over (counted as seen).
  static bool takeNewReadings(Hosted& hosted);
  // What the plant's sensors measure at the next step the rate allows: while the Gazebo sensor is
  // active; a camera rendering every step renders its next frame once the last was handed over.
  static void handActivityBack(Hosted& hosted);
  void remove(Hosted& hosted);
  PlantGazeboHost& host_;
  std::vector<Hosted> hosted_;
};
}  // namespace bullet_plant
