// gl_context.cpp, gl_renderer.cpp, gl_scene.cpp and pinhole.cpp (OpenGL ES 3 through EGL, no
// window): a context on Mesa's llvmpipe when the CPU is asked for, TIANRACER_GL_DEVICE read as
// documented, and frames that look as the same boxes (or spheres, cylinders and a plane, or a
// textured mesh) seen by rays through each pixel centre (castFrame below: RayScene::castHit, exact
// for boxes, planes, meshes, spheres and cylinders, RayPrimitive::surfaceMaterial, and pinhole.h's
// lighting worked out again here, in double precision, per ray) under the same lights (a sun, and
// point and spot lamps with specular surfaces): colours within 3/255 and depths within 1 mm away
// from silhouette edges; bit for bit the same on every run; the camera's noise as pinhole.h says.
// GL_DUMP=/tmp/x writes each compared pair as /tmp/x_gl.png and /tmp/x_rays.png, to look at.
#include <gtest/gtest.h>

#include <stb/stb_image_write.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <cstring>
#include <limits>
#include <fstream>
#include <memory>
#include <random>
#include <string>

#include "mesh_fixtures.h"
#include "rendering/gl_context.h"
#include "rendering/gl_renderer.h"
#include "rendering/gl_scene.h"
#include "rendering/ray_caster.h"

using namespace bullet_plant;

