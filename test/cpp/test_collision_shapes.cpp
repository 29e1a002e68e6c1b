// collision_shapes.cpp: one Shape -> Bullet switch with one margin rule, the aligned-primitive
// shortcut, and URDF geometry read as Shapes.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <BulletCollision/CollisionShapes/btBvhTriangleMeshShape.h>
#include <BulletCollision/CollisionShapes/btConvexHullShape.h>

#include "log_capture.h"
#include "simulation/collision_shapes.h"
#include "mesh_fixtures.h"

using namespace bullet_plant;

namespace
{
Shape box(double x, double y, double z)
{
  Shape s;
  s.kind = Shape::Kind::Box;
  s.box_size = {{x, y, z}};
  return s;
}

Shape cylinder(double radius, double length)
{
  Shape s;
  s.kind = Shape::Kind::Cylinder;
  s.radius = radius;
  s.length = length;
  return s;
}

btTransform rotatedAbout(const btVector3& axis, double angle, const btVector3& origin = btVector3(0, 0, 0))
{
  return btTransform(btQuaternion(axis, btScalar(angle)), origin);
}
}  // namespace

TEST(MakeCollisionShape, BoxKeepsItsOuterSizeWithTheHalfMillimetreMargin)
{
  std::unique_ptr<btCollisionShape> shape(makeCollisionShape(box(0.4, 0.2, 0.1)));
  auto* b = dynamic_cast<btBoxShape*>(shape.get());
  ASSERT_NE(b, nullptr);
  EXPECT_FLOAT_EQ(b->getMargin(), 0.0005f);
  const btVector3 half = b->getHalfExtentsWithMargin();
  EXPECT_FLOAT_EQ(half.x(), 0.2f);
  EXPECT_FLOAT_EQ(half.y(), 0.1f);
  EXPECT_FLOAT_EQ(half.z(), 0.05f);
}

TEST(MakeCollisionShape, CylinderAlongZSphereAndPlaneKeepBulletsMargins)
{
  std::unique_ptr<btCollisionShape> c(makeCollisionShape(cylinder(0.032, 0.025)));
  auto* z = dynamic_cast<btCylinderShapeZ*>(c.get());
  ASSERT_NE(z, nullptr);
  EXPECT_FLOAT_EQ(z->getMargin(), 0.0005f);
  EXPECT_FLOAT_EQ(z->getHalfExtentsWithMargin().z(), 0.0125f);
  EXPECT_FLOAT_EQ(z->getRadius(), 0.032f);

  Shape s;
  s.kind = Shape::Kind::Sphere;
  s.radius = 0.1;
  std::unique_ptr<btCollisionShape> sphere(makeCollisionShape(s));
  EXPECT_FLOAT_EQ(sphere->getMargin(), 0.1f) << "a sphere's margin is its radius";

  Shape p;
  p.kind = Shape::Kind::Plane;
  p.normal = urdf::Vector3(0, 0, 1);
  std::unique_ptr<btCollisionShape> plane(makeCollisionShape(p));
  auto* sp = dynamic_cast<btStaticPlaneShape*>(plane.get());
  ASSERT_NE(sp, nullptr);
  EXPECT_FLOAT_EQ(sp->getPlaneNormal().z(), 1.0f);
}

TEST(MakeAlignedCollisionShape, PermutedBoxAxesBecomeAPlainBox)
{
  std::unique_ptr<btCollisionShape> shape(
      makeAlignedCollisionShape(box(0.4, 0.2, 0.1), rotatedAbout(btVector3(0, 0, 1), M_PI / 2)));
  auto* b = dynamic_cast<btBoxShape*>(shape.get());
  ASSERT_NE(b, nullptr);
  const btVector3 half = b->getHalfExtentsWithMargin();
  EXPECT_NEAR(half.x(), 0.1, 1e-6) << "the box's y axis lies along the body's x";
  EXPECT_NEAR(half.y(), 0.2, 1e-6);
  EXPECT_NEAR(half.z(), 0.05, 1e-6);
}

