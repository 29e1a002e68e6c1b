// What a sensor sees of the world: a lidar's ranges by ray casting, a camera's pixels by OpenGL,
// from the sensor's pose in the world, at one simulated time.
#pragma once

#include <cstdint>

#include "bullet_plant/sensors.h"
#include "rendering/frame_worker.h"
#include "rendering/gl_scene.h"
#include "rendering/lens_distortion.h"
#include "rendering/ray_caster.h"

namespace bullet_plant
{
namespace detail
{
struct SensorRendering
{
  // scene: committed with the lidar's own robot hidden (a lidar does not see its robot).
  static void scan(Lidar& lidar, const RayScene& scene, const Frame& pose, int64_t time_ns);
  // Cameras see their own robot, as Gazebo's do. The frame renders on `worker` while the
  // simulation goes on (null: now), from the bodies' poses at `time_ns`; Camera::collect makes it
  // the latest (finish) when it is done.
  static void render(Camera& camera, GlScene& scene, FrameWorker* worker, const Frame& pose, const Lighting& lighting,
                     int64_t time_ns);
  // A rendered frame's depths and points (depth cameras), and the frame the camera's latest.
  static void finish(Camera& camera);
};
}  // namespace detail

// A camera's frame in the making: its time, its pixels as the renderer gives them, and the
// worker's ticket (0: rendered, or nothing pending).
struct Camera::Rendering
{
  FrameWorker* worker = nullptr;
  uint64_t ticket = 0;
  bool pending = false;
  int64_t stamp_ns = 0;
  PinholeImage image;  // kept from frame to frame
  std::string error;   // what the renderer threw, rethrown by collect
  // The <distortion>'s remap, worked out at the first frame (and again when the crop changes);
  // empty without distortion. The job reads it, so it changes only while no frame renders.
  DistortionRemap distortion;
  bool distortion_ready = false, distortion_cropped = false;
  std::vector<uint8_t> undistorted;  // the rendered colours before the remap, kept from frame to frame
  std::vector<uint16_t> undistorted16;  // the same for a 16-bit camera
};

}  // namespace bullet_plant
