// ray_caster.cpp (Embree): rays hit meshes where their triangles are, with the triangle's normal and
// its sub-mesh's colour or texture; boxes, planes, spheres and cylinders where they analytically
// are; robots' bodies where their last pose puts them; cameras see visuals and lidars collisions; a
// lidar fan in a room of mesh walls; camera images that do not depend on the number of threads;
// scenes of the same world shapes share one set of them.
// Embree casts in single precision: distances agree within 1e-5 m.
#include <gtest/gtest.h>

#include <stb/stb_image_write.h>

#include <cmath>
#include <random>
#include <set>
#include <sstream>
#include <string>

#include "mesh_fixtures.h"
#include "rendering/ray_caster.h"

using namespace bullet_plant;
using namespace mesh_fixtures;

namespace
{
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kFloatTolerance = 1e-5;

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
  RayScene scene({box});
  scene.commit(nullptr);

  const double origin[3] = {0, 0.1, 0.1}, ahead[3] = {1, 0, 0};
  const RayHit hit = scene.castHit(origin, ahead, 0, 10, kSeenByAll);
  ASSERT_NE(hit.primitive, nullptr);
  EXPECT_NEAR(hit.distance, 3 - 0.25, kFloatTolerance);
  ASSERT_GE(hit.triangle, 0);
  EXPECT_NEAR(hit.normal[0], -1.0, 1e-6) << "the face's normal, turned towards the ray";
  EXPECT_NEAR(hit.normal[1], 0.0, 1e-6);
  EXPECT_NEAR(hit.normal[2], 0.0, 1e-6);

  const double above[3] = {0, 0.1, 0.3};  // passes over the box's 0.2 m top
  EXPECT_EQ(scene.cast(above, ahead, 10, kSeenByAll), kInf);
  EXPECT_EQ(scene.cast(origin, ahead, 2.5, kSeenByAll), kInf) << "beyond the range";
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
  std::vector<RayPrimitive> shapes{RayPrimitive::fromMesh(mesh, poseFromXyzRpy(1, 0, 0, 0, 0, 0), nullptr)};
  RayScene scene(shapes);
  scene.commit(nullptr);
  const double dir_x[3] = {1, 0, 0};
  const double left[3] = {0, 0.5, 0.5}, right[3] = {0, -0.5, 0.5};
  const RayHit blue = scene.castHit(left, dir_x, 0, 5, kSeenByAll), red = scene.castHit(right, dir_x, 0, 5, kSeenByAll);
  ASSERT_NE(blue.primitive, nullptr);
  ASSERT_NE(red.primitive, nullptr);
  EXPECT_NEAR(blue.distance, 1.0, kFloatTolerance);
  EXPECT_FLOAT_EQ(blue.primitive->surfaceColour(blue.triangle, blue.u, blue.v).b, 1.0f);
  EXPECT_FLOAT_EQ(red.primitive->surfaceColour(red.triangle, red.u, red.v).r, 1.0f);
  EXPECT_FLOAT_EQ(red.primitive->surfaceColour(-1, 0, 0).g, 1.0f) << "no triangle: Gazebo's white";
  // a visual's colour (a URDF <material><color>) in place of the file's, as Gazebo sets it
  RayPrimitive grey = shapes[0];
  grey.material = VisualMaterial::colour({0.5f, 0.5f, 0.5f, 1.0f});
  EXPECT_FLOAT_EQ(grey.surfaceColour(red.triangle, red.u, red.v).r, 0.5f);
  // an SDF <emissive> alone keeps the file's colours
  RayPrimitive glowing = shapes[0];
  glowing.material.has_emissive = true;
  glowing.material.emissive = {0.2f, 0.0f, 0.0f, 1.0f};
  bool textured = false;
  const Material m = glowing.surfaceMaterial(blue.triangle, textured);
  EXPECT_FLOAT_EQ(m.diffuse.b, 1.0f);
  EXPECT_FLOAT_EQ(m.emissive.r, 0.2f);
}