TEST(MakeAlignedCollisionShape, AWheelTurnedOntoYIsBulletsYCylinder)
{
  // A URDF wheel: a z cylinder rolled by pi/2 about x, so its axis is the body's y.
  std::unique_ptr<btCollisionShape> shape(
      makeAlignedCollisionShape(cylinder(0.032, 0.025), rotatedAbout(btVector3(1, 0, 0), M_PI / 2)));
  auto* y = dynamic_cast<btCylinderShape*>(shape.get());
  ASSERT_NE(y, nullptr);
  EXPECT_EQ(y->getUpAxis(), 1);
  EXPECT_NEAR(y->getHalfExtentsWithMargin().y(), 0.0125, 1e-6);
}

TEST(MakeAlignedCollisionShape, OffsetsAndObliqueRotationsNeedACompound)
{
  EXPECT_EQ(makeAlignedCollisionShape(box(1, 1, 1), btTransform(btQuaternion::getIdentity(), btVector3(0.1f, 0, 0))),
            nullptr);
  EXPECT_EQ(makeAlignedCollisionShape(box(1, 2, 3), rotatedAbout(btVector3(0, 0, 1), M_PI / 4)), nullptr);
  EXPECT_EQ(makeAlignedCollisionShape(cylinder(0.1, 0.2), rotatedAbout(btVector3(1, 0, 0), 0.3)), nullptr);
}

TEST(ShapeFromUrdf, ReadsPrimitivesAndRefusesNonPositiveSizesWithAWarning)
{
  WarningsCapture c;
  Shape s;
  urdf::Cylinder wheel;
  wheel.radius = 0.032;
  wheel.length = 0.025;
  ASSERT_TRUE(shapeFromUrdf(wheel, "wheel", c.log, s));
  EXPECT_EQ(s.kind, Shape::Kind::Cylinder);
  EXPECT_DOUBLE_EQ(s.radius, 0.032);
  EXPECT_TRUE(c.warnings.empty());

  urdf::Box flat;
  flat.dim = urdf::Vector3(0.1, 0.0, 0.1);
  EXPECT_FALSE(shapeFromUrdf(flat, "chassis", c.log, s));
  ASSERT_EQ(c.warnings.size(), 1u);
  EXPECT_NE(c.warnings[0].find("'chassis'"), std::string::npos) << c.warnings[0];
}

TEST(ShapeFromUrdf, AMissingMeshFileIsAWarningNamingTheLink)
{
  WarningsCapture c;
  Shape s;
  urdf::Mesh mesh;
  mesh.filename = "/nonexistent/track.stl";
  EXPECT_FALSE(shapeFromUrdf(mesh, "track", c.log, s));
  ASSERT_EQ(c.warnings.size(), 1u);
  EXPECT_NE(c.warnings[0].find("'track'"), std::string::npos) << c.warnings[0];
  EXPECT_NE(c.warnings[0].find("/nonexistent/track.stl"), std::string::npos) << c.warnings[0];
}

namespace
{
Shape meshShape(const std::string& file)
{
  Shape s;
  s.kind = Shape::Kind::Mesh;
  s.mesh_uri = "file://" + file;
  s.mesh_file = file;
  return s;
}

// A UV sphere of radius r with `rings` x `segments` quads, as an OBJ: many more vertices than a
// moving body's hull keeps.
std::string sphereObj(const std::string& dir, double r, int rings, int segments)
{
  std::string obj;
  for (int i = 0; i <= rings; ++i)
    for (int j = 0; j < segments; ++j)
    {
      const double polar = M_PI * i / rings, azimuth = 2 * M_PI * j / segments;
      obj += "v " + std::to_string(r * std::sin(polar) * std::cos(azimuth)) + " " +
             std::to_string(r * std::sin(polar) * std::sin(azimuth)) + " " + std::to_string(r * std::cos(polar)) + "\n";
    }
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < segments; ++j)
    {
      const int a = i * segments + j + 1, b = i * segments + (j + 1) % segments + 1;
      obj += "f " + std::to_string(a) + " " + std::to_string(b) + " " + std::to_string(b + segments) + "\n";
      obj += "f " + std::to_string(a) + " " + std::to_string(b + segments) + " " + std::to_string(a + segments) + "\n";
    }
  return mesh_fixtures::write(dir, "ball.obj", obj);
}
}  // namespace

