// The sensors' rendering, timed, for bench/sensor_bench.py: `sensor_cost URDF WORLD FRAMES
// [--one-thread]` puts the car (URDF) in WORLD and renders, from its own sensors' poses, an 800 x 800
// colour camera (80 degrees), a 640 x 480 depth camera (60 degrees, 0.3 to 8 m) and its lidar FRAMES
// times each (SensorRendering: cameras by OpenGL, the lidar on the Embree RayScene). Prints "isa NAME"
// (the ISA of Embree's kernels: TIANRACER_EMBREE_ISA or the widest the CPU has); where there is
// OpenGL, "gl RENDERER" and the two cameras: "camera 0 PIXELS_PER_CPU_S PIXELS_PER_WALL_S" (0: the
// renderer's own threads); then the lidar with one thread and, unless --one-thread, with all:
// "lidar THREADS RAYS_PER_CPU_S RAYS_PER_WALL_S" (of the cheapest frames). The cameras render
// without noise; with SENSOR_COST_NOISE set in the environment the colour camera keeps its URDF's noise.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <thread>

#include "bullet_plant/world.h"
#include "simulation/internals.h"
#include "sensors/sensor_rendering.h"

using namespace bullet_plant;

namespace
{
using Clock = std::chrono::steady_clock;

double processCpuSeconds()
{
  timespec t;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

struct Cost
{
  double wall = std::numeric_limits<double>::infinity();  // s
  double cpu = std::numeric_limits<double>::infinity();   // process CPU time, s (all threads)
};

// The least CPU time and the least wall time of `frames` runs: on a shared machine, the least disturbed.
template <typename F>
Cost bestCost(int frames, F&& frame)
{
  Cost best;
  for (int k = 0; k < frames; ++k)
  {
    const auto start = Clock::now();
    const double cpu_start = processCpuSeconds();
    frame();
    best.cpu = std::min(best.cpu, processCpuSeconds() - cpu_start);
    best.wall = std::min(best.wall, std::chrono::duration<double>(Clock::now() - start).count());
  }
  return best;
}

Sensor* sensorOfType(Robot::Internals& r, const std::string& type)
{
  for (auto& s : r.sensors)
    if (s->description().type == type)
      return s.get();
  return nullptr;
}

Frame sensorPose(Robot::Internals& r, const SensorDescription& d)
{
  return Frame::fromPose(fromBullet(r.multibody.linkWorldTransform(d.link, r.name))) * Frame::fromPose(d.pose);
}

// SENSOR THREADS RAYS_PER_CPU_SECOND RAYS_PER_WALL_SECOND
void report(const char* sensor, int threads, double rays, const Cost& cost)
{
  std::printf("%s %d %.0f %.0f\n", sensor, threads, rays / cost.cpu, rays / cost.wall);
}
}  // namespace

int main(int argc, char** argv)
{
  const bool one_thread = argc == 5 && std::string(argv[4]) == "--one-thread";
  if (argc != 4 && !one_thread)
  {
    std::cerr << "usage: sensor_cost URDF WORLD FRAMES [--one-thread]\n";
    return 2;
  }
  std::stringstream urdf;
  urdf << std::ifstream(argv[1]).rdbuf();
  World world(parseWorldFile(argv[2]));
  world.log().setSink([](LogLevel, const std::string&) {});
  Robot& car = world.spawn(urdf.str(), "tianracer", poseFromXyzRpy(0, 0, 0, 0, 0, 0));
  world.step(200);
  const int frames = std::stoi(argv[3]);
  Robot::Internals& r = internalsOf(car);
  World::Internals& w = *r.world;
  const Lighting lighting = w.lighting();
  const int all_threads = int(std::max(1u, std::thread::hardware_concurrency()));
  const std::vector<int> thread_counts = one_thread ? std::vector<int>{1} : std::vector<int>{1, all_threads};
  std::printf("isa %s\n", w.rayScene(nullptr).isa().name.c_str());

  const auto* colour = dynamic_cast<Camera*>(sensorOfType(r, "camera"));
  const auto* depth = dynamic_cast<Camera*>(sensorOfType(r, "depth"));
  auto* lidar = dynamic_cast<Lidar*>(sensorOfType(r, "ray") ? sensorOfType(r, "ray") : sensorOfType(r, "gpu_ray"));
  if (!colour || !depth || !lidar)
  {
    std::cerr << "sensor_cost: the URDF needs a camera, a depth camera and a lidar\n";
    return 1;
  }
  // The real car's cameras, on the URDF's camera links.
  SensorDescription colour_d = colour->description(), depth_d = depth->description();
  colour_d.image_width = colour_d.image_height = 800;
  colour_d.horizontal_fov = 80 * M_PI / 180;
  if (!std::getenv("SENSOR_COST_NOISE"))
    colour_d.noise = {};
  depth_d.image_width = 640;
  depth_d.image_height = 480;
  depth_d.horizontal_fov = 60 * M_PI / 180;
  depth_d.clip_near = 0.3;
  depth_d.clip_far = 8.0;
  depth_d.noise = {};
  SensorDescription lidar_d = lidar->description();
  lidar_d.noise = {};
  Camera colour_camera(colour_d, 1), depth_camera(depth_d, 2);
  Lidar scanner(lidar_d, 3);

  struct CameraCase
  {
    const char* name;
    Camera* camera;
  };
  if (GlScene* gl = w.glScene())
  {
    std::printf("gl %s\n", gl->context().renderer().c_str());
    for (CameraCase c : {CameraCase{"camera", &colour_camera}, CameraCase{"depth", &depth_camera}})
    {
      const SensorDescription& d = c.camera->description();
      const Frame pose = sensorPose(r, d);
      report(c.name, 0, double(d.image_width) * d.image_height,
             bestCost(frames, [&] {
               detail::SensorRendering::render(*c.camera, *gl, nullptr, pose, lighting, 0);  // now, on this thread
               c.camera->collect(true);
             }));
    }
  }

  const SensorDescription& ld = scanner.description();
  const Frame lidar_pose = sensorPose(r, ld);
  const double rays = double(ld.horizontal_samples) * ld.vertical_samples;
  constexpr int kScansPerTiming = 20;
  for (int threads : thread_counts)
  {
    setRayThreads(threads);
    report("lidar", threads, kScansPerTiming * rays, bestCost(frames, [&] {
             for (int k = 0; k < kScansPerTiming; ++k)
               detail::SensorRendering::scan(scanner, w.rayScene(&r), lidar_pose, 0);
           }));
  }
  return 0;
}