namespace
{
std::unique_ptr<GlContext> llvmpipe()
{
  std::string why_not;
  std::unique_ptr<GlContext> gl = GlContext::create(GlDevice::Cpu, why_not);
  EXPECT_TRUE(gl) << why_not;
  return gl;
}

RayPrimitive box(double sx, double sy, double sz, const urdf::Pose& pose, Rgba colour)
{
  Shape s;
  s.kind = Shape::Kind::Box;
  s.box_size = {{sx, sy, sz}};
  RayPrimitive p = RayPrimitive::fromShape(s, pose, nullptr);
  p.material = VisualMaterial::colour(colour);
  return p;
}

// The lights the frames are compared under: the sun from (0.5, -0.1, 0.9), 0.65 of it over an
// ambient 0.35 (every surface one colour as its ambient and diffuse: colour x (0.35 + 0.65 n . l)),
// its shadows drawn.
Lighting sunLight()
{
  const double towards[3] = {0.5, -0.1, 0.9};
  return Lighting::sunOnly(towards, 0.65f, 0.35f, true);
}

// A floor, three coloured boxes (one turned) and a wall, seen from a camera looking down at them.
std::vector<RayPrimitive> scene()
{
  return {box(10, 10, 0.1, poseFromXyzRpy(0, 0, -0.05, 0, 0, 0), Rgba{0.6f, 0.6f, 0.6f, 1}),
          box(0.5, 0.5, 0.5, poseFromXyzRpy(1.0, 0.4, 0.25, 0, 0, 0.3), Rgba{0.9f, 0.2f, 0.1f, 1}),
          box(0.3, 1.0, 0.8, poseFromXyzRpy(2.0, -0.6, 0.4, 0, 0, -0.2), Rgba{0.1f, 0.7f, 0.2f, 1}),
          box(0.2, 0.2, 1.5, poseFromXyzRpy(3.0, 0.8, 0.75, 0.1, 0.2, 0.0), Rgba{0.2f, 0.3f, 0.9f, 1}),
          box(0.1, 8.0, 2.0, poseFromXyzRpy(5.0, 0.0, 1.0, 0, 0, 0), Rgba{0.8f, 0.8f, 0.5f, 1})};
}

RayPrimitive curved(Shape::Kind kind, double radius, double length, const urdf::Pose& pose, Rgba colour)
{
  Shape s;
  s.kind = kind;
  s.radius = radius;
  s.length = length;
  RayPrimitive p = RayPrimitive::fromShape(s, pose, nullptr);
  p.material = VisualMaterial::colour(colour);
  return p;
}

// A ground plane, spheres and cylinders (upright, lying, tilted) of several sizes.
std::vector<RayPrimitive> curvedScene()
{
  Shape ground;
  ground.kind = Shape::Kind::Plane;
  RayPrimitive plane = RayPrimitive::fromShape(ground, urdf::Pose(), nullptr);
  plane.material = VisualMaterial::colour(Rgba{0.5f, 0.55f, 0.5f, 1});
  return {plane,
          curved(Shape::Kind::Sphere, 0.4, 0, poseFromXyzRpy(1.5, 0.5, 0.4, 0, 0, 0), Rgba{0.9f, 0.3f, 0.2f, 1}),
          curved(Shape::Kind::Sphere, 0.05, 0, poseFromXyzRpy(0.6, -0.2, 0.3, 0, 0, 0), Rgba{0.9f, 0.9f, 0.2f, 1}),
          curved(Shape::Kind::Cylinder, 0.3, 1.2, poseFromXyzRpy(3.0, -0.8, 0.6, 0, 0, 0), Rgba{0.2f, 0.6f, 0.9f, 1}),
          curved(Shape::Kind::Cylinder, 0.1, 0.6, poseFromXyzRpy(1.0, -0.6, 0.1, 1.5707963, 0, 0.4), Rgba{0.3f, 0.3f, 0.3f, 1}),
          curved(Shape::Kind::Cylinder, 1.5, 0.4, poseFromXyzRpy(6.0, 1.0, 1.0, 0.3, 0.5, 0), Rgba{0.7f, 0.4f, 0.8f, 1})};
}

PinholeCamera pinhole()
{
  PinholeCamera rays;
  rays.width = 160;
  rays.height = 120;
  rays.fx = rays.fy = 120.0;
  rays.cx = (rays.width - 1) / 2.0;
  rays.cy = (rays.height - 1) / 2.0;
  rays.near = 0.05;
  rays.far = 30.0;
  return rays;
}

const Frame kCamera = Frame::fromPose(poseFromXyzRpy(-1.5, 0.2, 1.2, 0, 0.35, 0.05));

// The texture of a ray's hit on a textured mesh, bilinear between the four texels nearest its
// texture coordinates (repeating): what the GL's trilinear filter gives where the texture is
// magnified (mipmap level 0). False where the hit shows no texture.
bool bilinearTexel(const RayHit& hit, Rgba& out)
{
  const RayPrimitive& p = *hit.primitive;
  if (!p.mesh || hit.triangle < 0 || p.mesh->uvs.empty() || !p.mesh->subMeshOf(hit.triangle).image)
    return false;
  const Texture& image = *p.mesh->subMeshOf(hit.triangle).image;
  const int* corner = &p.mesh->indices[3 * size_t(hit.triangle)];
  const float w0 = 1.0f - hit.u - hit.v;
  const std::vector<float>& uv = p.mesh->uvs;
  const double s = w0 * uv[2 * corner[0]] + hit.u * uv[2 * corner[1]] + hit.v * uv[2 * corner[2]];
  const double t = w0 * uv[2 * corner[0] + 1] + hit.u * uv[2 * corner[1] + 1] + hit.v * uv[2 * corner[2] + 1];
  // texel centres at (i + 0.5) / size; rows from the top, t up from the bottom
  const double x = s * image.width - 0.5, y = (1.0 - t) * image.height - 0.5;
  const double x0 = std::floor(x), y0 = std::floor(y), fx = x - x0, fy = y - y0;
  auto texel = [&](double column, double row, int channel) {
    const int c = ((int(column) % image.width) + image.width) % image.width;
    const int r = ((int(row) % image.height) + image.height) % image.height;
    return image.rgb[3 * (size_t(r) * image.width + c) + size_t(channel)] / 255.0;
  };
  float rgb[3];
  for (int k = 0; k < 3; ++k)
    rgb[k] = float((1 - fy) * ((1 - fx) * texel(x0, y0, k) + fx * texel(x0 + 1, y0, k)) +
                   fy * ((1 - fx) * texel(x0, y0 + 1, k) + fx * texel(x0 + 1, y0 + 1, k)));
  out = Rgba{rgb[0], rgb[1], rgb[2], 1.0f};
  return true;
}

struct RayFrame : PinholeImage
{
  std::vector<uint8_t> light;
};

// One light's diffuse and specular share at a point p with unit normal n, seen from `eye`
// (pinhole.h: OGRE's per-pixel lighting), in double precision.
void addLight(const Lighting::Light& light, double shininess, const double p[3], const double n[3],
              const double to_eye[3], double diffuse[3], double specular[3])
{
  double l[3], share = 1.0;
  if (light.kind == Lighting::Light::Directional)
    for (int i = 0; i < 3; ++i)
      l[i] = -light.direction[i];
  else
  {
    double d = 0;
    for (int i = 0; i < 3; ++i)
    {
      l[i] = light.position[i] - p[i];
      d += l[i] * l[i];
    }
    d = std::sqrt(d);
    for (double& x : l)
      x /= d;
    const float* a = light.attenuation;
    share = d <= a[0] ? 1.0 / (a[1] + a[2] * d + a[3] * d * d) : 0.0;
    if (light.kind == Lighting::Light::Spot)
    {
      const double rho = -(l[0] * light.direction[0] + l[1] * light.direction[1] + l[2] * light.direction[2]);
      const double inner = light.spot[0], outer = light.spot[1];
      double spot = rho < outer ? 0.0 : inner > outer ? std::min(1.0, std::max(0.0, (rho - outer) / (inner - outer))) : 1.0;
      share *= light.spot[2] > 0 ? std::pow(spot, double(light.spot[2])) : (rho < outer ? 0.0 : 1.0);
    }
  }
  const double n_l = n[0] * l[0] + n[1] * l[1] + n[2] * l[2];
  if (n_l <= 0)
    return;
  double h[3], length = 0;
  for (int i = 0; i < 3; ++i)
  {
    h[i] = l[i] + to_eye[i];
    length += h[i] * h[i];
  }
  length = std::sqrt(length);
  const double n_h = std::max(0.0, (n[0] * h[0] + n[1] * h[1] + n[2] * h[2]) / length);
  for (int i = 0; i < 3; ++i)
  {
    diffuse[i] += light.diffuse[i] * n_l * share;
    if (shininess > 0)
      specular[i] += light.specular[i] * std::pow(n_h, shininess) * share;
  }
}

// A ray-cast frame, and whether each pixel's surface sees the sun (1) or lies in its shadow (0).
// What the camera at `pose` sees by a ray through each pixel centre, one castHit each: the colour
// of the face the ray hits under `lighting` (pinhole.h), in the sun's shadow where a second ray from
// the surface towards the sun meets a visual (with lighting.shadows), rounded half up, and the depth
// along the optical axis (+inf: nothing within the clip range). No noise.
RayFrame castFrame(const RayScene& scene, const Frame& pose, const PinholeCamera& camera, const Lighting& lighting)
{
  RayFrame out;
  out.light.assign(size_t(camera.width) * camera.height, 1);
  out.rgb8.resize(size_t(camera.width) * camera.height * 3);
  out.depth.resize(size_t(camera.width) * camera.height);
  const double origin[3] = {pose.t[0], pose.t[1], pose.t[2]};
  for (int v = 0; v < camera.height; ++v)
    for (int u = 0; u < camera.width; ++u)
    {
      const double xo = (u - camera.cx) / camera.fx, yo = (v - camera.cy) / camera.fy;
      double dir[3];
      for (int r = 0; r < 3; ++r)  // forward - xo * left - yo * up, in the world
        dir[r] = pose.R[3 * r] - xo * pose.R[3 * r + 1] - yo * pose.R[3 * r + 2];
      const double length = std::sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
      for (double& d : dir)
        d /= length;
      // the clip distances are along the optical axis, the ray's along itself
      const RayHit hit = scene.castHit(origin, dir, camera.near * length, camera.far * length, kSeenByCameras);
      const size_t pixel = size_t(v) * camera.width + u;
      double rgb[3] = {lighting.background[0], lighting.background[1], lighting.background[2]};
      out.depth[pixel] = std::numeric_limits<float>::infinity();
      if (std::isfinite(hit.distance))
      {
        out.depth[pixel] = float(hit.distance / length);
        double at[3], to_eye[3];
        for (int r = 0; r < 3; ++r)
        {
          at[r] = origin[r] + dir[r] * hit.distance;
          to_eye[r] = -dir[r];
        }
        bool textured = false;
        const Material m = hit.primitive->surfaceMaterial(hit.triangle, textured);
        const double shininess = m.hasSpecular() ? m.shininess : 0.0;
        double diffuse[3] = {0, 0, 0}, specular[3] = {0, 0, 0};
        if (lighting.has_sun)
        {
          double towards_sun = 0;
          for (int r = 0; r < 3; ++r)
            towards_sun += hit.normal[r] * lighting.towards_light[r];
          if (lighting.shadows && towards_sun > 0)
          {
            double from[3];
            for (int r = 0; r < 3; ++r)  // just off the surface, on the lit side
              from[r] = at[r] + hit.normal[r] * 1e-4;
            out.light[pixel] = !std::isfinite(scene.castHit(from, lighting.towards_light, 0, 1e4, kSeenByCameras).distance);
          }
          addLight(lighting.sun, shininess, at, hit.normal, to_eye, diffuse, specular);
        }
        for (const Lighting::Light& light : lighting.lights)
          addLight(light, shininess, at, hit.normal, to_eye, diffuse, specular);
        Rgba c{1, 1, 1, 1};
        if (textured && !bilinearTexel(hit, c))
          c = hit.primitive->surfaceColour(hit.triangle, hit.u, hit.v);
        const double shadow = out.light[pixel];
        const double base[3] = {lighting.ambient[0] * m.ambient.r + m.emissive.r,
                                lighting.ambient[1] * m.ambient.g + m.emissive.g,
                                lighting.ambient[2] * m.ambient.b + m.emissive.b};
        const double kd[3] = {m.diffuse.r, m.diffuse.g, m.diffuse.b}, ks[3] = {m.specular.r, m.specular.g, m.specular.b};
        const double texel[3] = {c.r, c.g, c.b};
        for (int k = 0; k < 3; ++k)
          rgb[k] = (base[k] + kd[k] * diffuse[k] * shadow) * texel[k] + ks[k] * specular[k] * shadow;
      }
      for (int k = 0; k < 3; ++k)
        out.rgb8[3 * pixel + size_t(k)] = uint8_t(int(std::max(0.0, std::min(1.0, rgb[k])) * 255.0 + 0.5));
    }
  return out;
}
}  // namespace

