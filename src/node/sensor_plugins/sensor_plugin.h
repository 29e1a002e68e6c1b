// A gazebo_ros sensor plugin on the plant, shaped as gazebo_plugins' own: Load() takes the plant's
// sensor (its <plugin> block parsed at spawn) and advertises the plugin's topics in its namespace,
// named by the rules of plugin_names.h;
// OnUpdate() runs after each step (simTimeNs() is the step's time) and publishes what the sensor
// computed since the last call (the sensor itself keeps <update_rate>: Sensor::due). A plugin
// registers itself under its library's file names with GAZEBO_ROS_SENSOR_PLUGIN in its own file; its
// ROS-free half (the <sensor> it loads in, its naming rules), which the plant and Python read too, is
// its file of the same name in src/plant/gazebo_plugins/. Everything runs on the simulation thread;
// what a plugin publishes goes through the plant's outbox (outbox.h), which publishing threads empty.
#pragma once

#include <cmath>
#include <cstdlib>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <ros/ros.h>

#include "counted_publisher.h"
#include "outbox.h"
#include "bullet_plant/gaussian_kernel.h"
#include "bullet_plant/plugin_names.h"
#include "bullet_plant/registry.h"
#include "ros_names.h"
#include "bullet_plant/robot.h"
#include "bullet_plant/sensors.h"

namespace bullet_plant
{
class SensorPlugin
{
public:
  virtual ~SensorPlugin() = default;
  virtual void Load(Sensor& sensor) = 0;
  // Whether anyone subscribes to one of its topics: the sensor computes only then.
  virtual bool subscribed() const = 0;
  virtual void OnUpdate() = 0;

  // The plugin for `sensor`'s <plugin filename>; null for a sensor without one, or with a file no
  // plugin registered (the plant warned about that at spawn).
  // `robot` is the model it belongs to: its name and spawn namespace name the plugin's namespace.
  // `step_size` is the world's step (s); `outbox` where its messages go.
  static std::unique_ptr<SensorPlugin> create(Sensor& sensor, const Robot& robot, double step_size, Outbox& outbox);

  // After each step at simulated time `time_ns`: OnUpdate with simTimeNs() set.
  void update(int64_t time_ns)
  {
    sim_time_ns_ = time_ns;
    OnUpdate();
  }

protected:
  int64_t simTimeNs() const { return sim_time_ns_; }
  double stepSize() const { return step_size_; }
  // Where the plugin's messages go: outbox().publish(publisher, message).
  Outbox& outbox() const { return *outbox_; }
  // The plugin's namespace (pluginNamespace), set before Load.
  const std::string& robotNamespace() const { return namespace_; }
  // The node handle of the plugin, in its namespace.
  ros::NodeHandle nodeHandle(const Sensor& sensor) const;
  // tf::getPrefixParam, as the laser and camera plugins call it: a tf_prefix parameter found by
  // searching up from `nh`'s namespace; "" where there is none (gazebo_ros_pkgs 2.9.2).
  static std::string searchedTfPrefix(const ros::NodeHandle& nh);
  // True once per update of the sensor: whether it computed something since the last call.
  bool takeUpdate(const Sensor& sensor);

private:
  std::string namespace_;
  uint64_t seen_updates_ = 0;
  int64_t sim_time_ns_ = 0;
  double step_size_ = 0.001;
  Outbox* outbox_ = nullptr;
};

// The publisher of a plugin's point cloud topic, or none for an empty <topicName>: upstream
// advertises nothing then (velodyne_simulator, gazebo_ros_block_laser).
template <class Msg>
CountedPublisher advertiseUnlessEmpty(ros::NodeHandle& nh, const Sensor& sensor, const std::string& topic, uint32_t queue)
{
  if (topic.empty())
    return CountedPublisher();
  return CountedPublisher::advertise<Msg>(nh, requireValidRosName(topic, "sensor '" + sensor.name() + "' topicName"), queue);
}

using SensorPluginFactory = std::function<std::unique_ptr<SensorPlugin>()>;

}  // namespace bullet_plant

// In a plugin's .cpp, as GZ_REGISTER_SENSOR_PLUGIN in Gazebo: `Class` made for each of the plugin
// files that follow (libgazebo_ros_*.so). What the description makes of those files is their
// ROS-free half (src/plant/gazebo_plugins/, GAZEBO_ROS_SENSOR_PLUGIN_FILE).
#define GAZEBO_ROS_SENSOR_PLUGIN(Class, ...)                                                                         \
  BULLET_PLANT_REGISTER(                                                                                             \
      ::bullet_plant::SensorPluginFactory, Class,                                                                    \
      [] { return std::unique_ptr<::bullet_plant::SensorPlugin>(new Class()); }, __VA_ARGS__)

namespace bullet_plant
{
// A Sensor as the plugin's type: the plant builds the sensor class from the same file name, so a
// mismatch is a bug, reported by naming both.
template <class SensorType>
SensorType& sensorAs(Sensor& sensor, const char* plugin)
{
  if (auto* typed = dynamic_cast<SensorType*>(&sensor))
    return *typed;
  throw std::logic_error(std::string(plugin) + " loaded on sensor '" + sensor.name() + "' of type '" +
                         sensor.description().type + "', which the plant did not build for it");
}

}  // namespace bullet_plant
