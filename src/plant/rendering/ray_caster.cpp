#include "rendering/ray_caster.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <map>
#include <mutex>
#include <stdexcept>
#include <string>

#include "rendering/ray_threads.h"

namespace bullet_plant
{
namespace
{
constexpr double kInf = std::numeric_limits<double>::infinity();
// A plane is a square of this half size (m) in tiles of kPlaneTile: far beyond any sensor's range,
// and small tiles keep Embree's float hit distances within 1e-5 m of the exact plane.
constexpr double kPlaneHalfSize = 1000.0;
constexpr double kPlaneTile = 100.0;

// Outward unit normal of a sphere, cylinder, capsule or ellipsoid at a point on it (shape frame).
void curvedNormal(const RayPrimitive& p, const double q[3], double n[3])
{
  n[0] = n[1] = n[2] = 0.0;
  if (p.kind == Shape::Kind::Sphere || p.kind == Shape::Kind::Capsule || p.kind == Shape::Kind::Ellipsoid)
  {
    // From the nearest point of the capsule's axis segment; an ellipsoid's gradient (x/a^2, y/b^2, z/c^2).
    double g[3] = {q[0], q[1], q[2]};
    if (p.kind == Shape::Kind::Capsule)
      g[2] -= std::max(-p.half_length, std::min(p.half_length, q[2]));
    else if (p.kind == Shape::Kind::Ellipsoid)
      for (int i = 0; i < 3; ++i)
        g[i] = q[i] / (p.half[i] * p.half[i]);
    const double r = norm(g);
    for (int i = 0; r > 0 && i < 3; ++i)
      n[i] = g[i] / r;
    return;
  }
  const double radial = std::hypot(q[0], q[1]);
  if (std::abs(p.half_length - std::abs(q[2])) < std::abs(p.radius - radial))
    n[2] = q[2] >= 0 ? 1.0 : -1.0;
  else if (radial > 0)
  {
    n[0] = q[0] / radial;
    n[1] = q[1] / radial;
  }
}

// ------------------------------------------------------------------------------- Embree device

// The instruction sets Embree has kernels for (Debian's build: all five), narrowest first, with
// what Embree needs of the CPU for each (its isa= names and its own CPU checks).
struct IsaKernels
{
  const char* name;
  bool (*cpu_has)();
};
const IsaKernels kIsaKernels[] = {
    {"sse2", [] { return bool(__builtin_cpu_supports("sse2")); }},
    {"sse4.2", [] { return bool(__builtin_cpu_supports("sse4.2") && __builtin_cpu_supports("popcnt")); }},
    {"avx", [] { return bool(__builtin_cpu_supports("avx")); }},
    {"avx2", [] {
       return bool(__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma") && __builtin_cpu_supports("bmi") &&
                   __builtin_cpu_supports("bmi2"));
     }},
    {"avx512", [] {
       return bool(__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512cd") &&
                   __builtin_cpu_supports("avx512dq") && __builtin_cpu_supports("avx512bw") &&
                   __builtin_cpu_supports("avx512vl"));
     }},
};

std::string joined(const std::vector<std::string>& names)
{
  std::string out;
  for (const std::string& name : names)
    out += (out.empty() ? "" : ", ") + name;
  return out;
}

// One device per instruction set asked for, made on first use and kept for the process: scenes
// made under different settings each keep theirs.
RTCDevice deviceFor(const std::string& isa)
{
  static std::mutex mutex;
  static std::map<std::string, RTCDevice> devices;
  const std::lock_guard<std::mutex> lock(mutex);
  RTCDevice& d = devices[isa];
  if (!d)
  {
    const std::string config = isa.empty() ? "" : "isa=" + isa;
    d = rtcNewDevice(config.c_str());
    if (!d)
      throw std::runtime_error("Embree: cannot create a device with config '" + config + "' (error " +
                               std::to_string(rtcGetDeviceError(nullptr)) + ")");
  }
  return d;
}
}  // namespace

std::vector<std::string> embreeIsasThisCpuRuns()
{
  std::vector<std::string> out;
  __builtin_cpu_init();
  for (const IsaKernels& isa : kIsaKernels)
    if (isa.cpu_has())
      out.push_back(isa.name);
  return out;
}

EmbreeIsa embreeIsa()
{
  const std::vector<std::string> runnable = embreeIsasThisCpuRuns();
  EmbreeIsa chosen;
  chosen.name = runnable.empty() ? "sse2" : runnable.back();  // Embree's own choice: the widest
  const char* asked = std::getenv(kEmbreeIsaVariable);
  if (!asked || !*asked)
    return chosen;
  const std::string name = asked;
  std::vector<std::string> all;
  for (const IsaKernels& isa : kIsaKernels)
    all.push_back(isa.name);
  if (std::find(all.begin(), all.end(), name) == all.end())
    chosen.problem = std::string(kEmbreeIsaVariable) + "='" + name + "' is not one of " + joined(all) +
                     ": ray casting uses " + chosen.name + ", the widest this CPU runs";
  else if (std::find(runnable.begin(), runnable.end(), name) == runnable.end())
    chosen.problem = std::string(kEmbreeIsaVariable) + "='" + name + "': this CPU has no " + name + " (it runs " +
                     joined(runnable) + "): ray casting uses " + chosen.name;
  else
  {
    chosen.name = name;
    chosen.forced = true;
  }
  return chosen;
}

namespace
{
// ------------------------------------------------------------------------------ geometry builders

void transformedVertices(const Frame& frame, const float* vertices, int count, RTCGeometry g)
{
  float* out = static_cast<float*>(
      rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), size_t(count)));
  for (int v = 0; v < count; ++v)
  {
    const double p[3] = {vertices[3 * v], vertices[3 * v + 1], vertices[3 * v + 2]};
    double q[3];
    frame.apply(p, q);
    for (int i = 0; i < 3; ++i)
      out[3 * v + i] = float(q[i]);
  }
}