TEST(GlContext, MesasSoftwareRendererWhenTheCpuIsAskedFor)
{
  std::unique_ptr<GlContext> gl = llvmpipe();
  ASSERT_TRUE(gl);
  EXPECT_TRUE(gl->software());
  EXPECT_NE(gl->renderer().find("llvmpipe"), std::string::npos) << gl->renderer();
  EXPECT_NE(gl->version().find("OpenGL ES 3"), std::string::npos) << gl->version();
  // test_gtests.py runs each case at each of llvmpipe's vector widths: it says which it runs
  if (const char* width = std::getenv("LP_NATIVE_VECTOR_WIDTH"))
    EXPECT_NE(gl->renderer().find(std::string(width) + " bits"), std::string::npos) << gl->renderer();
}

TEST(GlContext, TheEnvironmentChoosesTheDevice)
{
  std::string error;
  setenv("TIANRACER_GL_DEVICE", "cpu", 1);
  EXPECT_EQ(glDeviceFromEnvironment(error), GlDevice::Cpu);
  setenv("TIANRACER_GL_DEVICE", "gpu", 1);
  EXPECT_EQ(glDeviceFromEnvironment(error), GlDevice::Gpu);
  EXPECT_TRUE(error.empty());
  setenv("TIANRACER_GL_DEVICE", "voodoo", 1);
  EXPECT_EQ(glDeviceFromEnvironment(error), GlDevice::Any);
  EXPECT_NE(error.find("TIANRACER_GL_DEVICE is 'voodoo'"), std::string::npos) << error;
  unsetenv("TIANRACER_GL_DEVICE");
  error.clear();
  EXPECT_EQ(glDeviceFromEnvironment(error), GlDevice::Any);
  EXPECT_TRUE(error.empty());
}

