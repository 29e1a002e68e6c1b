#include "previous_ray_caster.h"

#include "ray_caster.h"  // the analytic sphere and cylinder, unchanged since

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <mutex>

namespace bullet_plant
{
namespace previous
{
namespace
{
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kTwoPi = 2.0 * M_PI;

double intersectBox(const double o[3], const double d[3], const double h[3])
{
  double t_near = -kInf, t_far = kInf;
  bool inside = true;
  for (int i = 0; i < 3; ++i)
  {
    inside = inside && std::abs(o[i]) < h[i];
    if (d[i] == 0.0)
    {
      if (std::abs(o[i]) > h[i])
        return kInf;
      continue;
    }
    double inv = 1.0 / d[i];
    double t0 = (-h[i] - o[i]) * inv, t1 = (h[i] - o[i]) * inv;
    if (t0 > t1)
      std::swap(t0, t1);
    t_near = std::max(t_near, t0);
    t_far = std::min(t_far, t1);
  }
  if (inside || t_near > t_far || t_near < 0.0)
    return kInf;
  return t_near;
}

double intersectPlane(const double o[3], const double d[3], const double n[3])
{
  double height = dot(o, n), approach = dot(d, n);
  if (height <= 0.0 || approach >= 0.0)
    return kInf;
  return -height / approach;
}

// Entry distance of the ray into the box, or +inf if it misses it or it lies beyond `limit`.
double slabEntry(const float lo[3], const float hi[3], const double o[3], const double inv[3], double limit)
{
  double t_near = 0.0, t_far = limit;
  for (int i = 0; i < 3; ++i)
  {
    double t0 = (lo[i] - o[i]) * inv[i], t1 = (hi[i] - o[i]) * inv[i];
    if (t0 > t1)
      std::swap(t0, t1);
    t_near = t0 > t_near ? t0 : t_near;
    t_far = t1 < t_far ? t1 : t_far;
    if (t_near > t_far)
      return kInf;
  }
  return t_near;
}

double wrapAngle(double a)
{
  a = std::fmod(a, kTwoPi);
  return a < 0 ? a + kTwoPi : a;
}
}  // namespace

TriangleBvh::TriangleBvh(std::shared_ptr<const MeshData> mesh) : mesh_(std::move(mesh))
{
  const MeshData& m = *mesh_;
  const int n = m.triangleCount();
  triangles_.resize(n);
  std::vector<float> centroids(3 * n);
  for (int t = 0; t < n; ++t)
  {
    Triangle& tri = triangles_[t];
    const float* v[3];
    for (int k = 0; k < 3; ++k)
      v[k] = &m.vertices[3 * m.indices[3 * t + k]];
    for (int i = 0; i < 3; ++i)
    {
      tri.v0[i] = v[0][i];
      tri.e1[i] = double(v[1][i]) - v[0][i];
      tri.e2[i] = double(v[2][i]) - v[0][i];
      centroids[3 * t + i] = (v[0][i] + v[1][i] + v[2][i]) / 3.0f;
    }
    tri.index = t;
  }
  for (int v = 0; v < m.vertexCount(); ++v)
  {
    const double p[3] = {m.vertices[3 * v], m.vertices[3 * v + 1], m.vertices[3 * v + 2]};
    bound_radius_ = std::max(bound_radius_, norm(p));
  }
  nodes_.reserve(2 * n);
  build(0, n, centroids);
}

int TriangleBvh::build(int first, int count, std::vector<float>& centroids)
{
  const int index = int(nodes_.size());
  nodes_.emplace_back();
  Node node;
  float c_lo[3] = {1e30f, 1e30f, 1e30f}, c_hi[3] = {-1e30f, -1e30f, -1e30f};
  for (int i = 0; i < 3; ++i)
  {
    node.lo[i] = 1e30f;
    node.hi[i] = -1e30f;
  }
  for (int t = first; t < first + count; ++t)
  {
    const Triangle& tri = triangles_[t];
    for (int i = 0; i < 3; ++i)
    {
      for (double corner : {tri.v0[i], tri.v0[i] + tri.e1[i], tri.v0[i] + tri.e2[i]})
      {
        node.lo[i] = std::min(node.lo[i], std::nextafter(float(corner), -1e30f));
        node.hi[i] = std::max(node.hi[i], std::nextafter(float(corner), 1e30f));
      }
      c_lo[i] = std::min(c_lo[i], centroids[3 * tri.index + i]);
      c_hi[i] = std::max(c_hi[i], centroids[3 * tri.index + i]);
    }
  }
  constexpr int kLeafSize = 4;
  if (count <= kLeafSize)
  {
    node.first = first;
    node.count = count;
    nodes_[index] = node;
    return index;
  }
  int axis = 0;
  for (int i = 1; i < 3; ++i)
    if (c_hi[i] - c_lo[i] > c_hi[axis] - c_lo[axis])
      axis = i;
  const int half = count / 2;
  std::nth_element(triangles_.begin() + first, triangles_.begin() + first + half, triangles_.begin() + first + count,
                   [&](const Triangle& a, const Triangle& b) {
                     return centroids[3 * a.index + axis] < centroids[3 * b.index + axis];
                   });
  build(first, half, centroids);
  node.first = build(first + half, count - half, centroids);
  nodes_[index] = node;
  return index;
}

std::shared_ptr<const TriangleBvh> TriangleBvh::of(const std::shared_ptr<const MeshData>& mesh)
{
  static std::mutex mutex;
  static std::map<const MeshData*, std::weak_ptr<const TriangleBvh>> built;
  std::lock_guard<std::mutex> lock(mutex);
  std::shared_ptr<const TriangleBvh> bvh = built[mesh.get()].lock();
  if (!bvh)
  {
    bvh = std::make_shared<const TriangleBvh>(mesh);
    built[mesh.get()] = bvh;
  }
  return bvh;
}

double TriangleBvh::intersect(const double o[3], const double d[3], int& triangle) const
{
  double inv[3];
  for (int i = 0; i < 3; ++i)
    inv[i] = 1.0 / d[i];  // +-inf along an axis the ray does not move on: the slab test still holds
  double best = kInf;
  int stack[64], depth = 0;
  if (slabEntry(nodes_[0].lo, nodes_[0].hi, o, inv, best) == kInf)
    return kInf;
  stack[depth++] = 0;
  while (depth > 0)
  {
    const Node& node = nodes_[stack[--depth]];
    if (node.count > 0)
    {
      // Moeller-Trumbore, either side of the triangle
      for (int k = node.first; k < node.first + node.count; ++k)
      {
        const Triangle& tri = triangles_[k];
        double p[3];
        cross(d, tri.e2, p);
        const double det = dot(tri.e1, p);
        if (std::abs(det) < 1e-300)
          continue;
        const double inv_det = 1.0 / det;
        const double s[3] = {o[0] - tri.v0[0], o[1] - tri.v0[1], o[2] - tri.v0[2]};
        const double u = dot(s, p) * inv_det;
        if (u < 0.0 || u > 1.0)
          continue;
        double q[3];
        cross(s, tri.e1, q);
        const double v = dot(d, q) * inv_det;
        if (v < 0.0 || u + v > 1.0)
          continue;
        const double t = dot(tri.e2, q) * inv_det;
        if (t > 0.0 && t < best)
        {
          best = t;
          triangle = tri.index;
        }
      }
      continue;
    }
    const int a = int(&node - nodes_.data()) + 1, b = node.first;
    const double ta = slabEntry(nodes_[a].lo, nodes_[a].hi, o, inv, best);
    const double tb = slabEntry(nodes_[b].lo, nodes_[b].hi, o, inv, best);
    // the nearer child on top of the stack, so hits there prune the other
    if (ta <= tb)
    {
      if (tb != kInf)
        stack[depth++] = b;
      if (ta != kInf)
        stack[depth++] = a;
    }
    else
    {
      if (ta != kInf)
        stack[depth++] = a;
      stack[depth++] = b;
    }
  }
  return best;
}

void TriangleBvh::normal(int triangle, double out[3]) const
{
  const MeshData& m = *mesh_;
  const float* v[3];
  for (int k = 0; k < 3; ++k)
    v[k] = &m.vertices[3 * m.indices[3 * triangle + k]];
  const double e1[3] = {double(v[1][0]) - v[0][0], double(v[1][1]) - v[0][1], double(v[1][2]) - v[0][2]};
  const double e2[3] = {double(v[2][0]) - v[0][0], double(v[2][1]) - v[0][1], double(v[2][2]) - v[0][2]};
  cross(e1, e2, out);
  const double length = norm(out);
  for (int i = 0; length > 0 && i < 3; ++i)
    out[i] /= length;
}

RayPrimitive RayPrimitive::fromMesh(const std::shared_ptr<const MeshData>& mesh, const urdf::Pose& pose, const void* owner)
{
  RayPrimitive p;
  p.kind = Shape::Kind::Mesh;
  p.frame = Frame::fromPose(pose);
  p.owner = owner;
  p.mesh = TriangleBvh::of(mesh);
  p.bound_radius = p.mesh->boundRadius();
  return p;
}

const Rgba& RayPrimitive::colourAt(int triangle) const
{
  if (mesh && triangle >= 0)
  {
    const MeshData::SubMesh& sub = mesh->mesh().subMeshOf(triangle);
    if (sub.has_colour)
      return sub.diffuse;
  }
  return colour;
}

RayPrimitive RayPrimitive::fromShape(const Shape& s, const urdf::Pose& pose, const void* owner)
{
  RayPrimitive p;
  p.kind = s.kind;
  p.frame = Frame::fromPose(pose);
  p.owner = owner;
  switch (s.kind)
  {
    case Shape::Kind::Box:
      for (int i = 0; i < 3; ++i)
        p.half[i] = s.box_size[i] / 2.0;
      p.bound_radius = norm(p.half);
      break;
    case Shape::Kind::Cylinder:
      p.radius = s.radius;
      p.half_length = s.length / 2.0;
      p.bound_radius = std::sqrt(p.radius * p.radius + p.half_length * p.half_length);
      break;
    case Shape::Kind::Sphere:
      p.radius = s.radius;
      p.bound_radius = s.radius;
      break;
    case Shape::Kind::Plane:
      p.normal[0] = s.normal.x; p.normal[1] = s.normal.y; p.normal[2] = s.normal.z;
      p.bound_radius = kInf;
      break;
    case Shape::Kind::Mesh:
      break;  // fromMesh
  }
  return p;
}

double RayPrimitive::intersect(const double origin[3], const double dir[3], int* triangle) const
{
  double o[3], d[3];
  frame.inverseApply(origin, o);
  frame.inverseRotate(dir, d);
  switch (kind)
  {
    case Shape::Kind::Box: return intersectBox(o, d, half);
    case Shape::Kind::Cylinder: return intersectCylinder(o, d, radius, half_length);
    case Shape::Kind::Sphere: return intersectSphere(o, d, radius);
    case Shape::Kind::Plane: return intersectPlane(o, d, normal);
    case Shape::Kind::Mesh:
    {
      int hit = -1;
      const double t = mesh->intersect(o, d, hit);
      if (triangle)
        *triangle = hit;
      return t;
    }
  }
  return kInf;
}

RayCaster::RayCaster(const std::vector<RayPrimitive>& primitives, const void* exclude)
{
  primitives_.reserve(primitives.size());
  for (const RayPrimitive& p : primitives)
    if (exclude == nullptr || p.owner != exclude)
      primitives_.push_back(&p);
}

double RayCaster::cast(const double origin[3], const double dir[3], double max_range) const
{
  return castHit(origin, dir, max_range).distance;
}

void RayPrimitive::normalAt(const double point[3], double out[3], int triangle) const
{
  double p[3], n[3] = {0, 0, 0};
  frame.inverseApply(point, p);
  switch (kind)
  {
    case Shape::Kind::Box:
    {
      // the face the point is closest to
      int axis = 0;
      double best = kInf;
      for (int i = 0; i < 3; ++i)
      {
        double gap = std::abs(half[i] - std::abs(p[i]));
        if (gap < best)
        {
          best = gap;
          axis = i;
        }
      }
      n[axis] = p[axis] >= 0 ? 1.0 : -1.0;
      break;
    }
    case Shape::Kind::Cylinder:
    {
      double radial = std::hypot(p[0], p[1]);
      if (std::abs(half_length - std::abs(p[2])) < std::abs(radius - radial))
        n[2] = p[2] >= 0 ? 1.0 : -1.0;
      else if (radial > 0)
      {
        n[0] = p[0] / radial;
        n[1] = p[1] / radial;
      }
      break;
    }
    case Shape::Kind::Sphere:
    {
      double r = norm(p);
      for (int i = 0; r > 0 && i < 3; ++i)
        n[i] = p[i] / r;
      break;
    }
    case Shape::Kind::Plane:
      for (int i = 0; i < 3; ++i)
        n[i] = normal[i];
      break;
    case Shape::Kind::Mesh:
      if (triangle >= 0)
        mesh->normal(triangle, n);
      break;
  }
  frame.rotate(n, out);
}

RayHit RayCaster::castHit(const double origin[3], const double dir[3], double max_range) const
{
  double best = kInf;
  const RayPrimitive* hit = nullptr;
  int hit_triangle = -1;
  for (const RayPrimitive* p : primitives_)
  {
    const double* c = p->frame.t;
    double to_centre[3] = {c[0] - origin[0], c[1] - origin[1], c[2] - origin[2]};
    if (!std::isinf(p->bound_radius))
    {
      double along = dot(to_centre, dir);
      double dist2 = dot(to_centre, to_centre) - along * along;
      if (dist2 > p->bound_radius * p->bound_radius || along + p->bound_radius < 0.0 ||
          along - p->bound_radius > std::min(best, max_range))
        continue;
    }
    int triangle = -1;
    double t = p->intersect(origin, dir, &triangle);
    if (t < best)
    {
      best = t;
      hit = p;
      hit_triangle = triangle;
    }
  }
  return best <= max_range ? RayHit{best, hit, hit_triangle} : RayHit{kInf, nullptr, -1};
}

void RayCaster::castFan(const Frame& sensor, double a0, double da, int n_azimuth, const std::vector<double>& elevations,
                        double max_range, std::vector<double>& out) const
{
  const size_t n_rows = elevations.size();
  out.assign(n_rows * n_azimuth, kInf);
  if (n_azimuth <= 0)
    return;
  // Ray directions in the world, once per scan.
  std::vector<double> dirs(3 * n_rows * n_azimuth);
  for (size_t row = 0; row < n_rows; ++row)
  {
    double ce = std::cos(elevations[row]), se = std::sin(elevations[row]);
    for (int i = 0; i < n_azimuth; ++i)
    {
      double a = a0 + i * da;
      // Gazebo's convention: positive elevation tilts the ray up (towards +z of the sensor).
      double local[3] = {ce * std::cos(a), ce * std::sin(a), se};
      sensor.rotate(local, &dirs[3 * (row * n_azimuth + i)]);
    }
  }
  const double* origin = sensor.t;
  for (const RayPrimitive* p : primitives_)
  {
    int first = 0, last = n_azimuth - 1;  // inclusive ranges of azimuth indices, possibly two
    int first2 = 1, last2 = 0;
    if (!std::isinf(p->bound_radius))
    {
      double c[3];
      sensor.inverseApply(p->frame.t, c);
      double dist = norm(c);
      if (dist - p->bound_radius > max_range)
        continue;
      double dist_xy = std::hypot(c[0], c[1]);
      if (dist_xy > p->bound_radius && da != 0.0)
      {
        double centre = std::atan2(c[1], c[0]);
        double half = std::asin(p->bound_radius / dist_xy);
        double span = (n_azimuth - 1) * std::abs(da);
        // Offsets from the fan's first ray, measured in the fan's direction of sweep.
        double sign = da > 0 ? 1.0 : -1.0;
        double lo = wrapAngle(sign * (centre - a0) - half);
        double width = 2.0 * half;
        double step = std::abs(da);
        auto index = [&](double offset) { return static_cast<int>(std::floor(offset / step)); };
        // The covered interval [lo, lo + width] (mod 2 pi) against the fan [0, span].
        if (lo <= span)
        {
          first = static_cast<int>(std::ceil(lo / step));
          last = std::min(n_azimuth - 1, index(lo + width));
        }
        else
        {
          first = 1;
          last = 0;
        }
        if (lo + width > kTwoPi)  // wraps past the fan's start
        {
          first2 = 0;
          last2 = std::min(n_azimuth - 1, index(lo + width - kTwoPi));
        }
      }
    }
    for (size_t row = 0; row < n_rows; ++row)
    {
      double* ranges = &out[row * n_azimuth];
      const double* row_dirs = &dirs[3 * row * n_azimuth];
      for (int pass = 0; pass < 2; ++pass)
      {
        int a = pass == 0 ? first : first2, b = pass == 0 ? last : last2;
        for (int i = a; i <= b; ++i)
        {
          double t = p->intersect(origin, &row_dirs[3 * i]);
          if (t < ranges[i])
            ranges[i] = t;
        }
      }
    }
  }
  for (double& r : out)
    if (r > max_range)
      r = kInf;
}

}  // namespace previous
}  // namespace bullet_plant
