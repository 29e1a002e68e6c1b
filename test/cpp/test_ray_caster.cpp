// ray_caster.cpp on triangle meshes: rays hit where the triangles are (through the BVH), with the
// triangle's normal and its sub-mesh's colour; a lidar fan in a room of mesh walls.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <sstream>
#include <string>

#include "mesh_fixtures.h"
#include "ray_caster.h"

using namespace bullet_plant;
using namespace mesh_fixtures;

namespace
{
constexpr double kInf = std::numeric_limits<double>::infinity();

std::shared_ptr<const MeshData> load(const std::string& file)
{
  std::string reason;
  auto mesh = loadMesh(file, urdf::Vector3(1, 1, 1), reason);
  EXPECT_TRUE(mesh) << reason;
  return mesh;
}

// The four walls of a square room 2*half wide and `height` tall about the origin, each split into
// n x n squares of two triangles (8 n^2 triangles), as an OBJ.
std::string roomObj(const std::string& dir, double half, double height, int n)
{
  std::ostringstream obj;
  int vertex = 1;
  for (int wall = 0; wall < 4; ++wall)
  {
    const double angle = wall * M_PI / 2, c = std::cos(angle), s = std::sin(angle);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
      {
        // a square of the wall x = half (rotated by angle), y in [-half, half], z in [0, height]
        for (int k = 0; k < 4; ++k)
        {
          const double y = -half + 2 * half * (i + (k == 1 || k == 2)) / n;
          const double z = height * (j + (k >= 2)) / n;
          obj << "v " << c * half - s * y << " " << s * half + c * y << " " << z << "\n";
        }
        obj << "f " << vertex << " " << vertex + 1 << " " << vertex + 2 << "\n";
        obj << "f " << vertex << " " << vertex + 2 << " " << vertex + 3 << "\n";
        vertex += 4;
      }
  }
  return write(dir, "room.obj", obj.str());
}
}  // namespace

TEST(MeshRays, HitABoxMeshWhereItsFacesAreWithTheFaceNormal)
{
  const std::string dir = tempDir();
  const float lo[3] = {-0.5f, -0.25f, 0.0f}, hi[3] = {0.5f, 0.25f, 0.2f};
  auto mesh = load(binaryBoxStl(dir, "box.stl", lo, hi));
  ASSERT_TRUE(mesh);
  // The box's frame 3 m ahead along x, turned a quarter about z: its 0.25 m face meets the ray.
  const RayPrimitive box = RayPrimitive::fromMesh(mesh, poseFromXyzRpy(3, 0, 0, 0, 0, M_PI / 2), nullptr);
  std::vector<RayPrimitive> scene{box};
  RayCaster caster(scene, nullptr);

  const double origin[3] = {0, 0.1, 0.1}, ahead[3] = {1, 0, 0};
  const RayHit hit = caster.castHit(origin, ahead, 10);
  ASSERT_NE(hit.primitive, nullptr);
  EXPECT_NEAR(hit.distance, 3 - 0.25, 1e-6);
  ASSERT_GE(hit.triangle, 0);
  const double point[3] = {origin[0] + hit.distance, origin[1], origin[2]};
  double normal[3];
  hit.primitive->normalAt(point, normal, hit.triangle);
  EXPECT_NEAR(std::abs(normal[0]), 1.0, 1e-6) << "the face's normal is along the ray";
  EXPECT_NEAR(normal[1], 0.0, 1e-6);
  EXPECT_NEAR(normal[2], 0.0, 1e-6);

  const double above[3] = {0, 0.1, 0.3};  // passes over the box's 0.2 m top
  EXPECT_EQ(caster.cast(above, ahead, 10), kInf);
  EXPECT_EQ(caster.cast(origin, ahead, 2.5), kInf) << "beyond the range";
}