// Compares a rasterized frame with the ray-cast one (castFrame) away from silhouette edges: the pixel and its
// eight neighbours on one surface (depths within 5 % of each other in the ray-cast frame, or all of
// them background). Expects 99 % of them within 3/255 and depths within 1 mm where both see a
// surface, and a frame mostly of such pixels; prints the measures.
void expectAgreement(const PinholeImage& rasterized, const RayFrame& cast, const PinholeCamera& camera,
                     const std::string& what)
{
  const int w = camera.width, h = camera.height;
  if (const char* dump = std::getenv("GL_DUMP"))
  {
    stbi_write_png((std::string(dump) + "_gl.png").c_str(), w, h, 3, rasterized.rgb8.data(), 3 * w);
    stbi_write_png((std::string(dump) + "_rays.png").c_str(), w, h, 3, cast.rgb8.data(), 3 * w);
  }
  auto interior = [&](int u, int v) {
    const float d = cast.depth[size_t(v * w + u)];
    for (int dv = -1; dv <= 1; ++dv)
      for (int du = -1; du <= 1; ++du)
      {
        const int x = u + du, y = v + dv;
        if (x < 0 || y < 0 || x >= w || y >= h)
          return false;
        const float n = cast.depth[size_t(y * w + x)];
        if (cast.light[size_t(y * w + x)] != cast.light[size_t(v * w + u)])
          return false;  // a shadow's edge: the shadow maps' texels and filter soften it
        if (std::isinf(d) != std::isinf(n) || (!std::isinf(d) && std::fabs(n - d) > 0.05f * d))
          return false;
      }
    return true;
  };
  int compared = 0, close = 0, depths = 0;
  double worst_depth = 0;
  for (int v = 0; v < h; ++v)
    for (int u = 0; u < w; ++u)
    {
      if (!interior(u, v))
        continue;
      ++compared;
      const size_t k = size_t(v * w + u);
      int worst = 0;
      for (int c = 0; c < 3; ++c)
        worst = std::max(worst, std::abs(int(rasterized.rgb8[3 * k + size_t(c)]) - int(cast.rgb8[3 * k + size_t(c)])));
      close += worst <= 3;
      if (std::isfinite(cast.depth[k]))
      {
        ++depths;
        worst_depth = std::max(worst_depth, double(std::fabs(rasterized.depth[k] - cast.depth[k])));
      }
      else
        EXPECT_TRUE(std::isinf(rasterized.depth[k])) << what << ": " << u << ", " << v;
    }
  EXPECT_GT(compared, w * h * 3 / 4) << what;
  EXPECT_GT(depths, w * h / 2) << what;
  EXPECT_GE(double(close) / compared, 0.99) << what << ": " << close << " of " << compared << " within 3/255";
  EXPECT_LT(worst_depth, 1e-3) << what;
  std::printf("%s against ray casting: %d of %d interior pixels within 3/255, worst depth %.2g m\n", what.c_str(),
              close, compared, worst_depth);
}

// `shapes` uploaded as the world's draws, as GlScene draws them: never moving, planes casting no
// shadow.
std::vector<GlRenderer::Draw> worldDraws(GlRenderer& renderer, const std::vector<RayPrimitive>& shapes)
{
  std::vector<GlRenderer::Draw> draws;
  for (const RayPrimitive& p : shapes)
    draws.push_back({renderer.addMesh(glTrianglesOf(p)), Frame(), false, p.kind != Shape::Kind::Plane});
  return draws;
}

// Renders `shapes` (the world's) both ways from kCamera.
void expectTheRayCastFrame(const std::vector<RayPrimitive>& shapes, const char* scene_name,
                           const PinholeCamera& camera = pinhole(), const Lighting& lighting = sunLight())
{
  std::unique_ptr<GlContext> gl = llvmpipe();
  ASSERT_TRUE(gl);
  GlRenderer renderer(*gl);
  const std::vector<GlRenderer::Draw> draws = worldDraws(renderer, shapes);
  PinholeImage rasterized;
  renderer.render(draws, kCamera, camera, lighting, rasterized);
  RayScene rays(shapes);
  rays.commit(nullptr);
  const RayFrame cast = castFrame(rays, kCamera, camera, lighting);
  expectAgreement(rasterized, cast, camera, std::string(scene_name) + ", GL (" + gl->renderer() + ")");
}

TEST(GlRenderer, BoxesLookAsRaysThroughThePixelsSeeThem) { expectTheRayCastFrame(scene(), "boxes"); }

// A material given outright (its ambient, diffuse, specular, emissive and shininess).
VisualMaterial made(Rgba ambient, Rgba diffuse, Rgba specular, double shininess, Rgba emissive = {0, 0, 0, 1})
{
  VisualMaterial v;
  v.has_replace = true;
  v.replace.ambient = ambient;
  v.replace.diffuse = diffuse;
  v.replace.specular = specular;
  v.replace.shininess = shininess;
  v.replace.emissive = emissive;
  return v;
}