TEST(MeshRays, ALidarInARoomOfMeshWallsMeasuresTheWalls)
{
  const std::string dir = tempDir();
  const double half = 2.0;
  auto mesh = load(roomObj(dir, half, 1.0, 8));  // 512 triangles
  ASSERT_TRUE(mesh);
  ASSERT_EQ(mesh->triangleCount(), 512);
  RayScene scene({RayPrimitive::fromMesh(mesh, poseFromXyzRpy(0, 0, 0, 0, 0, 0), nullptr)});
  scene.commit(nullptr);
  // A sensor 0.5 m up, off centre, turned: every ray meets a wall at the distance a square predicts.
  const urdf::Pose pose = poseFromXyzRpy(0.3, -0.7, 0.5, 0, 0, 0.4);
  const Frame sensor = Frame::fromPose(pose);
  const int n = 720;
  const double a0 = -M_PI, da = 2 * M_PI / n;
  std::vector<double> ranges;
  scene.castRays(sensor, fanDirections(a0, da, n, {0.0, 0.1}), 0.0, 30.0, kSeenByLidars, ranges);
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
      ASSERT_NEAR(ranges[row * n + i], expected, kFloatTolerance) << "ray " << i << " row " << row;
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
    const double t = scene.cast(o, d, 100, kSeenByAll);
    ASSERT_LT(t, kInf) << "ray " << k;
    const double p[3] = {o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2]};
    EXPECT_NEAR(std::max(std::abs(p[0]), std::abs(p[1])), half, kFloatTolerance) << "ray " << k;
  }
}

namespace
{
RayPrimitive primitive(Shape::Kind kind, double a, double b, double c, const urdf::Pose& pose)
{
  Shape s;
  s.kind = kind;
  s.box_size = {{a, b, c}};
  s.radius = a;
  s.length = b;
  s.normal = urdf::Vector3(a, b, c);
  return RayPrimitive::fromShape(s, pose, nullptr);
}
}  // namespace

TEST(ShapeRays, BoxesPlanesSpheresAndCylindersAreHitWhereTheyAre)
{
  const RayPrimitive ground = primitive(Shape::Kind::Plane, 0, 0, 1, poseFromXyzRpy(0, 0, 0, 0, 0, 0));
  const RayPrimitive box = primitive(Shape::Kind::Box, 0.4, 0.6, 0.8, poseFromXyzRpy(5, 0, 1, 0, 0, 0.3));
  const RayPrimitive ball = primitive(Shape::Kind::Sphere, 0.5, 0, 0, poseFromXyzRpy(0, 4, 1, 0, 0, 0));
  // a wheel: a cylinder lying along y
  const RayPrimitive wheel = primitive(Shape::Kind::Cylinder, 0.3, 0.2, 0, poseFromXyzRpy(-3, 0, 1, M_PI / 2, 0, 0));
  RayScene scene({ground, box, ball, wheel});
  scene.commit(nullptr);
  const double o[3] = {0, 0, 1};
  const double down[3] = {0, 0, -1}, x[3] = {1, 0, 0}, y[3] = {0, 1, 0}, minus_x[3] = {-1, 0, 0};
  EXPECT_NEAR(scene.cast(o, down, 10, kSeenByAll), 1.0, kFloatTolerance);
  // the box turned 0.3 rad about z: the ray along x meets its -x face at 5 - 0.2 / cos(0.3)
  EXPECT_NEAR(scene.cast(o, x, 10, kSeenByAll), 5 - 0.2 / std::cos(0.3), kFloatTolerance);
  EXPECT_NEAR(scene.cast(o, y, 10, kSeenByAll), 3.5, kFloatTolerance);
  EXPECT_NEAR(scene.cast(o, minus_x, 10, kSeenByAll), 2.7, kFloatTolerance);
  // off the sphere's centre line: the exact curved surface, not a tessellation
  const double o2[3] = {0.3, 0, 1};
  EXPECT_NEAR(scene.cast(o2, y, 10, kSeenByAll), 4 - std::sqrt(0.25 - 0.09), kFloatTolerance);
  const RayHit side = scene.castHit(o2, y, 0, 10, kSeenByAll);
  EXPECT_NEAR(side.normal[0], 0.6, 1e-5) << "the sphere's normal at the hit";
  EXPECT_NEAR(side.normal[1], -0.8, 1e-5);
  // the wheel's tread seen from above, 0.1 m off its axis: the circle's height there
  const double above[3] = {-3.1, 0.05, 3};
  EXPECT_NEAR(scene.cast(above, down, 10, kSeenByAll), 2 - std::sqrt(0.09 - 0.01), kFloatTolerance);
  EXPECT_EQ(scene.castHit(o, down, 1.5, 10, kSeenByAll).distance, kInf) << "nothing nearer than the near distance";
}

