// What the sensors that read their link's motion (AltimeterSensor, MagnetometerSensor, GpsSensor)
// share, as Gazebo 11 spells it in each: their topic, their link and their noise models (which
// ImuSensor reads and applies the same way). Private to the library.
#pragma once

#include <map>
#include <string>

#include <boost/algorithm/string/replace.hpp>
#include <sdf/sdf.hh>

#include "gazebo/common/Console.hh"
#include "gazebo/physics/Link.hh"
#include "gazebo/physics/World.hh"
#include "gazebo/sensors/Noise.hh"
#include "gazebo/sensors/SensorTypes.hh"

namespace gazebo
{
namespace sensors
{
namespace detail
{
// ~/PARENT/SENSOR, and /<topic> where the <sensor> has one ("::" made "/")
inline std::string linkSensorTopic(const std::string& parent, const std::string& name, const sdf::ElementPtr& sdf)
{
  std::string topic = "~/" + parent + '/' + name;
  if (sdf->HasElement("topic") && sdf->Get<std::string>("topic") != "__default__")
    topic += '/' + sdf->Get<std::string>("topic");
  boost::replace_all(topic, "::", "/");
  return topic;
}

// The sensor's link in its world (null, with an error naming it, where there is none: the sensor
// then measures nothing, as Gazebo's).
inline physics::LinkPtr linkOf(const physics::WorldPtr& world, const std::string& parent, const std::string& sensor)
{
  physics::LinkPtr link = world ? boost::dynamic_pointer_cast<physics::Link>(world->EntityByName(parent)) : nullptr;
  if (!link)
    gzerr << "Sensor [" << sensor << "]: no link [" << parent << "] in the world; it measures nothing\n";
  return link;
}

// A noise model of the element's <noise>, where it has one.
inline void loadNoise(std::map<SensorNoiseType, NoisePtr>& noises, SensorNoiseType type, const sdf::ElementPtr& parent,
                      const char* child)
{
  if (parent && parent->HasElement(child) && parent->GetElement(child)->HasElement("noise"))
    noises[type] = NoiseFactory::NewNoiseModel(parent->GetElement(child)->GetElement("noise"));
}

// The value with its noise, where the sensor has that model (`dt` the time since the last value,
// for the model's dynamic bias).
inline double withNoise(const std::map<SensorNoiseType, NoisePtr>& noises, SensorNoiseType type, double value,
                        double dt = 0.0)
{
  const auto found = noises.find(type);
  return found != noises.end() && found->second ? found->second->Apply(value, dt) : value;
}
}  // namespace detail
}  // namespace sensors
}  // namespace gazebo
