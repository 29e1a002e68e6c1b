// collision_shapes.cpp: one Shape -> Bullet switch with one margin rule, the aligned-primitive
// shortcut, and URDF geometry read as Shapes.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "collision_shapes.h"

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

struct Captured
{
  Log log;
  std::vector<std::string> warnings;
  Captured()
  {
    log.setSink([this](LogLevel level, const std::string& m) {
      if (level == LogLevel::Warn)
        warnings.push_back(m);
    });
  }
};
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
  Captured c;
  Shape s;
  btTransform offset;
  urdf::Cylinder wheel;
  wheel.radius = 0.032;
  wheel.length = 0.025;
  ASSERT_TRUE(shapeFromUrdf(wheel, "wheel", c.log, s, offset));
  EXPECT_EQ(s.kind, Shape::Kind::Cylinder);
  EXPECT_DOUBLE_EQ(s.radius, 0.032);
  EXPECT_TRUE(c.warnings.empty());

  urdf::Box flat;
  flat.dim = urdf::Vector3(0.1, 0.0, 0.1);
  EXPECT_FALSE(shapeFromUrdf(flat, "chassis", c.log, s, offset));
  ASSERT_EQ(c.warnings.size(), 1u);
  EXPECT_NE(c.warnings[0].find("'chassis'"), std::string::npos) << c.warnings[0];
}

TEST(ShapeFromUrdf, AMissingMeshFileIsAWarningNamingTheLink)
{
  Captured c;
  Shape s;
  btTransform offset;
  urdf::Mesh mesh;
  mesh.filename = "/nonexistent/track.stl";
  EXPECT_FALSE(shapeFromUrdf(mesh, "track", c.log, s, offset));
  ASSERT_EQ(c.warnings.size(), 1u);
  EXPECT_NE(c.warnings[0].find("'track'"), std::string::npos) << c.warnings[0];
}