TEST(ShapeRays, ScenesOfTheSameWorldShareItsShapesAndKeepTheLastFewAfterTheyGo)
{
  // a ground of this test's own: other tests' scenes' sets may still be kept
  const RayPrimitive ground = primitive(Shape::Kind::Plane, 0, 0, 1, poseFromXyzRpy(0, 0, -0.0123, 0, 0, 0));
  const auto wallAt = [&](double x) { return primitive(Shape::Kind::Box, 0.2, 2, 1, poseFromXyzRpy(x, 0, 1, 0, 0, 0)); };
  const size_t before = RayScene::staticSetsBuilt();
  const double o[3] = {0, 0, 1}, x[3] = {1, 0, 0};
  {
    RayScene first({ground, wallAt(3)});
    EXPECT_EQ(RayScene::staticSetsBuilt(), before + 2) << "the walls, and the planes on their own";
    RayScene second({ground, wallAt(3)});
    EXPECT_EQ(RayScene::staticSetsBuilt(), before + 2) << "the same shapes: nothing built";
    RayScene moved({ground, wallAt(3.001)});
    EXPECT_EQ(RayScene::staticSetsBuilt(), before + 3) << "a wall 1 mm off is another world; the ground is the same";
    second.commit(nullptr);
    moved.commit(nullptr);
    EXPECT_NEAR(second.cast(o, x, 10, kSeenByAll), 2.9, kFloatTolerance);
    EXPECT_NEAR(moved.cast(o, x, 10, kSeenByAll), 2.901, kFloatTolerance);
  }
  RayScene after_reset({ground, wallAt(3)});  // every scene of it gone, as at an environment's reset
  EXPECT_EQ(RayScene::staticSetsBuilt(), before + 3) << "kept while no scene holds it";
  for (size_t k = 0; k < RayScene::kUnheldStaticSets + 1; ++k)
    RayScene other({wallAt(10.0 + double(k))});  // each made and gone: unheld sets
  const size_t built = RayScene::staticSetsBuilt();
  RayScene again({wallAt(10.0)});
  EXPECT_EQ(RayScene::staticSetsBuilt(), built + 1) << "the oldest unheld set was let go";
  RayScene held({ground, wallAt(3)});
  EXPECT_EQ(RayScene::staticSetsBuilt(), built + 1) << "a set a scene holds is never let go";
}

TEST(ShapeRays, APlaneHasNoEdgesForARayToSlipThrough)
{
  // Rays from above at points of the line y = x on the ground, and of the line through the origin
  // a lidar there sweeps: where a plane of triangles has the edges two of its triangles share.
  const RayPrimitive ground = primitive(Shape::Kind::Plane, 0, 0, 1, poseFromXyzRpy(0, 0, 0, 0, 0, 0));
  RayScene scene({ground});
  scene.commit(nullptr);
  const double eye[3] = {6, -0.01, 16.8};
  int missed = 0;
  for (int k = 0; k <= 20000; ++k)
  {
    const double t = -50.0 + k * 0.005;
    double d[3] = {t - eye[0], t - eye[1], -eye[2]};
    const double length = norm(d);
    for (double& x : d)
      x /= length;
    const double hit = scene.cast(eye, d, 100, kSeenByAll);
    missed += !(std::abs(hit - length) < 1e-6 * length);  // single precision, up to 66 m away
  }
  EXPECT_EQ(missed, 0) << "of 20,001 rays at the line y = x";
  const double lidar[3] = {0, 0, 0.1};
  for (int k = 0; k < 3600; ++k)
  {
    const double a = k * M_PI / 1800, down = 0.05;
    const double d[3] = {std::cos(a) * std::cos(down), std::sin(a) * std::cos(down), -std::sin(down)};
    EXPECT_NEAR(scene.cast(lidar, d, 10, kSeenByAll), 0.1 / std::sin(down), kFloatTolerance) << "azimuth " << a;
  }
}

TEST(ShapeRays, CamerasSeeVisualsAndLidarsCollisions)
{
  RayPrimitive visual = primitive(Shape::Kind::Box, 1, 1, 1, poseFromXyzRpy(2, 0, 0, 0, 0, 0));
  visual.seen_by = kSeenByCameras;
  RayPrimitive collision = primitive(Shape::Kind::Box, 1, 1, 1, poseFromXyzRpy(4, 0, 0, 0, 0, 0));
  collision.seen_by = kSeenByLidars;
  RayScene scene({visual, collision});
  scene.commit(nullptr);
  const double o[3] = {0, 0, 0}, x[3] = {1, 0, 0};
  EXPECT_NEAR(scene.cast(o, x, 10, kSeenByCameras), 1.5, kFloatTolerance);
  EXPECT_NEAR(scene.cast(o, x, 10, kSeenByLidars), 3.5, kFloatTolerance);
}