// Faces of `corners` vertices each (3: triangles, 4: quads), `indices` `corners` to a face.
RTCGeometry faceGeometry(RTCDevice device, int corners, const Frame& frame, const std::vector<float>& vertices,
                         const std::vector<int>& indices)
{
  RTCGeometry g = rtcNewGeometry(device, corners == 4 ? RTC_GEOMETRY_TYPE_QUAD : RTC_GEOMETRY_TYPE_TRIANGLE);
  transformedVertices(frame, vertices.data(), int(vertices.size() / 3), g);
  unsigned* out = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
      g, RTC_BUFFER_TYPE_INDEX, 0, corners == 4 ? RTC_FORMAT_UINT4 : RTC_FORMAT_UINT3, corners * sizeof(unsigned),
      indices.size() / size_t(corners)));
  std::copy(indices.begin(), indices.end(), out);
  return g;
}

void boxQuads(const double half[3], std::vector<float>& vertices, std::vector<int>& indices)
{
  for (int c = 0; c < 8; ++c)
    for (int i = 0; i < 3; ++i)
      vertices.push_back(float((c >> (2 - i)) & 1 ? half[i] : -half[i]));
  indices = {0, 1, 3, 2, 4, 6, 7, 5, 0, 4, 5, 1, 2, 3, 7, 6, 0, 2, 6, 4, 1, 5, 7, 3};
}


void curvedBounds(const RTCBoundsFunctionArguments* args)
{
  const RayPrimitive& p = *static_cast<const RayPrimitive*>(args->geometryUserPtr);
  const double r = p.kind == Shape::Kind::Sphere      ? p.radius
                   : p.kind == Shape::Kind::Capsule   ? p.radius + p.half_length
                   : p.kind == Shape::Kind::Ellipsoid ? std::max({p.half[0], p.half[1], p.half[2]})
                                                      : std::hypot(p.radius, p.half_length);
  RTCBounds* b = args->bounds_o;
  b->lower_x = float(p.frame.t[0] - r) - 1e-4f;
  b->lower_y = float(p.frame.t[1] - r) - 1e-4f;
  b->lower_z = float(p.frame.t[2] - r) - 1e-4f;
  b->upper_x = float(p.frame.t[0] + r) + 1e-4f;
  b->upper_y = float(p.frame.t[1] + r) + 1e-4f;
  b->upper_z = float(p.frame.t[2] + r) + 1e-4f;
}

// Spheres and cylinders, exactly, in double precision: the nearest hit within the ray's
// [tnear, tfar], with its normal in the shape set's frame.
void curvedIntersect(const RTCIntersectFunctionNArguments* args)
{
  const RayPrimitive& p = *static_cast<const RayPrimitive*>(args->geometryUserPtr);
  RTCRayN* ray = RTCRayHitN_RayN(args->rayhit, args->N);
  RTCHitN* hit = RTCRayHitN_HitN(args->rayhit, args->N);
  const unsigned N = args->N;
  for (unsigned i = 0; i < N; ++i)
  {
    if (args->valid[i] != -1 || !(RTCRayN_mask(ray, N, i) & p.seen_by))
      continue;
    const double origin[3] = {RTCRayN_org_x(ray, N, i), RTCRayN_org_y(ray, N, i), RTCRayN_org_z(ray, N, i)};
    double dir[3] = {RTCRayN_dir_x(ray, N, i), RTCRayN_dir_y(ray, N, i), RTCRayN_dir_z(ray, N, i)};
    const double length = norm(dir);
    if (!(length > 0))
      continue;
    for (double& x : dir)
      x /= length;
    double o[3], d[3];
    p.frame.inverseApply(origin, o);
    p.frame.inverseRotate(dir, d);
    const double along = p.kind == Shape::Kind::Sphere      ? intersectSphere(o, d, p.radius)
                         : p.kind == Shape::Kind::Capsule   ? intersectCapsule(o, d, p.radius, p.half_length)
                         : p.kind == Shape::Kind::Ellipsoid ? intersectEllipsoid(o, d, p.half)
                                                            : intersectCylinder(o, d, p.radius, p.half_length);
    const double t = along / length;  // in the ray's own units
    if (!(t >= RTCRayN_tnear(ray, N, i) && t < RTCRayN_tfar(ray, N, i)))
      continue;
    const double q[3] = {o[0] + along * d[0], o[1] + along * d[1], o[2] + along * d[2]};
    double n_shape[3], n[3];
    curvedNormal(p, q, n_shape);
    p.frame.rotate(n_shape, n);
    RTCRayN_tfar(ray, N, i) = float(t);
    RTCHitN_Ng_x(hit, N, i) = float(n[0]);
    RTCHitN_Ng_y(hit, N, i) = float(n[1]);
    RTCHitN_Ng_z(hit, N, i) = float(n[2]);
    RTCHitN_u(hit, N, i) = 0.0f;
    RTCHitN_v(hit, N, i) = 0.0f;
    RTCHitN_primID(hit, N, i) = args->primID;
    RTCHitN_geomID(hit, N, i) = args->geomID;
    RTCHitN_instID(hit, N, i, 0) = args->context->instID[0];
  }
}

