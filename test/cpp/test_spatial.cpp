// The spatial vocabulary (physics/spatial.h): hand-computed values and identities.
#include <gtest/gtest.h>

#include <cmath>

#include "physics/spatial.h"

namespace bullet_plant
{
namespace
{
void expectNear(const double* a, const double* b, int n = 3, double tolerance = 1e-12)
{
  for (int i = 0; i < n; ++i)
    EXPECT_NEAR(a[i], b[i], tolerance) << "entry " << i;
}

urdf::Pose pose(double x, double y, double z, double roll, double pitch, double yaw)
{
  urdf::Pose p;
  p.position = urdf::Vector3(x, y, z);
  p.rotation.setFromRPY(roll, pitch, yaw);
  return p;
}

TEST(Spatial, DotNormCrossByHand)
{
  const double a[3] = {1, 2, 3}, b[3] = {-4, 5, 0.5};
  EXPECT_DOUBLE_EQ(dot(a, b), -4 + 10 + 1.5);
  EXPECT_DOUBLE_EQ(norm(a), std::sqrt(14.0));
  double c[3];
  cross(a, b, c);
  const double expected[3] = {2 * 0.5 - 3 * 5, 3 * -4 - 1 * 0.5, 1 * 5 - 2 * -4};
  expectNear(c, expected);
  EXPECT_NEAR(dot(c, a), 0, 1e-12);  // perpendicular to both
  EXPECT_NEAR(dot(c, b), 0, 1e-12);
  const double x[3] = {1, 0, 0}, y[3] = {0, 1, 0}, z[3] = {0, 0, 1};
  cross(x, y, c);
  expectNear(c, z);  // right-handed
  const float u[4] = {1, 2, 3, 4}, v[4] = {0.5f, -1, 2, 0.25f};
  EXPECT_FLOAT_EQ(dot(u, v, 4), 0.5f - 2 + 6 + 1);
}

TEST(Spatial, RotateAndInverseRotate)
{
  // A quarter turn about z, row-major: x -> y, y -> -x.
  const double R[9] = {0, -1, 0, 1, 0, 0, 0, 0, 1};
  const double x[3] = {1, 0, 0}, y[3] = {0, 1, 0}, minus_x[3] = {-1, 0, 0};
  double out[3];
  rotate(R, x, out);
  expectNear(out, y);
  rotate(R, y, out);
  expectNear(out, minus_x);
  inverseRotate(R, y, out);
  expectNear(out, x);
  // R^T R v = v for a general rotation.
  const Frame f = Frame::fromPose(pose(0, 0, 0, 0.3, -1.1, 2.5));
  const double v[3] = {0.2, -3, 1.7};
  double w[3], back[3];
  rotate(f.R, v, w);
  inverseRotate(f.R, w, back);
  expectNear(back, v);
  EXPECT_NEAR(norm(w), norm(v), 1e-12);
}

TEST(Spatial, FrameFromPoseByHand)
{
  // Yaw of 90 degrees and a translation: local x lands on world y, shifted.
  const Frame f = Frame::fromPose(pose(1, 2, 3, 0, 0, M_PI / 2));
  const double local[3] = {1, 0, 0}, expected[3] = {1, 3, 3};
  double world[3];
  f.apply(local, world);
  expectNear(world, expected);
  double back[3];
  f.inverseApply(world, back);
  expectNear(back, local);
  const double rotated_expected[3] = {0, 1, 0};
  double rotated[3];
  f.rotate(local, rotated);
  expectNear(rotated, rotated_expected);
  f.inverseRotate(rotated, back);
  expectNear(back, local);
}

TEST(Spatial, FrameCompositionAndInverse)
{
  const Frame a = Frame::fromPose(pose(0.5, -1, 2, 0.2, 0.4, -0.7));
  const Frame b = Frame::fromPose(pose(-0.3, 0.8, 0.1, -1.2, 0.1, 2.0));
  const Frame ab = a * b;
  const double p[3] = {0.7, 0.2, -1.5};
  double via_b[3], composed[3], stepwise[3];
  b.apply(p, via_b);
  a.apply(via_b, stepwise);
  ab.apply(p, composed);
  expectNear(composed, stepwise);
  // The identity is neutral on both sides.
  const Frame identity;
  const Frame left = identity * a, right = a * identity;
  expectNear(left.R, a.R, 9);
  expectNear(right.R, a.R, 9);
  expectNear(left.t, a.t);
  expectNear(right.t, a.t);
  // Undoing the composition step by step returns the point.
  double back[3];
  ab.inverseApply(composed, via_b);
  expectNear(via_b, p);
  double via_a[3];
  a.inverseApply(composed, via_a);
  b.inverseApply(via_a, back);
  expectNear(back, p);
  // The composition of rotations agrees with the matrix product: (R_a R_b) e_k.
  for (int k = 0; k < 3; ++k)
  {
    const double e[3] = {double(k == 0), double(k == 1), double(k == 2)};
    double rb[3], rab[3], column[3];
    b.rotate(e, rb);
    a.rotate(rb, rab);
    ab.rotate(e, column);
    expectNear(column, rab);
  }
}

TEST(Spatial, FrameFromPoseNormalizesTheQuaternion)
{
  urdf::Pose p = pose(0, 0, 0, 0.1, 0.2, 0.3);
  urdf::Pose scaled = p;
  scaled.rotation.x *= 3;
  scaled.rotation.y *= 3;
  scaled.rotation.z *= 3;
  scaled.rotation.w *= 3;
  expectNear(Frame::fromPose(scaled).R, Frame::fromPose(p).R, 9);
}

}  // namespace
}  // namespace bullet_plant