TEST(MeshRays, SeeEachSubMeshsColour)
{
  const std::string dir = tempDir();
  write(dir, "paint.mtl", "newmtl red\nKd 1 0 0\nnewmtl blue\nKd 0 0 1\n");
  // Two squares in the plane x = 0: red at y < 0, blue at y > 0.
  auto mesh = load(write(dir, "halves.obj",
                         "mtllib paint.mtl\n"
                         "v 0 -1 0\nv 0 0 0\nv 0 0 1\nv 0 -1 1\nv 0 1 0\nv 0 1 1\n"
                         "usemtl red\nf 1 2 3\nf 1 3 4\n"
                         "usemtl blue\nf 2 5 6\nf 2 6 3\n"));
  ASSERT_TRUE(mesh);
  std::vector<RayPrimitive> scene{RayPrimitive::fromMesh(mesh, poseFromXyzRpy(1, 0, 0, 0, 0, 0), nullptr)};
  scene[0].colour = {0.5f, 0.5f, 0.5f, 1.0f};
  RayCaster caster(scene, nullptr);
  const double dir_x[3] = {1, 0, 0};
  const double left[3] = {0, 0.5, 0.5}, right[3] = {0, -0.5, 0.5};
  const RayHit blue = caster.castHit(left, dir_x, 5), red = caster.castHit(right, dir_x, 5);
  ASSERT_NE(blue.primitive, nullptr);
  ASSERT_NE(red.primitive, nullptr);
  EXPECT_NEAR(blue.distance, 1.0, 1e-9);
  EXPECT_FLOAT_EQ(blue.primitive->colourAt(blue.triangle).b, 1.0f);
  EXPECT_FLOAT_EQ(red.primitive->colourAt(red.triangle).r, 1.0f);
  EXPECT_FLOAT_EQ(red.primitive->colourAt(-1).g, 0.5f) << "no triangle: the primitive's own colour";
}

TEST(MeshRays, ALidarInARoomOfMeshWallsMeasuresTheWalls)
{
  const std::string dir = tempDir();
  const double half = 2.0;
  auto mesh = load(roomObj(dir, half, 1.0, 8));  // 512 triangles
  ASSERT_TRUE(mesh);
  ASSERT_EQ(mesh->triangleCount(), 512);
  std::vector<RayPrimitive> scene{RayPrimitive::fromMesh(mesh, poseFromXyzRpy(0, 0, 0, 0, 0, 0), nullptr)};
  RayCaster caster(scene, nullptr);
  // A sensor 0.5 m up, off centre, turned: every ray meets a wall at the distance a square predicts.
  const urdf::Pose pose = poseFromXyzRpy(0.3, -0.7, 0.5, 0, 0, 0.4);
  const Frame sensor = Frame::fromPose(pose);
  const int n = 720;
  const double a0 = -M_PI, da = 2 * M_PI / n;
  std::vector<double> ranges;
  caster.castFan(sensor, a0, da, n, {0.0, 0.1}, 30.0, ranges);
  ASSERT_EQ(ranges.size(), size_t(2 * n));
  for (int row = 0; row < 2; ++row)
    for (int i = 0; i < n; ++i)
    {
      const double elevation = row == 0 ? 0.0 : 0.1;
      const double a = a0 + i * da + 0.4;  // world azimuth
      const double dx = std::cos(elevation) * std::cos(a), dy = std::cos(elevation) * std::sin(a);
      double expected = kInf;
      if (dx != 0)
        expected = std::min(expected, ((dx > 0 ? half : -half) - 0.3) / dx);
      if (dy != 0)
        expected = std::min(expected, ((dy > 0 ? half : -half) + 0.7) / dy);
      ASSERT_NEAR(ranges[row * n + i], expected, 1e-6) << "ray " << i << " row " << row;
    }

  // Random rays from inside: each hits some wall (the room is closed sideways, open above).
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int k = 0; k < 1000; ++k)
  {
    const double a = M_PI * u(rng);
    double d[3] = {std::cos(a), std::sin(a), 0.1 * u(rng)};  // rises less than 0.5 m over 4.9 m
    const double length = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    for (double& x : d)
      x /= length;
    const double o[3] = {1.5 * u(rng), 1.5 * u(rng), 0.5};
    const double t = caster.cast(o, d, 100);
    ASSERT_LT(t, kInf) << "ray " << k;
    const double p[3] = {o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2]};
    EXPECT_NEAR(std::max(std::abs(p[0]), std::abs(p[1])), half, 1e-6) << "ray " << k;
  }
}