void frameToColumnMajor(const Frame& f, float out[12])
{
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r)
      out[3 * c + r] = float(f.R[3 * r + c]);
  for (int r = 0; r < 3; ++r)
    out[9 + r] = float(f.t[r]);
}

}  // namespace

void planeTriangles(const double normal[3], std::vector<float>& vertices, std::vector<int>& indices)
{
  // two unit vectors across the plane
  double a[3] = {1, 0, 0};
  if (std::abs(normal[0]) > 0.9)
    a[0] = 0, a[1] = 1;
  double s[3], t[3];
  cross(normal, a, s);
  const double ls = norm(s);
  for (double& x : s)
    x /= ls;
  cross(normal, s, t);
  const int n = int(2 * kPlaneHalfSize / kPlaneTile);
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j)
    {
      const double x = -kPlaneHalfSize + i * kPlaneTile, y = -kPlaneHalfSize + j * kPlaneTile;
      for (int k = 0; k < 3; ++k)
        vertices.push_back(float(x * s[k] + y * t[k]));
    }
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
    {
      const int v = i * (n + 1) + j;
      indices.insert(indices.end(), {v, v + n + 1, v + n + 2, v, v + n + 2, v + 1});
    }
}

// ------------------------------------------------------------------------ analytic intersections

double intersectSphere(const double o[3], const double d[3], double r)
{
  double b = dot(o, d);
  double c = dot(o, o) - r * r;
  if (c <= 0.0)
    return kInf;  // starts inside
  double disc = b * b - c;
  if (disc < 0.0 || b > 0.0)
    return kInf;
  return -b - std::sqrt(disc);
}

double intersectCylinder(const double o[3], const double d[3], double r, double half_length)
{
  if (o[0] * o[0] + o[1] * o[1] < r * r && std::abs(o[2]) < half_length)
    return kInf;  // starts inside
  double best = kInf;
  // side: (ox + t dx)^2 + (oy + t dy)^2 = r^2
  double a = d[0] * d[0] + d[1] * d[1];
  if (a > 1e-18)
  {
    double b = o[0] * d[0] + o[1] * d[1];
    double c = o[0] * o[0] + o[1] * o[1] - r * r;
    double disc = b * b - a * c;
    if (disc >= 0.0)
    {
      double t = (-b - std::sqrt(disc)) / a;
      if (t >= 0.0 && std::abs(o[2] + t * d[2]) <= half_length)
        best = t;
    }
  }
  // caps
  if (d[2] != 0.0)
  {
    for (double z : {-half_length, half_length})
    {
      double t = (z - o[2]) / d[2];
      if (t >= 0.0 && t < best)
      {
        double x = o[0] + t * d[0], y = o[1] + t * d[1];
        if (x * x + y * y <= r * r)
          best = t;
      }
    }
  }
  return best;
}

double intersectCapsule(const double o[3], const double d[3], double r, double half_length)
{
  // Starts inside: within r of the axis segment.
  const double along = std::max(-half_length, std::min(half_length, o[2]));
  if (o[0] * o[0] + o[1] * o[1] + (o[2] - along) * (o[2] - along) < r * r)
    return kInf;
  // Outside the union of a cylinder and two spheres, the ray enters it where it first enters one.
  const double top[3] = {o[0], o[1], o[2] - half_length}, bottom[3] = {o[0], o[1], o[2] + half_length};
  return std::min({intersectCylinder(o, d, r, half_length), intersectSphere(top, d, r), intersectSphere(bottom, d, r)});
}

