// The world's lights by name, as gazebo_ros's light services reach them (World::lightNames, light,
// setLight, removeLight in include/bullet_plant/world.h): the lights of the description the world
// keeps, which World::Internals::lighting() hands to every camera frame.
#include <cmath>
#include <stdexcept>

#include "bullet_plant/world.h"
#include "simulation/internals.h"

namespace bullet_plant
{
namespace
{
bool finite(const urdf::Vector3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

bool finite(const Rgba& c) { return std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b) && std::isfinite(c.a); }

// The unit vector along `v`, or `otherwise` for a zero one.
urdf::Vector3 unitOr(const urdf::Vector3& v, const urdf::Vector3& otherwise)
{
  const double n = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
  return n > 0 ? scaled(v, 1.0 / n) : otherwise;
}

// Colours, attenuation, position and direction: numbers, and an attenuation that lights something.
void check(const WorldLight& light)
{
  const LightDescription& l = light.light;
  const std::string where = "light '" + l.name + "': ";
  if (!finite(l.diffuse) || !finite(l.specular))
    throw std::invalid_argument(where + "the diffuse and specular colours must be finite");
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
  for (const LightDescription& l : in_->description.lights)
    names.push_back(l.name);
  return names;
}

bool World::light(const std::string& name, WorldLight& out) const
{
  for (const LightDescription& l : in_->description.lights)
    if (l.name == name)
    {
      out = WorldLight();
      out.light = l;
      out.directional = l.kind == LightDescription::Kind::Directional;
      out.cast_shadows = l.cast_shadows;
      return true;
    }
  return false;
}

bool World::setLight(const WorldLight& light)
{
  const LightDescription& l = light.light;
  for (LightDescription& own : in_->description.lights)
    if (own.name == l.name)
    {
      check(light);
      own.position = l.position;
      if (own.kind != LightDescription::Kind::Point)
        own.direction = unitOr(l.direction, own.direction);
      own.diffuse = l.diffuse;
      own.specular = l.specular;
      own.constant = l.constant;
      own.linear = l.linear;
      own.quadratic = l.quadratic;
      own.cast_shadows = light.cast_shadows;
      return true;
    }
  return false;
}

bool World::removeLight(const std::string& name)
{
  auto& lights = in_->description.lights;
  for (auto it = lights.begin(); it != lights.end(); ++it)
    if (it->name == name)
    {
      lights.erase(it);
      return true;
    }
  return false;
}

}  // namespace bullet_plant
