// The plant's one spatial-math vocabulary: 3-vectors as double[3], rotations as row-major 3 x 3
// double[9], a rigid transform (Frame), and 6-vectors (SpatialVector) for the dynamics' motions
// and forces. Plain arrays in double precision, so the dynamics and the ray caster can keep their
// data flat and their arithmetic in one known order (the trajectory digest depends on that order).
// An output never aliases an input (rotate(R, x, x) would read entries it has overwritten).
#pragma once

#include <cmath>

#include <urdf_model/pose.h>

namespace bullet_plant
{
inline double dot(const double* a, const double* b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

inline double norm(const double* x) { return std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]); }

inline void cross(const double* a, const double* b, double* out)
{
  out[0] = a[1] * b[2] - a[2] * b[1];
  out[1] = a[2] * b[0] - a[0] * b[2];
  out[2] = a[0] * b[1] - a[1] * b[0];
}

// y = R x for a row-major 3 x 3 R.
inline void rotate(const double* R, const double* x, double* y)
{
  for (int a = 0; a < 3; ++a)
    y[a] = R[3 * a] * x[0] + R[3 * a + 1] * x[1] + R[3 * a + 2] * x[2];
}

// y = R^T x for a row-major 3 x 3 R (the inverse rotation).
inline void inverseRotate(const double* R, const double* x, double* y)
{
  for (int a = 0; a < 3; ++a)
    y[a] = R[a] * x[0] + R[3 + a] * x[1] + R[6 + a] * x[2];
}

// The dot product of two n-vectors (generalized velocities, Jacobian rows), summed in index order.
template <typename T>
T dot(const T* a, const T* b, int n)
{
  T sum = 0;
  for (int i = 0; i < n; ++i)
    sum += a[i] * b[i];
  return sum;
}

// A rigid transform: world = R * local + t.
struct Frame
{
  double R[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};  // row-major rotation
  double t[3] = {0, 0, 0};
  static Frame fromPose(const urdf::Pose& p);
  Frame operator*(const Frame& b) const;  // b's local coordinates to this frame's world: (R Rb, R tb + t)
  void apply(const double in[3], double out[3]) const  // R*in + t
  {
    rotate(in, out);
    for (int i = 0; i < 3; ++i)
      out[i] += t[i];
  }
  void rotate(const double in[3], double out[3]) const { bullet_plant::rotate(R, in, out); }  // R*in
  void inverseApply(const double in[3], double out[3]) const  // R^T*(in - t)
  {
    const double v[3] = {in[0] - t[0], in[1] - t[1], in[2] - t[2]};
    inverseRotate(v, out);
  }
  void inverseRotate(const double in[3], double out[3]) const { bullet_plant::inverseRotate(R, in, out); }  // R^T*in
};

// A spatial 6-vector at a body's centre of mass, in some frame's axes: a motion (angular velocity
// w, linear velocity v of the centre of mass) or a force (moment w about the centre of mass,
// force v).
struct SpatialVector
{
  double w[3], v[3];
};

}  // namespace bullet_plant