// The boxes and curved shapes of specular materials (one emissive) under a coloured ambient light,
// a sun with a specular colour, a point lamp, a spot lamp and a second directional light: each
// pixel as the rays work OGRE's lighting out.
TEST(GlRenderer, LampsAndSpecularSurfacesLookAsRaysThroughThePixelsSeeThem)
{
  std::vector<RayPrimitive> shapes = scene();
  shapes[0].material = made({0.3f, 0.3f, 0.3f, 1}, {0.6f, 0.6f, 0.55f, 1}, {0.5f, 0.5f, 0.5f, 1}, 12);
  shapes[1].material = made({0.9f, 0.2f, 0.1f, 1}, {0.9f, 0.2f, 0.1f, 1}, {0.8f, 0.8f, 0.8f, 1}, 40);
  shapes[2].material = made({0.05f, 0.2f, 0.05f, 1}, {0.1f, 0.7f, 0.2f, 1}, {0, 0, 0, 1}, 0, {0.1f, 0.15f, 0.0f, 1});
  const std::vector<RayPrimitive> curved = curvedScene();
  shapes.push_back(curved[1]);  // the large sphere
  shapes.back().material = made({0.5f, 0.2f, 0.2f, 1}, {0.9f, 0.3f, 0.2f, 1}, {0.6f, 0.6f, 0.6f, 1}, 25);
  Lighting lighting = sunLight();
  for (int i = 0; i < 3; ++i)
  {
    lighting.ambient[i] = 0.15f + 0.05f * float(i);
    lighting.sun.diffuse[i] = 0.4f;
    lighting.sun.specular[i] = 0.3f;
  }
  Lighting::Light point;
  point.kind = Lighting::Light::Point;
  const float point_at[3] = {1.4f, -0.6f, 1.2f}, point_colour[3] = {0.6f, 0.5f, 0.4f};
  std::copy(point_at, point_at + 3, point.position);
  std::copy(point_colour, point_colour + 3, point.diffuse);
  std::fill(point.specular, point.specular + 3, 0.7f);
  const float point_attenuation[4] = {8, 0.5f, 0.2f, 0.1f};
  std::copy(point_attenuation, point_attenuation + 4, point.attenuation);
  Lighting::Light spot = point;
  spot.kind = Lighting::Light::Spot;
  const float spot_at[3] = {2.6f, 0.6f, 2.5f}, spot_axis[3] = {0.0f, -0.6f, -0.8f};
  std::copy(spot_at, spot_at + 3, spot.position);
  std::copy(spot_axis, spot_axis + 3, spot.direction);
  std::fill(spot.diffuse, spot.diffuse + 3, 0.5f);
  const float spot_attenuation[4] = {20, 1, 0, 0.05f};
  std::copy(spot_attenuation, spot_attenuation + 4, spot.attenuation);
  spot.spot[0] = float(std::cos(0.5 / 2));
  spot.spot[1] = float(std::cos(1.2 / 2));
  spot.spot[2] = 1.5f;
  Lighting::Light second;
  second.kind = Lighting::Light::Directional;
  const float second_axis[3] = {0.6f, 0.8f, 0.0f};
  std::copy(second_axis, second_axis + 3, second.direction);
  std::fill(second.diffuse, second.diffuse + 3, 0.15f);
  std::fill(second.specular, second.specular + 3, 0.0f);
  lighting.lights = {point, spot, second};
  expectTheRayCastFrame(shapes, "lamps and specular surfaces", pinhole(), lighting);
}

// Without a sun (a world whose file gives no directional light): the ambient light and a lamp alone.
TEST(GlRenderer, AWorldWithoutASunIsLitByItsAmbientLightAndLampsAlone)
{
  Lighting lighting;
  Lighting::Light lamp;
  const float lamp_at[3] = {1.0f, 0.0f, 1.5f};
  std::copy(lamp_at, lamp_at + 3, lamp.position);
  const float lamp_attenuation[4] = {20, 0.32f, 0.01f, 0.03f};
  std::copy(lamp_attenuation, lamp_attenuation + 4, lamp.attenuation);
  std::fill(lamp.diffuse, lamp.diffuse + 3, 0.5f);
  lighting.lights = {lamp};
  ASSERT_FALSE(lighting.has_sun);
  expectTheRayCastFrame(scene(), "no sun, a lamp", pinhole(), lighting);
}

TEST(GlRenderer, SpheresCylindersAndAPlaneLookAsRaysThroughThePixelsSeeThem)
{
  expectTheRayCastFrame(curvedScene(), "spheres, cylinders, a plane");
}

// Frustum culling leaves out what lies wholly outside the view and nothing more: boxes behind, above
// and beside the camera and beyond the far clip plane are not drawn, and the frame is still the
// ray-cast one (the floor reaches out of the view on every side and behind the camera).
TEST(GlRenderer, WhatLiesOutsideTheViewIsLeftOutAndTheFrameIsTheSame)
{
  std::vector<RayPrimitive> shapes = scene();
  for (const urdf::Pose& outside : {poseFromXyzRpy(-4, 0.2, 1.2, 0, 0, 0), poseFromXyzRpy(-1.5, 6, 1.2, 0, 0, 0),
                                    poseFromXyzRpy(-1.5, -6, 1.2, 0, 0, 0), poseFromXyzRpy(-1, 0.2, 8, 0, 0, 0),
                                    poseFromXyzRpy(60, 0, 1, 0, 0, 0)})
    shapes.push_back(box(0.5, 0.5, 0.5, outside, Rgba{1, 0, 1, 1}));
  std::unique_ptr<GlContext> gl = llvmpipe();
  ASSERT_TRUE(gl);
  GlRenderer renderer(*gl);
  const std::vector<GlRenderer::Draw> draws = worldDraws(renderer, shapes);
  PinholeImage rasterized;
  renderer.render(draws, kCamera, pinhole(), Lighting(), rasterized);
  EXPECT_EQ(renderer.lastFrame().runs_culled, 5);
  EXPECT_EQ(renderer.lastFrame().runs_drawn, int(shapes.size()) - 5);
  RayScene rays(shapes);
  rays.commit(nullptr);
  expectAgreement(rasterized, castFrame(rays, kCamera, pinhole(), Lighting()), pinhole(), "culled boxes");
}

