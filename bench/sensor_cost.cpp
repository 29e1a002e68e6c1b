// The sensors' ray casting, timed, for bench/sensor_bench.py: `sensor_cost URDF WORLD FRAMES` puts
// the car (URDF) in WORLD and renders, from its own sensors' poses, an 800 x 800 colour camera
// (80 degrees), a 640 x 480 depth camera (60 degrees, 0.3 to 8 m) and its lidar FRAMES times each,
// through the previous path (bench/previous_ray_caster.cpp: one ray at a time, double precision,
// single thread) and through the plant's own (SensorRendering on the Embree RayScene) with one
// thread and with all. Prints one line per sensor and path: "SENSOR PATH THREADS RAYS_PER_CPU_S
// RAYS_PER_WALL_S" (of the cheapest frames), then the share of colour values the two paths agree on
// within 2 of 255. The cameras render without noise (the previous path had none); with
// SENSOR_COST_NOISE set in the environment the colour camera keeps its URDF's noise. With a fourth
// argument --embree-one-thread only the plant's own path on one thread runs (what one core does on
// the ISA of Embree's kernels that TIANRACER_EMBREE_ISA names); the first line is then "isa NAME".
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
#include "internals.h"
#include "previous_ray_caster.h"
#include "sensor_rendering.h"

using namespace bullet_plant;

namespace
{
using Clock = std::chrono::steady_clock;

// The shapes cameras (or lidars) see, as the previous path's primitives in the world frame.
std::vector<previous::RayPrimitive> previousScene(World::Internals& w, unsigned seen_by)
{
  std::vector<previous::RayPrimitive> out;
  auto add = [&](const RayPrimitive& p, const Frame& parent) {
    if (!(p.seen_by & seen_by))
      return;
    Shape s;
    s.kind = p.kind;
    s.box_size = {{2 * p.half[0], 2 * p.half[1], 2 * p.half[2]}};
    s.radius = p.radius;
    s.length = 2 * p.half_length;
    s.normal = urdf::Vector3(p.normal[0], p.normal[1], p.normal[2]);
    previous::RayPrimitive q = p.mesh ? previous::RayPrimitive::fromMesh(p.mesh, urdf::Pose(), p.owner)
                                      : previous::RayPrimitive::fromShape(s, urdf::Pose(), p.owner);
    q.frame = parent * p.frame;
    q.colour = p.colour;
    out.push_back(q);
  };
  for (const RayPrimitive& p : w.static_ray_shapes)
    add(p, Frame());
  for (auto& robot : w.robots)
  {
    RobotMultibody& m = internalsOf(*robot).multibody;
    for (size_t b = 0; b < m.bodies.size(); ++b)
      for (const RayPrimitive& p : m.bodies[b].ray_shapes)
        add(p, Frame::fromPose(fromBullet(m.bodyWorldTransform(int(b)))));
  }
  return out;
}

// The previous path's camera: a ray per pixel centre, shaded as the plant did before Embree.
void previousRender(const Camera& camera, const previous::RayCaster& caster, const Frame& pose, const Lighting& light,
                    std::vector<uint8_t>& rgb, std::vector<float>& depth)
{
  const SensorDescription& d = camera.description();
  const int w = d.image_width, h = d.image_height;
  double fx, fy, cx, cy;
  camera.intrinsics(fx, fy, cx, cy);
  rgb.assign(size_t(w) * h * 3, 0);
  depth.assign(size_t(w) * h, std::numeric_limits<float>::quiet_NaN());
  const double near = d.clip_near > 0 ? d.clip_near : 0.0, far = d.clip_far > 0 ? d.clip_far : 100.0;
  for (int v = 0; v < h; ++v)
    for (int u = 0; u < w; ++u)
    {
      const double xo = (u - cx) / fx, yo = (v - cy) / fy;
      const double length = std::sqrt(1.0 + xo * xo + yo * yo);
      const double in_link[3] = {1.0 / length, -xo / length, -yo / length};
      double dir[3];
      pose.rotate(in_link, dir);
      const previous::RayHit hit = caster.castHit(pose.t, dir, far * length);
      const double z = hit.distance / length;
      const size_t pixel = size_t(v) * w + u;
      float colour[3] = {light.background[0], light.background[1], light.background[2]};
      if (hit.primitive && z >= near)
      {
        const double point[3] = {pose.t[0] + dir[0] * hit.distance, pose.t[1] + dir[1] * hit.distance,
                                 pose.t[2] + dir[2] * hit.distance};
        double normal[3];
        hit.primitive->normalAt(point, normal, hit.triangle);
        if (dot(normal, dir) > 0)
          for (double& n : normal)
            n = -n;
        const double shade = light.ambient + (1.0 - light.ambient) * std::max(0.0, dot(normal, light.towards_light));
        const Rgba& c = hit.primitive->colourAt(hit.triangle);
        colour[0] = float(c.r * shade);
        colour[1] = float(c.g * shade);
        colour[2] = float(c.b * shade);
        depth[pixel] = float(z);
      }
      for (int k = 0; k < 3; ++k)
        rgb[3 * pixel + k] = uint8_t(std::lround(std::max(0.0f, std::min(1.0f, colour[k])) * 255.0));
    }
}

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

// SENSOR PATH THREADS RAYS_PER_CPU_SECOND RAYS_PER_WALL_SECOND
void report(const char* sensor, const char* path, int threads, double rays, const Cost& cost)
{
  std::printf("%s %s %d %.0f %.0f\n", sensor, path, threads, rays / cost.cpu, rays / cost.wall);
}
}  // namespace