double intersectEllipsoid(const double o[3], const double d[3], const double radii[3])
{
  // In the frame scaled by 1 / radii the ellipsoid is the unit sphere: |o' + t d'|^2 = 1, t the
  // distance along the unit ray.
  double os[3], ds[3];
  for (int i = 0; i < 3; ++i)
  {
    os[i] = o[i] / radii[i];
    ds[i] = d[i] / radii[i];
  }
  const double a = dot(ds, ds), b = dot(os, ds), c = dot(os, os) - 1.0;
  if (c <= 0.0)
    return kInf;  // starts inside
  const double disc = b * b - a * c;
  if (disc < 0.0 || b > 0.0 || !(a > 0.0))
    return kInf;
  return (-b - std::sqrt(disc)) / a;
}

// ------------------------------------------------------------------------------------ primitives

RayPrimitive RayPrimitive::fromMesh(const std::shared_ptr<const MeshData>& mesh, const urdf::Pose& pose, const void* owner)
{
  RayPrimitive p;
  p.kind = Shape::Kind::Mesh;
  p.frame = Frame::fromPose(pose);
  p.owner = owner;
  p.mesh = mesh;
  return p;
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
      break;
    case Shape::Kind::Cylinder:
      p.radius = s.radius;
      p.half_length = s.length / 2.0;
      break;
    case Shape::Kind::Sphere:
      p.radius = s.radius;
      break;
    case Shape::Kind::Capsule:
      p.radius = s.radius;
      p.half_length = s.length / 2.0;
      break;
    case Shape::Kind::Ellipsoid:
      for (int i = 0; i < 3; ++i)
        p.half[i] = s.radii[size_t(i)];
      break;
    case Shape::Kind::Plane:
      p.normal[0] = s.normal.x; p.normal[1] = s.normal.y; p.normal[2] = s.normal.z;
      {
        const double n = norm(p.normal);
        for (double& x : p.normal)
          x = n > 0 ? x / n : 0.0;
      }
      break;
    case Shape::Kind::Mesh:
      break;  // fromMesh
  }
  return p;
}

Material RayPrimitive::surfaceMaterial(int triangle, bool& textured) const
{
  textured = false;
  if (!mesh || triangle < 0)
  {
    const Material m = material.resolve(Material::gazeboWhite(), textured);
    textured = false;  // a primitive has no texture
    return m;
  }
  const MeshData::SubMesh& sub = mesh->subMeshOf(triangle);
  bool keep = false;
  const Material m = material.resolve(sub.has_material ? sub.material : Material::gazeboWhite(), keep);
  textured = keep && sub.image && !mesh->uvs.empty();
  return m;
}

Rgba RayPrimitive::surfaceColour(int triangle, float u, float v) const
{
  bool textured = false;
  const Material m = surfaceMaterial(triangle, textured);
  if (textured)
  {
    const MeshData::SubMesh& sub = mesh->subMeshOf(triangle);
    const int* corner = &mesh->indices[3 * triangle];
    const float w0 = 1.0f - u - v;
    const float s = w0 * mesh->uvs[2 * corner[0]] + u * mesh->uvs[2 * corner[1]] + v * mesh->uvs[2 * corner[2]];
    const float t =
        w0 * mesh->uvs[2 * corner[0] + 1] + u * mesh->uvs[2 * corner[1] + 1] + v * mesh->uvs[2 * corner[2] + 1];
    return sub.image->at(s, t);
  }
  return m.diffuse;
}

// ------------------------------------------------------------------------------------ shape sets

// Shapes that move together, in their common frame, as one Embree scene.
struct RayScene::ShapeSet
{
  RTCScene scene = nullptr;
  std::vector<RayPrimitive> shapes;      // never resized after construction: user geometry points into it
  std::vector<int> shape_of_geometry;    // Embree geometry id -> index in shapes

  // robust: Embree's robust traversal (planes: see ray_caster.h)
  ShapeSet(RTCDevice device, std::vector<RayPrimitive> primitives, bool robust = false) : shapes(std::move(primitives))
  {
    scene = rtcNewScene(device);
    if (robust)
      rtcSetSceneFlags(scene, RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(scene, RTC_BUILD_QUALITY_HIGH);
    for (size_t k = 0; k < shapes.size(); ++k)
    {
      const RayPrimitive& p = shapes[k];
      RTCGeometry g = nullptr;
      std::vector<float> vertices;
      std::vector<int> indices;
      switch (p.kind)
      {
        case Shape::Kind::Box:
          boxQuads(p.half, vertices, indices);
          g = faceGeometry(device, 4, p.frame, vertices, indices);
          break;
        case Shape::Kind::Plane:
          planeTriangles(p.normal, vertices, indices);
          g = faceGeometry(device, 3, p.frame, vertices, indices);
          break;
        case Shape::Kind::Mesh:
          g = faceGeometry(device, 3, p.frame, p.mesh->vertices, p.mesh->indices);
          break;
        case Shape::Kind::Sphere:
        case Shape::Kind::Cylinder:
        case Shape::Kind::Capsule:
        case Shape::Kind::Ellipsoid:
          g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_USER);
          rtcSetGeometryUserPrimitiveCount(g, 1);
          rtcSetGeometryUserData(g, const_cast<RayPrimitive*>(&p));
          rtcSetGeometryBoundsFunction(g, curvedBounds, nullptr);
          rtcSetGeometryIntersectFunction(g, curvedIntersect);
          break;
      }
      rtcSetGeometryMask(g, p.seen_by);
      rtcCommitGeometry(g);
      const unsigned id = rtcAttachGeometry(scene, g);
      rtcReleaseGeometry(g);
      if (shape_of_geometry.size() <= id)
        shape_of_geometry.resize(id + 1, -1);
      shape_of_geometry[id] = int(k);
    }
    rtcCommitScene(scene);
  }
  ~ShapeSet() { rtcReleaseScene(scene); }
};