// Back faces are culled, as OGRE renders Gazebo's cameras: a camera inside its own link's box (the
// rrbot of gazebo_ros_demos, a 5 cm box around its camera) sees the world outside, not the box.
TEST(GlRenderer, ACameraInsideABoxSeesOut)
{
  std::vector<RayPrimitive> shapes = scene();
  std::unique_ptr<GlContext> gl = llvmpipe();
  ASSERT_TRUE(gl);
  GlRenderer renderer(*gl);
  std::vector<GlRenderer::Draw> draws = worldDraws(renderer, shapes);
  const std::vector<RayPrimitive> link = {box(0.05, 0.05, 0.05, poseFromXyzRpy(-1.5, 0.2, 1.2, 0, 0, 0),
                                               Rgba{0.28f, 0.0f, 0.0f, 1})};
  const std::vector<GlRenderer::Draw> around = worldDraws(renderer, link);
  draws.insert(draws.end(), around.begin(), around.end());
  PinholeImage rasterized;
  renderer.render(draws, kCamera, pinhole(), Lighting(), rasterized);
  RayScene rays(shapes);  // the world without the box
  rays.commit(nullptr);
  expectAgreement(rasterized, castFrame(rays, kCamera, pinhole(), Lighting()), pinhole(), "inside a box");
}

// A colour frame draws a coarser level of a finely tessellated shape where its error spans under
// kLevelOfDetailPixels (a depth frame never does): far fewer vertices, the same picture but for
// the odd pixel along an outline.
TEST(GlRenderer, LevelsOfDetailStandInForFarFineShapesInColourFrames)
{
  std::vector<RayPrimitive> shapes = curvedScene();
  std::unique_ptr<GlContext> gl = llvmpipe();
  ASSERT_TRUE(gl);
  GlRenderer renderer(*gl);
  const std::vector<GlRenderer::Draw> draws = worldDraws(renderer, shapes);
  PinholeCamera camera = pinhole();
  PinholeImage full, coarse;
  renderer.render(draws, kCamera, camera, Lighting(), full);
  const GlRenderer::FrameStats every = renderer.lastFrame();
  EXPECT_EQ(every.vertices_drawn, every.vertices_in_runs);
  camera.depth = false;
  renderer.render(draws, kCamera, camera, Lighting(), coarse);
  const GlRenderer::FrameStats fewer = renderer.lastFrame();
  EXPECT_LT(fewer.vertices_drawn * 4, every.vertices_drawn) << fewer.vertices_drawn << " of " << every.vertices_drawn;
  int differ = 0;
  for (size_t k = 0; k < full.rgb8.size(); k += 3)
  {
    int worst = 0;
    for (size_t c = 0; c < 3; ++c)
      worst = std::max(worst, std::abs(int(full.rgb8[k + c]) - int(coarse.rgb8[k + c])));
    differ += worst > 3;
  }
  const int pixels = camera.width * camera.height;
  if (const char* dump = std::getenv("GL_DUMP"))
  {
    stbi_write_png((std::string(dump) + "_full.png").c_str(), camera.width, camera.height, 3, full.rgb8.data(), 3 * camera.width);
    stbi_write_png((std::string(dump) + "_coarse.png").c_str(), camera.width, camera.height, 3, coarse.rgb8.data(), 3 * camera.width);
  }
  EXPECT_LT(differ, pixels / 100) << differ << " of " << pixels << " pixels differ by more than 3/255";
  std::printf("levels of detail: %ld of %ld vertices drawn, %d of %d pixels differ by more than 3/255\n",
              fewer.vertices_drawn, every.vertices_drawn, differ, pixels);
}

// The noise (pinhole.h): each pixel's three values moved by its sample (in levels) from the frame's offset,
// the same frame for the same offset, another for another; its spread that of the samples.
TEST(GlRenderer, CameraNoiseIsTheSamplesFromTheFramesOffset)
{
  std::mt19937 rng(7);
  const float sigma = 0.01f;
  std::normal_distribution<float> gaussian(0.0f, sigma);
  const std::vector<int16_t> noise = noiseSamples(size_t(pinhole().width) * pinhole().height, [&] { return gaussian(rng); });
  std::unique_ptr<GlContext> gl = llvmpipe();
  ASSERT_TRUE(gl);
  GlRenderer renderer(*gl);
  const std::vector<GlRenderer::Draw> draws = worldDraws(renderer, scene());
  PinholeCamera camera = pinhole();
  PinholeImage clean, noisy, again, other;
  renderer.render(draws, kCamera, camera, sunLight(), clean);
  camera.noise = noise.data();
  camera.noise_offset = 1234;
  renderer.render(draws, kCamera, camera, sunLight(), noisy);
  renderer.render(draws, kCamera, camera, sunLight(), again);
  camera.noise_offset = PinholeCamera::kNoiseOffsets - 1;
  renderer.render(draws, kCamera, camera, sunLight(), other);
  EXPECT_EQ(noisy.rgb8, again.rgb8);
  EXPECT_NE(noisy.rgb8, other.rgb8);
  for (size_t k = 0; k < clean.rgb8.size(); ++k)
    ASSERT_EQ(noisy.rgb8[k], std::min(255, std::max(0, clean.rgb8[k] + noise[1234 + k / 3]))) << "value " << k;
  double sum = 0, squares = 0;
  size_t count = 0;
  for (size_t k = 0; k < clean.rgb8.size(); ++k)
    if (clean.rgb8[k] > 10 && clean.rgb8[k] < 245)  // no clamping
    {
      const double d = (int(noisy.rgb8[k]) - int(clean.rgb8[k])) / 255.0;
      sum += d, squares += d * d, ++count;
    }
  ASSERT_GT(count, clean.rgb8.size() / 2);
  const double mean = sum / count, spread = std::sqrt(squares / count - mean * mean);
  EXPECT_NEAR(mean, 0.0, 0.001);
  // the samples rounded to whole levels: a uniform error 1/255 wide, variance 1 / (12 * 255^2)
  EXPECT_NEAR(spread, std::sqrt(sigma * sigma + 1.0 / (12 * 255.0 * 255.0)), 0.0005);
}

