// What a sensor sees of the world: a lidar's ranges and a camera's pixels by ray casting from the
// sensor's pose in the world, at one simulated time.
#pragma once

#include <cstdint>

#include "bullet_plant/sensors.h"
#include "ray_caster.h"

namespace bullet_plant
{
namespace detail
{
struct SensorRendering
{
  // caster: the scene without the lidar's own robot (a lidar does not see its robot).
  static void scan(Lidar& lidar, const RayCaster& caster, const Frame& pose, int64_t time_ns);
  // caster: the whole scene (cameras see their own robot, as Gazebo's do).
  static void render(Camera& camera, const RayCaster& caster, const Frame& pose, const urdf::Vector3& light_direction,
                     int64_t time_ns);
};
}  // namespace detail

}  // namespace bullet_plant
