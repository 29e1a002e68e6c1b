// What a sensor sees of the world: a lidar's ranges by ray casting, a camera's pixels by OpenGL,
// from the sensor's pose in the world, at one simulated time.
#pragma once

#include <cstdint>

#include "bullet_plant/sensors.h"
#include "rendering/gl_scene.h"
#include "rendering/ray_caster.h"

namespace bullet_plant
{
namespace detail
{
struct SensorRendering
{
  // scene: committed with the lidar's own robot hidden (a lidar does not see its robot).
  static void scan(Lidar& lidar, const RayScene& scene, const Frame& pose, int64_t time_ns);
  // Cameras see their own robot, as Gazebo's do.
  static void render(Camera& camera, GlScene& scene, const Frame& pose, const Lighting& lighting, int64_t time_ns);
};
}  // namespace detail

}  // namespace bullet_plant