namespace
{
bool sameDoubles(const double* a, const double* b, size_t n) { return std::equal(a, a + n, b); }

std::mutex static_sets_mutex;  // guards RayScene::staticSet's sets and count
size_t static_sets_built = 0;

bool sameShape(const RayPrimitive& a, const RayPrimitive& b)
{
  return a.kind == b.kind && sameDoubles(a.half, b.half, 3) && a.radius == b.radius &&
         a.half_length == b.half_length && sameDoubles(a.normal, b.normal, 3) && sameDoubles(a.frame.R, b.frame.R, 9) &&
         sameDoubles(a.frame.t, b.frame.t, 3) && a.owner == b.owner && a.seen_by == b.seen_by && a.mesh == b.mesh &&
         a.material == b.material;
}

}  // namespace

size_t RayScene::staticSetsBuilt()
{
  const std::lock_guard<std::mutex> lock(static_sets_mutex);
  return static_sets_built;
}

std::shared_ptr<RayScene::ShapeSet> RayScene::staticSet(RTCDevice device, const std::vector<RayPrimitive>& shapes,
                                                        bool robust)
{
  struct Built
  {
    RTCDevice device = nullptr;
    bool robust = false;
    std::shared_ptr<ShapeSet> set;
  };
  // Least recently asked for first. Sets no scene holds stay, the newest kUnheldStaticSets of them:
  // an environment's reset makes its new world's scene after the old world is gone.
  static std::vector<Built> built;
  const std::lock_guard<std::mutex> lock(static_sets_mutex);
  auto same = std::find_if(built.begin(), built.end(), [&](const Built& b) {
    return b.device == device && b.robust == robust && b.set->shapes.size() == shapes.size() &&
           std::equal(shapes.begin(), shapes.end(), b.set->shapes.begin(), sameShape);
  });
  Built wanted;
  if (same != built.end())
  {
    wanted = *same;
    built.erase(same);
  }
  else
  {
    wanted = Built{device, robust, std::make_shared<ShapeSet>(device, shapes, robust)};
    ++static_sets_built;
  }
  built.push_back(wanted);
  size_t unheld = 0;
  for (auto b = built.rbegin(); b != built.rend(); ++b)
    if (b->set.use_count() == 1 && ++unheld > kUnheldStaticSets)
      b->set.reset();
  built.erase(std::remove_if(built.begin(), built.end(), [](const Built& b) { return !b.set; }), built.end());
  return wanted.set;
}

// ------------------------------------------------------------------------------------- RayScene

RayScene::RayScene(const std::vector<RayPrimitive>& world_shapes)
  : isa_(embreeIsa()), device_(deviceFor(isa_.forced ? isa_.name : ""))
{
  top_ = rtcNewScene(device_);
  rtcSetSceneFlags(top_, RTC_SCENE_FLAG_DYNAMIC);
  // Rebuilt at every scan that follows a step: Embree's binned SAH builder (MEDIUM) takes 30 % fewer
  // instructions over a few dozen instances than its Morton one (LOW), rays as fast (4 cars on
  // peanut, callgrind).
  rtcSetSceneBuildQuality(top_, RTC_BUILD_QUALITY_MEDIUM);
  statics_top_ = rtcNewScene(device_);
  std::vector<RayPrimitive> planes, others;
  for (const RayPrimitive& p : world_shapes)
    (p.kind == Shape::Kind::Plane ? planes : others).push_back(p);
  instances_.emplace_back();
  instances_[0].set = staticSet(device_, others, false);
  attach(instances_[0]);
  instances_.emplace_back();
  instances_[1].set = staticSet(device_, planes, true);
  attach(instances_[1]);
  // The same two instances, in the same order (so the same geometry ids), in a level of their own
  for (const Instance& instance : instances_)
  {
    const unsigned id = attachInstance(statics_top_, instance);
    if (id != instance.geometry_id)
      throw std::logic_error("RayScene: the static instances' ids differ between the two top levels");
  }
  rtcCommitScene(statics_top_);
  rtcCommitScene(top_);
  cast_scene_ = top_;
}

RayScene::~RayScene()
{
  instances_.clear();
  rtcReleaseScene(top_);
  rtcReleaseScene(statics_top_);
}

