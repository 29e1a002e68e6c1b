// The world's lights by name, as gazebo_ros's light services reach them (World::lightNames, light,
// setLight, removeLight in include/bullet_plant/world.h): the sun and the point and spot lights of the
// description the world keeps, which World::Internals::lighting() hands to every camera frame.
#include <cmath>
#include <stdexcept>

#include "bullet_plant/world.h"
#include "simulation/internals.h"

namespace bullet_plant
{
namespace
{
bool finite(const urdf::Vector3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// The unit vector along `v`, or `otherwise` for a zero one.
urdf::Vector3 unitOr(const urdf::Vector3& v, const urdf::Vector3& otherwise)
{
  const double n = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
  return n > 0 ? scaled(v, 1.0 / n) : otherwise;
}

// Colour, attenuation, position and direction: numbers, and an attenuation that lights something.
void check(const WorldLight& light)
{
  const LightDescription& l = light.light;
  const std::string where = "light '" + l.name + "': ";
  if (!std::isfinite(l.diffuse.r) || !std::isfinite(l.diffuse.g) || !std::isfinite(l.diffuse.b) ||
      !std::isfinite(l.diffuse.a))
    throw std::invalid_argument(where + "the diffuse colour must be finite");
  if (!finite(l.position) || !finite(l.direction))
    throw std::invalid_argument(where + "the pose and direction must be finite");
  if (!std::isfinite(l.constant) || !std::isfinite(l.linear) || !std::isfinite(l.quadratic) || l.constant < 0 ||
      l.linear < 0 || l.quadratic < 0 || l.constant + l.linear + l.quadratic <= 0)
    throw std::invalid_argument(where + "attenuation constant " + formatNumber(l.constant) + ", linear " +
                                formatNumber(l.linear) + ", quadratic " + formatNumber(l.quadratic) +
                                " lights nothing: give factors >= 0, not all 0 (get_light_properties has the light's)");
}
}  // namespace

std::vector<std::string> World::lightNames() const
{
  std::vector<std::string> names;
  if (in_->sun.present)
    names.push_back(in_->description.sun_name);
  for (const LightDescription& l : in_->description.lights)
    names.push_back(l.name);
  return names;
}

bool World::light(const std::string& name, WorldLight& out) const
{
  const Internals& w = *in_;
  if (w.sun.present && name == w.description.sun_name)
  {
    out = WorldLight();
    out.directional = true;
    out.cast_shadows = w.sun.cast_shadows;
    out.light.name = name;
    out.light.direction = unitOr(w.description.light_direction, urdf::Vector3(0, 0, -1));
    out.light.diffuse = w.sun.diffuse;
    out.light.constant = w.sun.constant;
    out.light.linear = w.sun.linear;
    out.light.quadratic = w.sun.quadratic;
    out.light.range = 1000.0;  // model://sun's: a directional light reaches everything
    return true;
  }
  for (const LightDescription& l : w.description.lights)
    if (l.name == name)
    {
      out = WorldLight();
      out.light = l;
      out.cast_shadows = false;
      return true;
    }
  return false;
}

bool World::setLight(const WorldLight& light)
{
  Internals& w = *in_;
  const LightDescription& l = light.light;
  if (w.sun.present && l.name == w.description.sun_name)
  {
    check(light);
    w.description.light_direction = unitOr(l.direction, w.description.light_direction);
    w.sun.cast_shadows = light.cast_shadows;
    w.sun.diffuse = l.diffuse;
    w.sun.constant = l.constant;
    w.sun.linear = l.linear;
    w.sun.quadratic = l.quadratic;
    return true;
  }
  for (LightDescription& own : w.description.lights)
    if (own.name == l.name)
    {
      check(light);
      own.position = l.position;
      if (own.spot)
        own.direction = unitOr(l.direction, own.direction);
      own.diffuse = l.diffuse;
      own.constant = l.constant;
      own.linear = l.linear;
      own.quadratic = l.quadratic;
      return true;
    }
  return false;
}

bool World::removeLight(const std::string& name)
{
  Internals& w = *in_;
  if (w.sun.present && name == w.description.sun_name)
  {
    w.sun.present = false;
    return true;
  }
  for (auto it = w.description.lights.begin(); it != w.description.lights.end(); ++it)
    if (it->name == name)
    {
      w.description.lights.erase(it);
      return true;
    }
  return false;
}

}  // namespace bullet_plant