// A wall textured with a repeating 8 x 8 image of 64 colours (texture coordinates 0 to 2 across
// it), before the floor.
std::vector<RayPrimitive> texturedScene(const std::string& dir)
{
  std::vector<uint8_t> rgb;
  for (int r = 0; r < 8; ++r)
    for (int c = 0; c < 8; ++c)
      rgb.insert(rgb.end(), {uint8_t(30 * c + 10), uint8_t(30 * r + 10), uint8_t(200 - 20 * ((r + c) % 8))});
  EXPECT_TRUE(stbi_write_png((dir + "/tiles.png").c_str(), 8, 8, 3, rgb.data(), 24));
  std::ofstream(dir + "/wall.mtl") << "newmtl tiles\nKd 1 1 1\nmap_Kd tiles.png\n";
  std::ofstream(dir + "/wall.obj") << "mtllib wall.mtl\n"
                                      "v 0 -1.5 0\nv 0 1.5 0\nv 0 1.5 2\nv 0 -1.5 2\n"
                                      "vt 0 0\nvt 2 0\nvt 2 2\nvt 0 2\n"
                                      "usemtl tiles\nf 1/1 3/3 2/2\nf 1/1 4/4 3/3\n";  // facing -x, the camera
  std::string reason;
  std::shared_ptr<const MeshData> wall = loadMesh(dir + "/wall.obj", urdf::Vector3(1, 1, 1), reason);
  EXPECT_TRUE(wall && wall->submeshes[0].image) << reason;
  std::vector<RayPrimitive> shapes = scene();
  shapes.resize(1);  // the floor
  shapes.push_back(RayPrimitive::fromMesh(wall, poseFromXyzRpy(1.2, 0.2, 0, 0, 0, 0.2), nullptr));
  return shapes;
}

// Close enough that every texel spans several pixels: the GL samples the image itself, bilinear.
TEST(GlRenderer, MagnifiedTexturesShowTheTexelsARayThroughThePixelHitsBilinearly)
{
  const std::string dir = mesh_fixtures::tempDir("gl_textures");
  expectTheRayCastFrame(texturedScene(dir), "a textured wall");
}

// Far away, a pixel covers dozens of texels of a black and white checker of one-texel squares: the
// mipmaps give their mean grey (nearest sampling would alias to black or white at random).
TEST(GlRenderer, MinifiedTexturesShowTheirMipmapsMean)
{
  const std::string dir = mesh_fixtures::tempDir("gl_mipmaps");
  std::vector<uint8_t> rgb;
  for (int r = 0; r < 64; ++r)
    for (int c = 0; c < 64; ++c)
      rgb.insert(rgb.end(), 3, uint8_t((r + c) % 2 ? 255 : 0));
  ASSERT_TRUE(stbi_write_png((std::string(dir) + "/checker.png").c_str(), 64, 64, 3, rgb.data(), 3 * 64));
  std::ofstream(std::string(dir) + "/floor.mtl") << "newmtl checker\nKd 1 1 1\nmap_Kd checker.png\n";
  std::ofstream(std::string(dir) + "/floor.obj") << "mtllib floor.mtl\n"
                                                   "v -50 -50 0\nv 50 -50 0\nv 50 50 0\nv -50 50 0\n"
                                                   "vt 0 0\nvt 400 0\nvt 400 400\nvt 0 400\n"
                                                   "usemtl checker\nf 1/1 2/2 3/3\nf 1/1 3/3 4/4\n";
  std::string reason;
  std::shared_ptr<const MeshData> floor = loadMesh(std::string(dir) + "/floor.obj", urdf::Vector3(1, 1, 1), reason);
  ASSERT_TRUE(floor && floor->submeshes[0].image) << reason;
  std::unique_ptr<GlContext> gl = llvmpipe();
  ASSERT_TRUE(gl);
  GlRenderer renderer(*gl);
  const std::vector<GlRenderer::Draw> draws = {
      {renderer.addMesh(glTrianglesOf(RayPrimitive::fromMesh(floor, urdf::Pose(), nullptr))), Frame(), false, false}};
  const Lighting lighting = sunLight();
  PinholeImage image;
  // 20 m up looking straight down: a pixel spans 0.17 m, 43 texels of 3.9 mm
  renderer.render(draws, Frame::fromPose(poseFromXyzRpy(0, 0, 20, 0, M_PI / 2, 0)), pinhole(), lighting, image);
  // floor.mtl gives Kd 1 and no Ka (0): the checker's mean grey in the sun's diffuse light alone
  const double lit = lighting.sun.diffuse[0] * lighting.towards_light[2];
  const double grey = 0.5 * lit * 255;
  double worst = 0;
  for (uint8_t value : image.rgb8)
    worst = std::max(worst, std::fabs(value - grey));
  EXPECT_LT(worst, 4.0) << "every pixel the checker's mean, lit: " << grey;
}