unsigned RayScene::attachInstance(RTCScene level, const Instance& instance) const
{
  RTCGeometry g = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_INSTANCE);
  rtcSetGeometryInstancedScene(g, instance.set->scene);
  rtcSetGeometryTimeStepCount(g, 1);
  float m[12];
  frameToColumnMajor(instance.pose, m);
  rtcSetGeometryTransform(g, 0, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, m);
  rtcSetGeometryMask(g, instance.mask);
  rtcCommitGeometry(g);
  const unsigned id = rtcAttachGeometry(level, g);
  rtcReleaseGeometry(g);
  return id;
}

void RayScene::attach(Instance& instance)
{
  instance.geometry_id = attachInstance(top_, instance);
  if (instance_of_geometry_.size() <= instance.geometry_id)
    instance_of_geometry_.resize(instance.geometry_id + 1, -1);
  instance_of_geometry_[instance.geometry_id] = int(&instance - instances_.data());
}

int RayScene::addBody(const void* owner, std::vector<RayPrimitive> shapes)
{
  Instance instance;
  instance.set = std::make_shared<ShapeSet>(device_, std::move(shapes));
  instance.owner = owner;
  const unsigned bit = robotBit(owner);
  instance.mask = bit ? bit : freeRobotBit();
  // A removed body's slot is taken again, so a world that spawns and deletes models all day keeps
  // its size (each slot left behind was some 130 bytes a body).
  auto slot = std::find_if(instances_.begin(), instances_.end(), [](const Instance& i) { return !i.set; });
  if (slot == instances_.end())
    slot = instances_.insert(slot, std::move(instance));
  else
    *slot = std::move(instance);
  attach(*slot);
  if (owner == masked_out_)
    masked_out_ = nullptr;  // the next commit masks this body out too
  changed_ = true;
  return int(slot - instances_.begin());
}

void RayScene::removeOwner(const void* owner)
{
  for (Instance& instance : instances_)
    if (instance.set && instance.owner == owner && owner != nullptr)
    {
      rtcDetachGeometry(top_, instance.geometry_id);
      instance_of_geometry_[instance.geometry_id] = -1;
      instance.set.reset();
      instance.owner = nullptr;
    }
  if (owner == masked_out_)
    masked_out_ = nullptr;
  changed_ = true;
}

namespace
{
constexpr unsigned kFirstRobotBit = 1u << 2;  // bits 0 and 1 are SeenBy's
constexpr unsigned kSharedRobotBit = 1u << 31;
constexpr unsigned kRobotBits = ~unsigned(kSeenByAll);
static_assert(kFirstRobotBit << (RayScene::kRobotMaskBits - 1) == kSharedRobotBit >> 1,
              "the robots' own bits lie between SeenBy's and the shared one");
}  // namespace

unsigned RayScene::robotBit(const void* owner) const
{
  for (auto i = instances_.begin() + 2; i != instances_.end(); ++i)
    if (i->set && i->owner == owner)
      return i->mask;
  return 0;
}

unsigned RayScene::freeRobotBit() const
{
  unsigned bit = kFirstRobotBit;
  while (bit != kSharedRobotBit && std::any_of(instances_.begin() + 2, instances_.end(),
                                               [&](const Instance& i) { return i.set && i.mask == bit; }))
    bit <<= 1;
  return bit;
}

bool RayScene::hasOwner(const void* owner) const
{
  return std::any_of(instances_.begin(), instances_.end(),
                     [&](const Instance& i) { return i.set && i.owner == owner; });
}

void RayScene::setPose(int body, const Frame& world_from_body)
{
  Instance& instance = instances_.at(size_t(body));
  if (std::equal(world_from_body.R, world_from_body.R + 9, instance.pose.R) &&
      std::equal(world_from_body.t, world_from_body.t + 3, instance.pose.t))
    return;
  instance.pose = world_from_body;
  RTCGeometry g = rtcGetGeometry(top_, instance.geometry_id);
  float m[12];
  frameToColumnMajor(world_from_body, m);
  rtcSetGeometryTransform(g, 0, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, m);
  rtcCommitGeometry(g);
  changed_ = true;
}

void RayScene::commit(const void* hidden)
{
  // The hidden robot's own bit is left out of the rays' masks; a robot of the shared bit has its
  // instances masked out instead (and the one masked out before shown again), which needs a commit.
  const unsigned hidden_bit = hidden ? robotBit(hidden) : 0u;
  const void* masked_out = hidden_bit == kSharedRobotBit ? hidden : nullptr;
  if (masked_out != masked_out_)
  {
    for (Instance& instance : instances_)
    {
      if (!instance.set || instance.owner == nullptr ||
          (instance.owner != masked_out && instance.owner != masked_out_))
        continue;
      RTCGeometry g = rtcGetGeometry(top_, instance.geometry_id);
      rtcSetGeometryMask(g, instance.owner == masked_out ? 0u : instance.mask);
      rtcCommitGeometry(g);
    }
    masked_out_ = masked_out;
    changed_ = true;
  }
  rays_see_robots_ = kRobotBits & ~(hidden_bit == kSharedRobotBit ? 0u : hidden_bit);
  // Where every robot body is hidden (a robot's lidar in a world of no other robot: a racing
  // environment's car), the rays see the static shapes alone, whose level never changes: the top
  // level that moves with the robots is left uncommitted (it cost more than the rays, 14 us a scan
  // on the peanut track, most of it Embree's build starting up) until a ray could see a robot.
  const bool robots_seen = std::any_of(instances_.begin() + 2, instances_.end(), [&](const Instance& i) {
    return i.set && i.owner != hidden;
  });
  if (!robots_seen)
  {
    cast_scene_ = statics_top_;
    return;
  }
  if (changed_)
    rtcCommitScene(top_);
  changed_ = false;
  cast_scene_ = top_;
}

