// The car on a world of meshes, for bench/mesh_cost.py: `mesh_world_cost URDF STEPS [FLOOR WALLS]`
// steps the car driving its rear wheels at 1 m/s for STEPS 1 ms steps on the empty world (a ground
// plane) or, given FLOOR and WALLS (mesh files), on a world made of those meshes in place of the
// plane; `mesh_world_cost URDF --rays FANS FLOOR WALLS` casts FANS scans of the Tianracer's lidar
// (1081 rays over 270 degrees, 10 m) from the car on the mesh world and prints rays per second.
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

#include "bullet_plant/world.h"
#include "simulation/internals.h"

using namespace bullet_plant;

namespace
{
WorldDescription meshWorld(const std::string& floor, const std::string& walls)
{
  WorldDescription d = emptyWorldDescription();
  d.collisions.clear();
  for (const std::string& file : {floor, walls})
  {
    StaticCollision c;
    c.name = file;
    c.shape.kind = Shape::Kind::Mesh;
    c.shape.mesh_uri = c.shape.mesh_file = file;
    c.pose = poseFromXyzRpy(0, 0, 0, 0, 0, 0);
    d.collisions.push_back(c);
  }
  return d;
}

void driveRearWheels(Robot& car)
{
  for (const char* joint : {"left_rear_wheel_joint", "right_rear_wheel_joint"})
    if (JointHandle* h = car.handle(joint))
      h->setCommand(31.25);
}
}  // namespace

int main(int argc, char** argv)
{
  if (argc < 3)
  {
    std::cerr << "usage: mesh_world_cost URDF STEPS [FLOOR WALLS] | URDF --rays FANS FLOOR WALLS\n";
    return 2;
  }
  std::stringstream urdf;
  urdf << std::ifstream(argv[1]).rdbuf();
  const bool rays = std::string(argv[2]) == "--rays";
  const int first_mesh = rays ? 4 : 3;
  const WorldDescription description =
      argc > first_mesh + 1 ? meshWorld(argv[first_mesh], argv[first_mesh + 1]) : emptyWorldDescription();
  World world(description);
  world.log().setSink([](LogLevel, const std::string&) {});
  Robot& car = world.spawn(urdf.str(), "tianracer", urdf::Pose());
  driveRearWheels(car);
  if (!rays)
  {
    world.step(std::stoi(argv[2]));
    return 0;
  }
  world.step(500);
  const int fans = std::stoi(argv[3]);
  Robot::Internals& r = internalsOf(car);
  const RayScene& scene = r.world->rayScene(&r);
  const Frame sensor = Frame::fromPose(compose(car.basePose(), poseFromXyzRpy(0.1, 0, 0.15, 0, 0, 0)));
  const int samples = 1081;
  const double span = 270.0 * M_PI / 180.0;
  const std::vector<double> directions = fanDirections(-span / 2, span / (samples - 1), samples, {0.0});
  std::vector<double> ranges;
  long hits = 0;
  const auto start = std::chrono::steady_clock::now();
  for (int k = 0; k < fans; ++k)
  {
    scene.castRays(sensor, directions, 0.0, 10.0, kSeenByLidars, ranges);
    for (double d : ranges)
      hits += d < 10.0;
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("%.2f M rays/s (%ld of %ld rays hit within 10 m)\n", fans * double(samples) / seconds / 1e6, hits,
              long(fans) * samples);
  return 0;
}