TEST(ShapeRays, BodiesAreWhereTheirLastPoseIsAndHiddenFromTheirOwnLidar)
{
  RayScene scene({});
  int robot = 0;
  const int body = scene.addBody(&robot, {primitive(Shape::Kind::Sphere, 0.5, 0, 0, poseFromXyzRpy(1, 0, 0, 0, 0, 0))});
  const double o[3] = {0, 0, 0}, x[3] = {1, 0, 0};
  for (double at : {2.0, 6.0})
  {
    scene.setPose(body, Frame::fromPose(poseFromXyzRpy(at, 0, 0, 0, 0, 0)));
    scene.commit(nullptr);
    EXPECT_NEAR(scene.cast(o, x, 10, kSeenByLidars), at + 0.5, kFloatTolerance);
  }
  scene.commit(&robot);
  EXPECT_EQ(scene.cast(o, x, 10, kSeenByLidars), kInf) << "hidden for the robot's own lidar";
  EXPECT_EQ(scene.cast(o, x, 10, kSeenByCameras), kInf) << "also for its own gpu_ray lidar";
  scene.commit(nullptr);
  EXPECT_NEAR(scene.cast(o, x, 10, kSeenByCameras), 6.5, kFloatTolerance) << "its cameras see it";
  scene.removeOwner(&robot);
  scene.commit(nullptr);
  EXPECT_EQ(scene.cast(o, x, 10, kSeenByAll), kInf);
  EXPECT_FALSE(scene.hasOwner(&robot));
}

namespace
{
// A 4 x 4 texture of 16 distinct colours, texel (column c, row r from the top) = (16c, 16r, 200).
std::string writeTexture(const std::string& dir)
{
  std::vector<uint8_t> rgb;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c)
      rgb.insert(rgb.end(), {uint8_t(16 * c + 8), uint8_t(16 * r + 8), 200});
  const std::string path = dir + "/checker.png";
  EXPECT_TRUE(stbi_write_png(path.c_str(), 4, 4, 3, rgb.data(), 12));
  return path;
}

// A 1 m square quad in the plane x = 0 (y, z in [0, 1]) textured with the whole image: texture s
// along +y, t along +z.
std::shared_ptr<const MeshData> texturedQuad(const std::string& dir)
{
  writeTexture(dir);
  write(dir, "quad.mtl", "newmtl picture\nKd 1 1 1\nmap_Kd checker.png\n");
  return load(write(dir, "quad.obj",
                    "mtllib quad.mtl\n"
                    "v 0 0 0\nv 0 1 0\nv 0 1 1\nv 0 0 1\n"
                    "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
                    "usemtl picture\nf 1/1 2/2 3/3\nf 1/1 3/3 4/4\n"));
}

}  // namespace

TEST(TexturedMeshes, EachTexelShowsWhereTheUvMappingPutsIt)
{
  const std::string dir = tempDir();
  auto quad = texturedQuad(dir);
  ASSERT_TRUE(quad);
  ASSERT_TRUE(quad->submeshes[0].image) << quad->submeshes[0].texture_problem;
  RayScene scene({RayPrimitive::fromMesh(quad, poseFromXyzRpy(0, 0, 0, 0, 0, 0), nullptr)});
  scene.commit(nullptr);
  // Rays along -x through the quad's points: texel column from s = y, row from the top from t = z.
  const double towards[3] = {-1, 0, 0};
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
    {
      const double y = (c + 0.5) / 4, z = 1.0 - (r + 0.5) / 4;
      const double o[3] = {1, y, z};
      const RayHit hit = scene.castHit(o, towards, 0, 5, kSeenByAll);
      ASSERT_NE(hit.primitive, nullptr);
      const Rgba colour = hit.primitive->surfaceColour(hit.triangle, hit.u, hit.v);
      EXPECT_NEAR(colour.r * 255, 16 * c + 8, 1e-3) << "texel " << c << ", " << r;
      EXPECT_NEAR(colour.g * 255, 16 * r + 8, 1e-3) << "texel " << c << ", " << r;
      EXPECT_NEAR(colour.b * 255, 200, 1e-3);
    }
}