// ------------------------------------------------------------------------------------- casting

void RayScene::resolve(const RTCRayHit& rh, RayHit& out) const
{
  const Instance& instance = instances_[size_t(instance_of_geometry_[rh.hit.instID[0]])];
  const ShapeSet& set = *instance.set;
  const RayPrimitive& p = set.shapes[size_t(set.shape_of_geometry[rh.hit.geomID])];
  out.distance = rh.ray.tfar;
  out.primitive = &p;
  out.triangle = p.kind == Shape::Kind::Mesh ? int(rh.hit.primID) : -1;
  out.u = rh.hit.u;
  out.v = rh.hit.v;
  const double ng[3] = {rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z};
  instance.pose.rotate(ng, out.normal);
  const double length = norm(out.normal);
  const double facing = out.normal[0] * rh.ray.dir_x + out.normal[1] * rh.ray.dir_y + out.normal[2] * rh.ray.dir_z;
  const double scale = length > 0 ? (facing > 0 ? -1.0 : 1.0) / length : 0.0;
  for (double& n : out.normal)
    n *= scale;
}

namespace
{
// Embree checks this (RayK::valid) with assertions, which Debian's build keeps: a ray outside it
// aborts the process (builds without them return garbage). Such a ray (a NaN or 1e308 pose or range from
// a user) is simply not cast: it hits nothing. Without branches, so that a scan's loop vectorizes.
constexpr float kLargest = 1.844e18f;  // Embree's FLT_LARGE

bool embreeAcceptsDirection(const float dir[3])
{
  return (std::fabs(dir[0]) <= kLargest) & (std::fabs(dir[1]) <= kLargest) & (std::fabs(dir[2]) <= kLargest);
}

bool embreeAcceptsOriginAndRange(const float origin[3], float near, float far)
{
  return embreeAcceptsDirection(origin) & (near >= 0) & !std::isnan(far);
}

bool embreeAcceptsRay(const float origin[3], const float dir[3], float near, float far)
{
  return embreeAcceptsOriginAndRange(origin, near, far) & embreeAcceptsDirection(dir);
}
}  // namespace

RayHit RayScene::castHit(const double origin[3], const double dir[3], double near, double far, unsigned seen_by) const
{
  RayHit out;
  out.distance = kInf;
  const float org_f[3] = {float(origin[0]), float(origin[1]), float(origin[2])};
  const float dir_f[3] = {float(dir[0]), float(dir[1]), float(dir[2])};
  if (!embreeAcceptsRay(org_f, dir_f, float(near), float(far)))
    return out;
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rh;
  rh.ray.org_x = org_f[0];
  rh.ray.org_y = org_f[1];
  rh.ray.org_z = org_f[2];
  rh.ray.dir_x = dir_f[0];
  rh.ray.dir_y = dir_f[1];
  rh.ray.dir_z = dir_f[2];
  rh.ray.tnear = float(near);
  rh.ray.tfar = float(far);
  rh.ray.mask = seen_by | rays_see_robots_;
  rh.ray.time = 0;
  rh.ray.flags = 0;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(cast_scene_, &context, &rh);
  if (rh.hit.geomID != RTC_INVALID_GEOMETRY_ID)
    resolve(rh, out);
  return out;
}

double RayScene::cast(const double origin[3], const double dir[3], double far, unsigned seen_by) const
{
  return castHit(origin, dir, 0.0, far, seen_by).distance;
}

namespace
{
constexpr int kPacket = 16;

// A packet of rays, Embree's structure of arrays. Which lanes Embree casts depends on the width of
// its kernels: the 16-wide ones (AVX-512) follow `valid`; narrower ones (AVX2's 8, SSE's 4) get the
// packet through Embree's stream fallback, which ignores `valid` and casts every lane whose
// tnear <= tfar (Embree 3.13: rtcIntersect16 without a 16-wide intersector calls
// RayStreamFilter::filterSOA), asserting that each holds a ray RayK::valid accepts. So a lane not to
// be cast is both invalid and empty (tnear > tfar), whatever its other fields hold.
struct alignas(64) Packet
{
  RTCRayHit16 rh;
  int valid[kPacket];