// GlScene keeps RayScene's bodies: the world, a robot's body moved between frames, hidden from
// one frame, removed; shapes only lidars see are not drawn.
TEST(GlScene, BodiesAreWhereRaySceneHasThem)
{
  std::unique_ptr<GlContext> gl = llvmpipe();
  ASSERT_TRUE(gl);
  std::vector<RayPrimitive> world = curvedScene();
  world.resize(2);  // the plane and a sphere
  RayPrimitive lidar_only = box(0.5, 0.5, 3.0, poseFromXyzRpy(0.3, 0.0, 1.0, 0, 0, 0), Rgba{1, 0, 1, 1});
  lidar_only.seen_by = kSeenByLidars;
  world.push_back(lidar_only);
  const int robot = 1;
  const std::vector<RayPrimitive> body = {box(0.6, 0.4, 0.3, urdf::Pose(), Rgba{0.9f, 0.5f, 0.1f, 1}),
                                          curved(Shape::Kind::Cylinder, 0.1, 0.1, poseFromXyzRpy(0.2, 0.25, 0, 1.5707963, 0, 0),
                                                 Rgba{0.1f, 0.1f, 0.1f, 1})};
  GlScene gl_scene(*gl, world);
  RayScene ray_scene(world);
  const int gl_body = gl_scene.addBody(&robot, body), ray_body = ray_scene.addBody(&robot, body);
  const PinholeCamera camera = pinhole();
  const Lighting lighting = sunLight();
  PinholeImage rasterized;
  for (const Frame& pose : {Frame::fromPose(poseFromXyzRpy(1.0, -0.3, 0.2, 0, 0, 0.5)),
                            Frame::fromPose(poseFromXyzRpy(2.5, 0.6, 0.6, 0.2, 0.1, -0.8))})
  {
    gl_scene.setPose(gl_body, pose);
    ray_scene.setPose(ray_body, pose);
    ray_scene.commit(nullptr);
    gl_scene.renderPinhole(kCamera, camera, lighting, rasterized);
    expectAgreement(rasterized, castFrame(ray_scene, kCamera, camera, lighting), camera, "a moving body");
  }
  ray_scene.commit(&robot);
  gl_scene.renderPinhole(kCamera, camera, lighting, rasterized, &robot);
  expectAgreement(rasterized, castFrame(ray_scene, kCamera, camera, lighting), camera, "the body hidden");
  gl_scene.removeOwner(&robot);
  ray_scene.removeOwner(&robot);
  ray_scene.commit(nullptr);
  PinholeImage removed;
  gl_scene.renderPinhole(kCamera, camera, lighting, removed);
  expectAgreement(removed, castFrame(ray_scene, kCamera, camera, lighting), camera, "the body removed");
  EXPECT_EQ(removed.rgb8, rasterized.rgb8) << "removed is as hidden";
}

// A pose with a NaN or a huge coordinate (bad input from a user's world) draws nothing: the
// background and no depth in every pixel, and the next frame is whole again.
TEST(GlRenderer, ACameraPoseThatIsNotFiniteShowsNothing)
{
  std::unique_ptr<GlContext> gl = llvmpipe();
  ASSERT_TRUE(gl);
  GlRenderer renderer(*gl);
  const std::vector<GlRenderer::Draw> draws = worldDraws(renderer, scene());
  const Lighting lighting = sunLight();
  PinholeImage nothing;  // the background alone, as the GL rounds it
  renderer.render({}, kCamera, pinhole(), lighting, nothing);
  for (double bad : {std::nan(""), 1e300, std::numeric_limits<double>::infinity()})
  {
    PinholeImage image;
    renderer.render(draws, Frame::fromPose(poseFromXyzRpy(bad, 0, 0.5, 0, 0, 0)), pinhole(), lighting, image);
    EXPECT_EQ(image.rgb8, nothing.rgb8) << "x = " << bad;
    EXPECT_TRUE(std::all_of(image.depth.begin(), image.depth.end(), [](float d) { return std::isinf(d); })) << "x = " << bad;
  }
  PinholeImage good;
  renderer.render(draws, kCamera, pinhole(), lighting, good);
  EXPECT_GT(std::count_if(good.depth.begin(), good.depth.end(), [](float d) { return std::isfinite(d); }),
            long(good.depth.size() / 2));
}

TEST(GlRenderer, TheSameInputsGiveTheSameFrameBitForBit)
{
  std::unique_ptr<GlContext> gl = llvmpipe();
  ASSERT_TRUE(gl);
  GlRenderer renderer(*gl);
  const std::vector<GlRenderer::Draw> draws = worldDraws(renderer, scene());
  PinholeImage first, second;
  renderer.render(draws, kCamera, pinhole(), sunLight(), first);
  renderer.render(draws, kCamera, pinhole(), sunLight(), second);
  EXPECT_EQ(first.rgb8, second.rgb8);
  EXPECT_EQ(0, std::memcmp(first.depth.data(), second.depth.data(), first.depth.size() * sizeof(float)));
}