TEST(MakeCollider, AStaticMeshIsItsExactTrianglesWithTheHalfMillimetreMargin)
{
  const std::string dir = mesh_fixtures::tempDir();
  const float lo[3] = {-1, -1, -0.1f}, hi[3] = {1, 1, 0};
  const Collider c = makeCollider(meshShape(mesh_fixtures::binaryBoxStl(dir, "slab.stl", lo, hi)), Mobility::Static,
                                  urdf::Pose(), nullptr);
  ASSERT_TRUE(c.shape) << c.reason;
  auto* mesh = dynamic_cast<btBvhTriangleMeshShape*>(c.shape.get());
  ASSERT_NE(mesh, nullptr) << "a static mesh collides as Bullet's BVH triangle mesh";
  EXPECT_FLOAT_EQ(mesh->getMargin(), kCollisionMargin);
  EXPECT_EQ(mesh->getMeshInterface()->getNumSubParts(), 1);
  btVector3 aabb_lo, aabb_hi;
  mesh->getAabb(btTransform::getIdentity(), aabb_lo, aabb_hi);
  EXPECT_NEAR(aabb_hi.z(), kCollisionMargin, 1e-6);
  EXPECT_NEAR(aabb_lo.x(), -1.0f - kCollisionMargin, 1e-6);
  EXPECT_TRUE(c.note.empty());
  EXPECT_EQ(c.ray.kind, Shape::Kind::Mesh);
}

TEST(MakeCollider, BodiesOfTheSameStaticMeshShareItsShapeWithItsEdgeAngles)
{
  const std::string dir = mesh_fixtures::tempDir();
  const float lo[3] = {-1, -1, -0.1f}, hi[3] = {1, 1, 0};
  const Shape slab = meshShape(mesh_fixtures::binaryBoxStl(dir, "slab.stl", lo, hi));
  const Collider first = makeCollider(slab, Mobility::Static, urdf::Pose(), nullptr);
  const Collider second = makeCollider(slab, Mobility::Static, poseFromXyzRpy(3, 0, 0, 0, 0, 0), nullptr);
  ASSERT_TRUE(first.shape && second.shape);
  EXPECT_EQ(first.shape, second.shape) << "one BVH for both (each body has its own pose)";
  EXPECT_NE(static_cast<btBvhTriangleMeshShape*>(first.shape.get())->getTriangleInfoMap(), nullptr)
      << "the angles between its faces, for correctInternalEdges";
  const Collider moving = makeCollider(slab, Mobility::Moving, urdf::Pose(), nullptr);
  const Collider moving_too = makeCollider(slab, Mobility::Moving, urdf::Pose(), nullptr);
  EXPECT_NE(moving.shape, moving_too.shape) << "hulls are each body's own";
}