  // The 16 rays from `first` on: `cast` -1 for a ray Embree accepts (embreeAcceptsRay), 0 for one
  // not cast (or beyond the scan's last), directions by axis.
  void fill(int first, const int* cast, const float* dx, const float* dy, const float* dz, const float origin[3],
            float near, float far, unsigned mask)
  {
    // One field at a time: each loop is a few vector stores.
    constexpr float kInfF = std::numeric_limits<float>::infinity();
    std::copy_n(cast + first, kPacket, valid);
    std::fill_n(rh.ray.org_x, kPacket, origin[0]);
    std::fill_n(rh.ray.org_y, kPacket, origin[1]);
    std::fill_n(rh.ray.org_z, kPacket, origin[2]);
    std::copy_n(dx + first, kPacket, rh.ray.dir_x);
    std::copy_n(dy + first, kPacket, rh.ray.dir_y);
    std::copy_n(dz + first, kPacket, rh.ray.dir_z);
    for (int lane = 0; lane < kPacket; ++lane)
      rh.ray.tnear[lane] = valid[lane] ? near : kInfF;
    for (int lane = 0; lane < kPacket; ++lane)
      rh.ray.tfar[lane] = valid[lane] ? far : -kInfF;
    std::fill_n(rh.ray.mask, kPacket, mask);
    std::fill_n(rh.ray.time, kPacket, 0.0f);
    std::fill_n(rh.ray.flags, kPacket, 0u);
    std::fill_n(rh.hit.geomID, kPacket, RTC_INVALID_GEOMETRY_ID);
    std::fill_n(rh.hit.instID[0], kPacket, RTC_INVALID_GEOMETRY_ID);
  }
  bool hit(int lane) const { return valid[lane] == -1 && rh.hit.geomID[lane] != RTC_INVALID_GEOMETRY_ID; }
};
}  // namespace

std::vector<double> fanDirections(double a0, double da, int n_azimuth, const std::vector<double>& elevations)
{
  std::vector<double> out;
  out.reserve(3 * elevations.size() * size_t(std::max(0, n_azimuth)));
  for (double e : elevations)
    for (int i = 0; i < n_azimuth; ++i)
    {
      const double a = a0 + i * da;
      out.insert(out.end(), {std::cos(e) * std::cos(a), std::cos(e) * std::sin(a), std::sin(e)});
    }
  return out;
}

void RayScene::castRays(const Frame& sensor, const std::vector<double>& directions, double near, double far,
                        unsigned seen_by, std::vector<double>& out) const
{
  const int n = int(directions.size() / 3);
  out.resize(size_t(n));  // every ray's distance is written below
  const float origin[3] = {float(sensor.t[0]), float(sensor.t[1]), float(sensor.t[2])};
  const float near_f = float(near), far_f = float(far);
  // The fan turned into the world once a scan, in float and by axis as the packets take it, each ray
  // checked there: filling a packet is then copies a vectorizing compiler turns into a few stores.
  const int packets = (n + kPacket - 1) / kPacket;
  const size_t padded = size_t(packets) * kPacket;
  // Kept by the calling thread from scan to scan (no allocation); the tasks read them through the
  // pointers below, whichever thread runs them.
  thread_local std::vector<float> world_dirs;
  thread_local std::vector<int> cast_lane;
  world_dirs.assign(3 * padded, 0.0f);
  cast_lane.assign(padded, 0);
  float* dir_x = world_dirs.data();
  float* dir_y = dir_x + padded;
  float* dir_z = dir_y + padded;
  const bool origin_ok = embreeAcceptsOriginAndRange(origin, near_f, far_f);
  int* cast = cast_lane.data();
  for (int i = 0; i < n; ++i)
  {
    double dir[3];
    sensor.rotate(&directions[3 * size_t(i)], dir);
    const float dir_f[3] = {float(dir[0]), float(dir[1]), float(dir[2])};
    dir_x[i] = dir_f[0];
    dir_y[i] = dir_f[1];
    dir_z[i] = dir_f[2];
    cast[i] = -int(origin_ok & embreeAcceptsDirection(dir_f));
  }
  const unsigned mask = seen_by | rays_see_robots_;
  constexpr int kPacketsPerTask = 128;  // 2048 rays: a planar scan stays on the calling thread, waking no worker
  parallelTasks((packets + kPacketsPerTask - 1) / kPacketsPerTask, [&](int task) {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    Packet packet;
    for (int k = task * kPacketsPerTask; k < std::min(packets, (task + 1) * kPacketsPerTask); ++k)
    {
      packet.fill(k * kPacket, cast, dir_x, dir_y, dir_z, origin, near_f, far_f, mask);
      rtcIntersect16(packet.valid, cast_scene_, &context, &packet.rh);
      double* distances = out.data() + size_t(k) * kPacket;
      for (int lane = 0; lane < std::min(kPacket, n - k * kPacket); ++lane)
        distances[lane] = packet.hit(lane) ? double(packet.rh.ray.tfar[lane]) : kInf;
    }
  });
}

}  // namespace bullet_plant