// Every case here runs once per ISA of Embree's kernels this CPU runs (test/cpp/test_gtests.py sets
// TIANRACER_EMBREE_ISA). A lidar's rays go in packets of 16: a fan of any size leaves lanes of its
// last packet unused, and a range Embree cannot take leaves lanes invalid. The 16-wide kernels
// (AVX-512) skip those lanes by the valid mask; the narrower ones cast every lane whose interval is
// not empty, and Embree aborts the process on one holding a ray it does not accept. Each ray of a
// fan must give what it gives cast alone.
TEST(LidarRays, FansOfAnySizeAndRangeGiveWhatEachRayGivesAlone)
{
  const RayPrimitive ground = primitive(Shape::Kind::Plane, 0, 0, 1, poseFromXyzRpy(0, 0, 0, 0, 0, 0));
  const RayPrimitive wall = primitive(Shape::Kind::Box, 0.2, 8, 3, poseFromXyzRpy(3, 0, 1, 0, 0, 0));
  const RayPrimitive post = primitive(Shape::Kind::Cylinder, 0.1, 2, 0, poseFromXyzRpy(1, 0.5, 1, 0, 0, 0));
  RayScene scene({ground, wall, post});
  scene.commit(nullptr);
  const Frame sensor = Frame::fromPose(poseFromXyzRpy(0, 0, 0.5, 0, 0, 0.1));
  const double nan = std::nan("");
  // (near, far): the usual, from 0, a range empty or reversed, and ones Embree cannot take
  const std::vector<std::pair<double, double>> ranges = {{0.1, 10}, {0, 10}, {2, 2}, {5, 1}, {0, 0},
                                                         {nan, 10}, {0.1, nan}, {-1, 10}, {0.1, kInf}};
  int hits = 0;
  for (int n : {1, 2, 5, 15, 16, 17, 31, 33, 100, 3000})
    for (const auto& [near, far] : ranges)
    {
      const std::vector<double> directions = fanDirections(-1.5, 3.0 / n, n, {-0.2, 0.0});
      std::vector<double> fan;
      scene.castRays(sensor, directions, near, far, kSeenByLidars, fan);
      ASSERT_EQ(fan.size(), directions.size() / 3);
      for (size_t i = 0; i < fan.size(); ++i)
      {
        double dir[3];
        sensor.rotate(&directions[3 * i], dir);
        const double alone = scene.castHit(sensor.t, dir, near, far, kSeenByLidars).distance;
        if (std::isinf(alone))
          EXPECT_EQ(fan[i], alone) << n << " rays, ray " << i << ", range [" << near << ", " << far << "]";
        else
          EXPECT_NEAR(fan[i], alone, kFloatTolerance) << n << " rays, ray " << i << ", range [" << near << ", " << far << "]";
        hits += std::isfinite(fan[i]);
      }
    }
  EXPECT_GT(hits, 1000) << "the fans see the ground, the wall and the post";
}

TEST(EmbreeKernels, TheVariableNamesTheKernelsOfTheScenesMadeAfterIt)
{
  const char* outer = std::getenv(kEmbreeIsaVariable);
  const std::string restore = outer ? outer : "";
  const std::vector<std::string> isas = embreeIsasThisCpuRuns();
  ASSERT_FALSE(isas.empty());
  EXPECT_EQ(isas.front(), "sse2") << "every x86-64 CPU runs SSE2";

  unsetenv(kEmbreeIsaVariable);
  EXPECT_EQ(embreeIsa().name, isas.back()) << "by default the widest, as Embree picks";
  EXPECT_FALSE(embreeIsa().forced);
  const double o[3] = {0, 0, 0}, x[3] = {1, 0, 0};
  for (const std::string& isa : isas)
  {
    setenv(kEmbreeIsaVariable, isa.c_str(), 1);
    RayScene scene({primitive(Shape::Kind::Box, 1, 1, 1, poseFromXyzRpy(3, 0, 0, 0, 0, 0))});
    scene.commit(nullptr);
    EXPECT_EQ(scene.isa().name, isa);
    EXPECT_TRUE(scene.isa().forced);
    EXPECT_EQ(scene.isa().problem, "");
    EXPECT_NEAR(scene.cast(o, x, 10, kSeenByAll), 2.5, kFloatTolerance) << isa;
  }
  setenv(kEmbreeIsaVariable, "avx9", 1);
  const EmbreeIsa unknown = embreeIsa();
  EXPECT_EQ(unknown.name, isas.back());
  EXPECT_FALSE(unknown.forced);
  EXPECT_NE(unknown.problem.find("TIANRACER_EMBREE_ISA='avx9' is not one of sse2, sse4.2, avx, avx2, avx512"),
            std::string::npos)
      << unknown.problem;
  if (isas.back() != "avx512")
  {
    setenv(kEmbreeIsaVariable, "avx512", 1);
    EXPECT_NE(embreeIsa().problem.find("this CPU has no avx512"), std::string::npos) << embreeIsa().problem;
  }
  if (restore.empty())
    unsetenv(kEmbreeIsaVariable);
  else
    setenv(kEmbreeIsaVariable, restore.c_str(), 1);
}