TEST(MakeCollider, AMovingMeshIsItsConvexHullOfAtMostTheVertexBound)
{
  const std::string dir = mesh_fixtures::tempDir();
  const Collider ball = makeCollider(meshShape(sphereObj(dir, 0.5, 24, 32)), Mobility::Moving, urdf::Pose(), nullptr);
  ASSERT_TRUE(ball.shape) << ball.reason;
  auto* hull = dynamic_cast<btConvexHullShape*>(ball.shape.get());
  ASSERT_NE(hull, nullptr);
  EXPECT_LE(hull->getNumPoints(), kMaxHullVertices);
  EXPECT_GE(hull->getNumPoints(), 20);
  // Still the ball: its support along any axis within a few millimetres of the radius.
  for (const btVector3& d : {btVector3(1, 0, 0), btVector3(0, 0, -1), btVector3(1, 1, 1).normalized()})
    EXPECT_NEAR(d.dot(hull->localGetSupportingVertex(d)), 0.5f, 0.02f);
  EXPECT_NE(ball.note.find("convex hull"), std::string::npos) << ball.note;

  // A box's hull is the box: its outer size with the margin is the mesh's.
  const float lo[3] = {-0.1f, -0.05f, 0.0f}, hi[3] = {0.1f, 0.05f, 0.06f};
  const Collider box = makeCollider(meshShape(mesh_fixtures::binaryBoxStl(dir, "slab.stl", lo, hi)), Mobility::Moving,
                                    urdf::Pose(), nullptr);
  auto* box_hull = dynamic_cast<btConvexHullShape*>(box.shape.get());
  ASSERT_NE(box_hull, nullptr);
  EXPECT_EQ(box_hull->getNumPoints(), 8);
  EXPECT_FLOAT_EQ(box_hull->getMargin(), kCollisionMargin);
  EXPECT_NEAR(box_hull->localGetSupportingVertex(btVector3(0, 0, -1)).z(), 0.0f, 2e-5);
  EXPECT_NEAR(box_hull->localGetSupportingVertex(btVector3(1, 0, 0)).x(), 0.1f, 2e-5);
}

TEST(MakeCollider, AnUnreadableMeshHasNoShapeAndAReason)
{
  const std::string dir = mesh_fixtures::tempDir();
  const Collider c = makeCollider(meshShape(mesh_fixtures::write(dir, "bad.stl", "not a mesh")), Mobility::Static,
                                  urdf::Pose(), nullptr);
  EXPECT_FALSE(c.shape);
  EXPECT_FALSE(c.reason.empty());
}

TEST(FitWheelCylinder, AWheelMeshIsTheCylinderAboutItsAxisAndABoxIsNot)
{
  const std::string dir = mesh_fixtures::tempDir();
  std::string reason;
  auto wheel = loadMesh(mesh_fixtures::wheelObj(dir, "wheel.obj", 0.05, 0.03, 24), urdf::Vector3(1, 1, 1), reason);
  ASSERT_TRUE(wheel) << reason;
  Shape cylinder;
  btTransform pose;
  ASSERT_TRUE(fitWheelCylinder(*wheel, btTransform::getIdentity(), btVector3(0, 1, 0), cylinder, pose));
  EXPECT_EQ(cylinder.kind, Shape::Kind::Cylinder);
  EXPECT_NEAR(cylinder.radius, 0.05, 1e-6);
  EXPECT_NEAR(cylinder.length, 0.03, 1e-6);
  EXPECT_NEAR(btFabs((pose.getBasis() * btVector3(0, 0, 1)).y()), 1.0f, 1e-6) << "its z along the axis";
  EXPECT_NEAR(pose.getOrigin().length(), 0.0f, 1e-6);

  // Not about another axis, nor about the wheel's axis moved off its centre.
  EXPECT_FALSE(fitWheelCylinder(*wheel, btTransform::getIdentity(), btVector3(1, 0, 0), cylinder, pose));
  EXPECT_FALSE(fitWheelCylinder(*wheel, btTransform(btQuaternion::getIdentity(), btVector3(0.02f, 0, 0)),
                                btVector3(0, 1, 0), cylinder, pose));
  // A square prism about the same axis is no wheel.
  auto square = loadMesh(mesh_fixtures::wheelObj(dir, "square.obj", 0.05, 0.03, 4), urdf::Vector3(1, 1, 1), reason);
  ASSERT_TRUE(square) << reason;
  EXPECT_FALSE(fitWheelCylinder(*square, btTransform::getIdentity(), btVector3(0, 1, 0), cylinder, pose));
}