int main(int argc, char** argv)
{
  const bool embree_one_thread = argc == 5 && std::string(argv[4]) == "--embree-one-thread";
  if (argc != 4 && !embree_one_thread)
  {
    std::cerr << "usage: sensor_cost URDF WORLD FRAMES [--embree-one-thread]\n";
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
  const std::vector<int> thread_counts = embree_one_thread ? std::vector<int>{1} : std::vector<int>{1, all_threads};
  if (embree_one_thread)
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

  const std::vector<previous::RayPrimitive> seen_by_cameras = previousScene(w, kSeenByCameras);
  const std::vector<previous::RayPrimitive> seen_by_lidars = previousScene(w, kSeenByLidars);
  const previous::RayCaster camera_caster(seen_by_cameras, nullptr), lidar_caster(seen_by_lidars, &r);

  struct CameraCase
  {
    const char* name;
    Camera* camera;
  };
  std::vector<uint8_t> previous_rgb;
  std::vector<float> previous_depth;
  for (CameraCase c : {CameraCase{"camera", &colour_camera}, CameraCase{"depth", &depth_camera}})
  {
    const SensorDescription& d = c.camera->description();
    const double rays = double(d.image_width) * d.image_height;
    const Frame pose = sensorPose(r, d);
    if (!embree_one_thread)
      report(c.name, "previous", 1, rays, bestCost(std::max(1, frames / 4), [&] {
               previousRender(*c.camera, camera_caster, pose, lighting, previous_rgb, previous_depth);
             }));
    for (int threads : thread_counts)
    {
      setRayThreads(threads);
      report(c.name, "embree", threads, rays, bestCost(frames, [&] {
               detail::SensorRendering::render(*c.camera, w.rayScene(nullptr), pose, lighting, 0);
             }));
    }
    if (embree_one_thread)
      continue;
    // How far the paths' images are apart (cameras see visuals now, where they saw collisions).
    const std::vector<uint8_t>& rgb = c.camera->latest().rgb;
    size_t close = 0;
    for (size_t k = 0; k < rgb.size(); ++k)
      close += std::abs(int(rgb[k]) - int(previous_rgb[k])) <= 2;
    std::printf("%s agree %.4f\n", c.name, double(close) / double(rgb.size()));
  }

  const SensorDescription& ld = scanner.description();
  const Frame lidar_pose = sensorPose(r, ld);
  const int n = ld.horizontal_samples;
  const double da = n > 1 ? (ld.horizontal_max_angle - ld.horizontal_min_angle) / (n - 1) : 0.0;
  const double rays = double(n) * ld.vertical_samples;
  std::vector<double> ranges;
  constexpr int kScansPerTiming = 20;
  if (!embree_one_thread)
    report("lidar", "previous", 1, kScansPerTiming * rays, bestCost(frames, [&] {
             for (int k = 0; k < kScansPerTiming; ++k)
               lidar_caster.castFan(lidar_pose, ld.horizontal_min_angle, da, n, {0.0}, ld.range_max, ranges);
           }));
  for (int threads : thread_counts)
  {
    setRayThreads(threads);
    report("lidar", "embree", threads, kScansPerTiming * rays, bestCost(frames, [&] {
             for (int k = 0; k < kScansPerTiming; ++k)
               detail::SensorRendering::scan(scanner, w.rayScene(&r), lidar_pose, 0);
           }));
  }
  return 0;
}
