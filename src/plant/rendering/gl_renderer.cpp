#include "rendering/gl_renderer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>

#include <GLES3/gl3.h>
#include <GLES2/gl2ext.h>  // GL_RGBA16_EXT (GL_EXT_texture_norm16)
#include <meshoptimizer.h>

#include "bullet_plant/image_encoding.h"  // spreadTo16Bits

namespace bullet_plant
{
namespace
{
// The sun's diffuse share is worked out per vertex: on a flat face every vertex has the face's
// normal and sees the same side of it (n . (p - camera) is the same for every point p of the plane),
// so the face's value is exact; on a curved surface's fine facets it is interpolated between the
// surface's normals. The depth along the optical axis and the shadow maps' coordinates are affine in
// the position, so their perspective-correct interpolation is exact. The other lights, and every
// light's specular share (it follows the direction to the camera), are worked out per pixel, as
// OGRE's per-pixel lighting does them, from the world position and the normal on the side the
// camera sees.
// The camera program's shaders, after "#version 300 es" and the defines STATIC_SHADOWS,
// MOVING_SHADOWS, LIGHTS, SPECULAR and TEXTURED (0 or 1): a frame (or a draw, or a run of one
// material) without shadows, lamps, a specular surface or a texture pays nothing for them; and
// DIRECTIONAL_LIGHTS, POINT_LIGHTS and SPOT_LIGHTS, how many of each kind a draw's program sums.
const char* const kVertexShader = R"(
#define PER_PIXEL (LIGHTS || SPECULAR)
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec4 diffuse;   // the material's diffuse colour, its alpha the opacity
layout(location = 3) in vec2 uv;
layout(location = 4) in vec3 ambient;   // the material's ambient colour
layout(location = 5) in vec3 emissive;
layout(location = 6) in vec4 specular;  // the material's specular colour, its shininess
uniform mat4 clip_from_body;
uniform mat4 world_from_body;
uniform vec3 camera_origin;
uniform vec3 camera_forward;
uniform vec3 towards_sun;  // zero: no sun
uniform vec3 sun_diffuse;
uniform vec3 scene_ambient;
out float sun_cos;         // n . l of the sun on the face the camera sees, at least 0
out float depth_along_axis;
flat out vec3 material_base;  // emissive + scene ambient x material ambient
flat out vec4 material_diffuse;
#if SPECULAR
flat out vec4 material_specular;
#endif
#if TEXTURED
out vec2 texture_uv;
#endif
invariant gl_Position;
#if STATIC_SHADOWS
uniform mat4 static_shadow_from_world;
out vec3 static_shadow_coordinates;
#endif
#if MOVING_SHADOWS
uniform mat4 moving_shadow_from_world;
out vec3 moving_shadow_coordinates;
#endif
#if PER_PIXEL
out vec3 world_position;
out vec3 seen_normal;  // the world normal on the side the camera sees (zero for a degenerate one)
#endif
void main()
{
  vec4 world = world_from_body * vec4(position, 1.0);
  vec3 ray = world.xyz - camera_origin;
  vec3 world_normal = mat3(world_from_body) * normal;
  float length_n = length(world_normal);
  float facing = dot(world_normal, ray) > 0.0 ? -1.0 : 1.0;
  sun_cos = length_n > 0.0 ? max(0.0, facing * dot(world_normal, towards_sun) / length_n) : 0.0;
  depth_along_axis = dot(ray, camera_forward);
  material_base = emissive + scene_ambient * ambient;
  material_diffuse = diffuse;
#if SPECULAR
  material_specular = specular;
#endif
#if STATIC_SHADOWS
  static_shadow_coordinates = (static_shadow_from_world * world).xyz;
#endif
#if MOVING_SHADOWS
  moving_shadow_coordinates = (moving_shadow_from_world * world).xyz;
#endif
#if PER_PIXEL
  world_position = world.xyz;
  seen_normal = length_n > 0.0 ? facing * world_normal / length_n : vec3(0.0);
#endif
#if TEXTURED
  texture_uv = uv;
#endif
  gl_Position = clip_from_body * vec4(position, 1.0);
}
)";

// The colour rounded to bytes by the GL (the noise is added on the CPU), and the depth into a float
// attachment, read back only when wanted. In the sun's shadow every light's diffuse and specular
// share is gone and the ambient and emissive light stay (Gazebo's integrated PSSM shadows:
// ambient + (lit - ambient) x shadow); a face turned away from the sun is in no shadow; a shadow
// map's lookup is the 2 x 2 texels' comparisons, filtered (hardware PCF), and what lies outside a
// map is not shadowed by it. The texture modulates the ambient and diffuse light, the specular light
// is added after it (OGRE's colour_op modulate, its RTSS adding the specular at the end).
// The lamps' loops have no branch a pixel could take apart from its neighbours (llvmpipe runs both
// sides of one), and their bounds are the variant's constants: llvmpipe keeps a loop counter per
// pixel, so a loop to a uniform count reads every light's uniforms as per-pixel gathers and masks
// each pass, where a constant count unrolls into plain loads (six lamps over a 640 x 480 wall:
// 15 -> 8.7 CPU ms a frame).
const char* const kFragmentShader = R"(
#define PER_PIXEL (LIGHTS || SPECULAR)
precision highp float;
precision highp sampler2DShadow;
in float sun_cos;
in float depth_along_axis;
flat in vec3 material_base;     // emissive + scene ambient x material ambient
flat in vec4 material_diffuse;  // its alpha: the opacity
uniform vec3 sun_diffuse;
#if TEXTURED
in vec2 texture_uv;
uniform sampler2D image;
#endif
#if STATIC_SHADOWS
in vec3 static_shadow_coordinates;
uniform sampler2DShadow static_shadow;
#endif
#if MOVING_SHADOWS
in vec3 moving_shadow_coordinates;
uniform sampler2DShadow moving_shadow;
#endif
#if PER_PIXEL
in vec3 world_position;
in vec3 seen_normal;
uniform vec3 camera_origin;
#endif
#if SPECULAR
flat in vec4 material_specular;  // its shininess in w
uniform vec3 towards_sun;
uniform vec3 sun_specular;
#endif
#if LIGHTS
// the lights: DIRECTIONAL_LIGHTS directional, then POINT_LIGHTS point lights, then SPOT_LIGHTS spots
uniform vec3 light_position[8];
uniform vec3 light_direction[8];    // the way it shines: a directional light's, a spot's axis
uniform vec3 light_diffuse[8];
uniform vec3 light_specular[8];
uniform vec4 light_attenuation[8];  // range, constant, linear, quadratic
uniform vec3 light_spot[8];         // cos(inner / 2), cos(outer / 2), falloff
// light i's share at a pixel, towards l (unit) with attenuation x spot `share`
void shine(int i, vec3 l, float share, vec3 n, vec3 to_eye, inout vec3 diffuse_light, inout vec3 specular_light)
{
  float n_l = dot(n, l);
  diffuse_light += light_diffuse[i] * (max(n_l, 0.0) * share);
#if SPECULAR
  specular_light += light_specular[i] * (step(0.0, n_l) * share *
                                         pow(max(0.0, dot(n, normalize(l + to_eye))), material_specular.w));
#endif
}
#endif
layout(location = 0) out vec4 colour;
layout(location = 1) out float depth;
float lightThrough(sampler2DShadow map, vec3 at)
{
  if (at.x < 0.0 || at.x > 1.0 || at.y < 0.0 || at.y > 1.0 || at.z < 0.0)
    return 1.0;
  return texture(map, vec3(at.xy, min(at.z, 1.0)));  // beyond the map's depth: behind what it holds
}
void main()
{
#if PER_PIXEL
  float length_n = length(seen_normal);
  vec3 n = length_n > 0.0 ? seen_normal / length_n : vec3(0.0);
  vec3 to_eye = normalize(camera_origin - world_position);
#else
  vec3 n = vec3(0.0), to_eye = vec3(0.0);
#endif
  vec3 specular_light = vec3(0.0);
#if SPECULAR
  float shininess = material_specular.w;
  if (sun_cos > 0.0)
    specular_light = sun_specular * pow(max(0.0, dot(n, normalize(towards_sun + to_eye))), shininess);
#endif
#if LIGHTS
  // OGRE's per-pixel lights: diffuse x n . l x attenuation (x a spot's factor) within range; the
  // directional lights, the point lights and the spots each in a loop of their own (a loop with a
  // light of each kind in it would pay for the spot's cone at every light)
  vec3 diffuse_light = vec3(0.0);
  for (int i = 0; i < DIRECTIONAL_LIGHTS; ++i)
    shine(i, -light_direction[i], 1.0, n, to_eye, diffuse_light, specular_light);
  for (int i = DIRECTIONAL_LIGHTS; i < DIRECTIONAL_LIGHTS + POINT_LIGHTS; ++i)
  {
    vec3 to_light = light_position[i] - world_position;
    float dd = dot(to_light, to_light), inverse = inversesqrt(dd), d = dd * inverse;
    vec4 a = light_attenuation[i];
    shine(i, to_light * inverse, step(d, a.x) / (a.y + d * (a.z + a.w * d)), n, to_eye, diffuse_light, specular_light);
  }
  for (int i = DIRECTIONAL_LIGHTS + POINT_LIGHTS; i < DIRECTIONAL_LIGHTS + POINT_LIGHTS + SPOT_LIGHTS; ++i)
  {
    vec3 to_light = light_position[i] - world_position;
    float dd = dot(to_light, to_light), inverse = inversesqrt(dd), d = dd * inverse;
    vec3 l = to_light * inverse;
    vec4 a = light_attenuation[i];
    float rho = dot(-l, light_direction[i]);
    float inner = light_spot[i].x, outer = light_spot[i].y;
    float spot = inner > outer ? clamp((rho - outer) / (inner - outer), 0.0, 1.0) : 1.0;
    spot = step(outer, rho) * (light_spot[i].z > 0.0 ? pow(spot, light_spot[i].z) : 1.0);
    shine(i, l, spot * step(d, a.x) / (a.y + d * (a.z + a.w * d)), n, to_eye, diffuse_light, specular_light);
  }
#endif
  float light = 1.0;
#if STATIC_SHADOWS || MOVING_SHADOWS
  // only a face the sun shines on can lie in a shadow: Gazebo draws its casters' back faces into
  // the maps (OGRE's shadow_caster_render_back_faces), so a face turned away from the sun is level
  // with its own map depth, not behind it
  if (sun_cos > 0.0)
  {
#if STATIC_SHADOWS
    light *= lightThrough(static_shadow, static_shadow_coordinates);
#endif
#if MOVING_SHADOWS
    light *= lightThrough(moving_shadow, moving_shadow_coordinates);
#endif
  }
#endif
  // (the sun's diffuse x material diffuse is not a varying of its own: with one more flat varying,
  // llvmpipe (Mesa 22.3) at 128 bits corrupts its heap building the lamps-and-specular variant)
  vec3 lit = material_base + material_diffuse.rgb * sun_diffuse * (sun_cos * light);
#if LIGHTS
  lit += material_diffuse.rgb * diffuse_light * light;
#endif
  float alpha = material_diffuse.a;
#if TEXTURED
  // the texture's rows from the top, its t up from the bottom (mesh_loader.h's Texture::at)
  vec4 texel = texture(image, vec2(texture_uv.x, 1.0 - texture_uv.y));
  lit *= texel.rgb;
  alpha *= texel.a;
#endif
#if SPECULAR
  lit += material_specular.rgb * specular_light * light;
#endif
  colour = vec4(lit, alpha);
  depth = depth_along_axis;
}
)";

// What the light sees, for the shadow maps: depth only.
const char* const kShadowVertexShader = R"(#version 300 es
layout(location = 0) in vec3 position;
uniform mat4 light_clip_from_body;
invariant gl_Position;
void main() { gl_Position = light_clip_from_body * vec4(position, 1.0); }
)";
const char* const kShadowFragmentShader = R"(#version 300 es
void main() {}
)";

constexpr int kMipmapLevels = 5;  // below the image itself, as Gazebo asks OGRE for

// Throws with the GL's log when a shader did not compile or a program did not link.
template <class GetStatus, class GetLog>
void requireBuilt(unsigned object, unsigned status, GetStatus get_status, GetLog get_log, const char* what)
{
  GLint ok = 0;
  get_status(object, status, &ok);
  if (ok)
    return;
  char log[2048] = {0};
  get_log(object, sizeof log, nullptr, log);
  throw std::runtime_error(std::string("GL camera ") + what + ": " + log);
}

unsigned compile(unsigned kind, const char* source)
{
  const unsigned shader = glCreateShader(kind);
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  requireBuilt(shader, GL_COMPILE_STATUS, glGetShaderiv, glGetShaderInfoLog, "shader does not compile");
  return shader;
}

unsigned link(const std::string& vertex_source, const std::string& fragment_source)
{
  const unsigned vertex = compile(GL_VERTEX_SHADER, vertex_source.c_str());
  const unsigned fragment = compile(GL_FRAGMENT_SHADER, fragment_source.c_str());
  const unsigned program = glCreateProgram();
  glAttachShader(program, vertex);
  glAttachShader(program, fragment);
  glLinkProgram(program);
  glDeleteShader(vertex);
  glDeleteShader(fragment);
  requireBuilt(program, GL_LINK_STATUS, glGetProgramiv, glGetProgramInfoLog, "program does not link");
  return program;
}

// Column-major 4 x 4, as GL takes it.
struct Matrix4
{
  float m[16] = {0};
  float& at(int row, int column) { return m[column * 4 + row]; }
};

Matrix4 fromFrame(const Frame& f)
{
  Matrix4 out;
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
      out.at(r, c) = float(f.R[3 * r + c]);
    out.at(r, 3) = float(f.t[r]);
  }
  out.at(3, 3) = 1;
  return out;
}

// Body coordinates to clip coordinates, in double until the end: the optical frame (x right, y
// down, z forward) of the camera at `pose`, then the pinhole's projection with pixel centres at
// integer pixel coordinates (window coordinates have them at + 0.5), the image's top row at the
// window's bottom: glReadPixels then gives the rows in the image's order, from the top.
Matrix4 clipFromBody(const Frame& pose, const Frame& world_from_body, const PinholeCamera& camera)
{
  const Frame camera_from_body = [&] {
    Frame inverse;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c)
        inverse.R[3 * r + c] = pose.R[3 * c + r];
    double t[3];
    inverse.rotate(pose.t, t);
    for (int r = 0; r < 3; ++r)
      inverse.t[r] = -t[r];
    return inverse * world_from_body;
  }();
  // optical x = -camera y, y = -camera z, z = camera x
  double optical[3][4];
  const int row_of[3] = {1, 2, 0};
  const double sign_of[3] = {-1, -1, 1};
  for (int i = 0; i < 3; ++i)
  {
    for (int c = 0; c < 3; ++c)
      optical[i][c] = sign_of[i] * camera_from_body.R[3 * row_of[i] + c];
    optical[i][3] = sign_of[i] * camera_from_body.t[row_of[i]];
  }
  const double w = camera.width, h = camera.height, n = camera.near, f = camera.far;
  double projection[4][3] = {{2 * camera.fx / w, 0, 2 * (camera.cx + 0.5) / w - 1},
                             {0, 2 * camera.fy / h, 2 * (camera.cy + 0.5) / h - 1},
                             {0, 0, std::isfinite(f) ? (f + n) / (f - n) : 1.0},
                             {0, 0, 1}};
  const double z_offset = std::isfinite(f) ? -2 * f * n / (f - n) : -2 * n;
  Matrix4 out;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c)
    {
      double v = 0;
      for (int k = 0; k < 3; ++k)
        v += projection[r][k] * optical[k][c];
      if (r == 2 && c == 3)
        v += z_offset;
      out.at(r, c) = float(v);
    }
  return out;
}
}  // namespace

namespace
{
// Each triangle's own normal (unnormalised: the shader divides) at its three vertices.
std::vector<float> flatNormals(const std::vector<float>& xyz)
{
  std::vector<float> normals;
  normals.reserve(xyz.size());
  for (size_t t = 0; t + 9 <= xyz.size(); t += 9)
  {
    const float* p = &xyz[t];
    const float e1[3] = {p[3] - p[0], p[4] - p[1], p[5] - p[2]}, e2[3] = {p[6] - p[0], p[7] - p[1], p[8] - p[2]};
    const float face[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
    for (int v = 0; v < 3; ++v)
      normals.insert(normals.end(), face, face + 3);
  }
  return normals;
}
}  // namespace

GlTriangles glTrianglesOf(const RayPrimitive& primitive)
{
  GlTriangles out;
  auto vertex = [&](double x, double y, double z) {
    const double in[3] = {x, y, z};
    double at[3];
    primitive.frame.apply(in, at);
    out.xyz.insert(out.xyz.end(), {float(at[0]), float(at[1]), float(at[2])});
  };
  // a primitive's triangles are all of its one material (index 0)
  bool primitive_textured = false;
  if (primitive.kind != Shape::Kind::Mesh)
    out.materials.push_back(primitive.surfaceMaterial(-1, primitive_textured));
  auto colour = [&](int) { out.material.push_back(0); };
  if (primitive.kind == Shape::Kind::Box)
  {
    const double* h = primitive.half;
    // each face as two triangles, its corners counter-clockwise seen from outside
    static const int faces[6][4][3] = {{{1, -1, -1}, {1, 1, -1}, {1, 1, 1}, {1, -1, 1}},
                                       {{-1, 1, -1}, {-1, -1, -1}, {-1, -1, 1}, {-1, 1, 1}},
                                       {{1, 1, -1}, {-1, 1, -1}, {-1, 1, 1}, {1, 1, 1}},
                                       {{-1, -1, -1}, {1, -1, -1}, {1, -1, 1}, {-1, -1, 1}},
                                       {{-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}},
                                       {{-1, 1, -1}, {1, 1, -1}, {1, -1, -1}, {-1, -1, -1}}};
    static const int triangles[2][3] = {{0, 1, 2}, {0, 2, 3}};
    for (const auto& face : faces)
      for (const auto& triangle : triangles)
      {
        for (int k : triangle)
          vertex(face[k][0] * h[0], face[k][1] * h[1], face[k][2] * h[2]);
        colour(0);
      }
  }
  else if (primitive.kind == Shape::Kind::Plane)
  {
    std::vector<float> vertices;
    std::vector<int> indices;
    planeTriangles(primitive.normal, vertices, indices);
    for (size_t i = 0; i < indices.size(); ++i)
    {
      const float* v = &vertices[3 * size_t(indices[i])];
      vertex(v[0], v[1], v[2]);
      if (i % 3 == 2)
        colour(0);
    }
  }
  else if (primitive.kind == Shape::Kind::Sphere || primitive.kind == Shape::Kind::Cylinder ||
           primitive.kind == Shape::Kind::Capsule || primitive.kind == Shape::Kind::Ellipsoid)
  {
    const bool ellipsoid = primitive.kind == Shape::Kind::Ellipsoid;
    const double r = ellipsoid ? std::max({primitive.half[0], primitive.half[1], primitive.half[2]}) : primitive.radius;
    // segments around: the chord's sagitta r (1 - cos(pi / n)) within the tolerance, and at most
    // kMaxCurvedSegments, where the sagitta is 75 ppm of the radius: a 2 m sphere would otherwise
    // be 490k triangles and half a gigabyte of vertex buffers.
    const int n = std::min(kMaxCurvedSegments,
                           std::max(8, int(std::ceil(M_PI / std::acos(std::max(-1.0, 1.0 - kCurvedTolerance / r))))));
    auto normal = [&](double x, double y, double z) {
      const double in[3] = {x, y, z};
      double n_world[3];
      primitive.frame.rotate(in, n_world);
      out.normal.insert(out.normal.end(), {float(n_world[0]), float(n_world[1]), float(n_world[2])});
    };
    // a vertex on the surface with its normal (unit, in the shape frame)
    auto at = [&](double x, double y, double z, double nx, double ny, double nz) {
      vertex(x, y, z);
      normal(nx, ny, nz);
    };
    auto quad = [&](const std::array<double, 6>& a, const std::array<double, 6>& b, const std::array<double, 6>& c,
                    const std::array<double, 6>& d) {
      for (const auto* v : {&a, &b, &c, &a, &c, &d})
        at((*v)[0], (*v)[1], (*v)[2], (*v)[3], (*v)[4], (*v)[5]);
      colour(0);
      colour(0);
    };
    if (primitive.kind != Shape::Kind::Cylinder)
    {
      // A sphere (radius r) scaled to the ellipsoid's radii, its normal the gradient (x/a, y/b, z/c)
      // of the unit sphere's point; a capsule's hemispheres, the upper ring half raised by the half
      // length and the lower lowered, the equator a ring boundary.
      const double a = ellipsoid ? primitive.half[0] : r, b = ellipsoid ? primitive.half[1] : r,
                   c = ellipsoid ? primitive.half[2] : r;
      const double h = primitive.kind == Shape::Kind::Capsule ? primitive.half_length : 0.0;
      const int rings = (std::max(4, n / 2) + 1) / 2 * 2;
      auto point = [&](int ring, int segment, double offset) {
        const double polar = M_PI * ring / rings, azimuth = 2 * M_PI * segment / n;
        const double x = std::sin(polar) * std::cos(azimuth), y = std::sin(polar) * std::sin(azimuth), z = std::cos(polar);
        const double nx = x / a, ny = y / b, nz = z / c, length = std::sqrt(nx * nx + ny * ny + nz * nz);
        return std::array<double, 6>{a * x, b * y, c * z + offset, nx / length, ny / length, nz / length};
      };
      for (int ring = 0; ring < rings; ++ring)
      {
        const double offset = ring < rings / 2 ? h : -h;
        for (int segment = 0; segment < n; ++segment)
          quad(point(ring, segment, offset), point(ring + 1, segment, offset), point(ring + 1, segment + 1, offset),
               point(ring, segment + 1, offset));
      }
      if (h > 0)  // the capsule's side between its hemispheres
        for (int segment = 0; segment < n; ++segment)
        {
          auto side = [&](int k, double z) {
            const double angle = 2 * M_PI * k / n, x = std::cos(angle), y = std::sin(angle);
            return std::array<double, 6>{r * x, r * y, z, x, y, 0};
          };
          quad(side(segment, -h), side(segment + 1, -h), side(segment + 1, h), side(segment, h));
        }
    }
    else
    {
      const double h = primitive.half_length;
      auto side = [&](int segment, double z) {
        const double a = 2 * M_PI * segment / n, x = std::cos(a), y = std::sin(a);
        return std::array<double, 6>{r * x, r * y, z, x, y, 0};
      };
      for (int segment = 0; segment < n; ++segment)
      {
        quad(side(segment, -h), side(segment + 1, -h), side(segment + 1, h), side(segment, h));
        for (const double z : {h, -h})  // the caps: fans about the axis
        {
          const double up = z > 0 ? 1 : -1;
          const auto a = side(segment, z), b = side(segment + (z > 0 ? 1 : -1), z);
          at(0, 0, z, 0, 0, up);
          at(a[0], a[1], z, 0, 0, up);
          at(b[0], b[1], z, 0, 0, up);
          colour(0);
        }
      }
    }
  }
  else if (primitive.kind == Shape::Kind::Mesh && primitive.mesh)
  {
    const MeshData& mesh = *primitive.mesh;
    // each sub-mesh's material (the visual's applied to the file's), one entry per sub-mesh
    std::vector<bool> sub_textured(mesh.submeshes.size());
    for (size_t k = 0; k < mesh.submeshes.size(); ++k)
    {
      bool textured = false;
      out.materials.push_back(primitive.surfaceMaterial(mesh.submeshes[k].first_triangle, textured));
      sub_textured[k] = textured;
    }
    const bool any_textured = std::find(sub_textured.begin(), sub_textured.end(), true) != sub_textured.end();
    size_t sub_index = 0;
    for (int t = 0; t < mesh.triangleCount(); ++t)
    {
      for (int k = 0; k < 3; ++k)
      {
        const float* v = &mesh.vertices[3 * size_t(mesh.indices[3 * size_t(t) + size_t(k)])];
        vertex(v[0], v[1], v[2]);
      }
      while (sub_index + 1 < mesh.submeshes.size() && t >= mesh.submeshes[sub_index + 1].first_triangle)
        ++sub_index;
      const MeshData::SubMesh& sub = mesh.submeshes[sub_index];
      out.material.push_back(uint32_t(sub_index));
      const bool textured = sub_textured[sub_index];
      if (any_textured)
      {
        out.texture.push_back(textured ? sub.image : nullptr);
        for (int k = 0; k < 3; ++k)
        {
          const int corner = mesh.indices[3 * size_t(t) + size_t(k)];
          out.uv.insert(out.uv.end(), {textured ? mesh.uvs[2 * size_t(corner)] : 0.0f,
                                       textured ? mesh.uvs[2 * size_t(corner) + 1] : 0.0f});
        }
      }
    }
  }
  if (out.normal.empty())
    out.normal = flatNormals(out.xyz);
  return out;
}

GlRenderer::GlRenderer(const GlContext& context) : context_(context)
{
  context_.makeCurrent();
  const char* extensions = reinterpret_cast<const char*>(glGetString(GL_EXTENSIONS));
  if (!extensions || !std::strstr(extensions, "GL_EXT_color_buffer_float"))
  {
    context_.release();
    throw std::runtime_error("the GL (" + context.renderer() +
                             ") cannot render into float colour buffers (GL_EXT_color_buffer_float): no depth images");
  }
  norm16_ = std::strstr(extensions, "GL_EXT_texture_norm16") != nullptr;
  try
  {
    cameraProgram(ProgramKey());  // the plainest: a GL that cannot build it fails here, not in a frame
    shadow_program_ = link(kShadowVertexShader, kShadowFragmentShader);
  }
  catch (const std::runtime_error&)
  {
    context_.release();
    throw;
  }
  light_clip_from_body_ = glGetUniformLocation(shadow_program_, "light_clip_from_body");
  static_shadow_.size = kStaticShadowMapSize;
  moving_shadow_.size = kMovingShadowMapSize;
  context_.release();
}

GlRenderer::CameraProgram& GlRenderer::cameraProgram(const ProgramKey& key)
{
  CameraProgram& p = camera_programs_[key];
  if (p.program)
    return p;
  auto bit = [&](int flag) { return char('0' + ((key.variant & flag) ? 1 : 0)); };
  const std::string defines =
      std::string("#version 300 es\n#define STATIC_SHADOWS ") + bit(kStaticShadows) +
      "\n#define MOVING_SHADOWS " + bit(kMovingShadows) + "\n#define LIGHTS " + bit(kLights) +
      "\n#define SPECULAR " + bit(kSpecular) + "\n#define TEXTURED " + bit(kTextured) +
      "\n#define DIRECTIONAL_LIGHTS " + std::to_string(key.directional) + "\n#define POINT_LIGHTS " +
      std::to_string(key.point) + "\n#define SPOT_LIGHTS " + std::to_string(key.spot) + "\n";
  p.program = link(defines + kVertexShader, defines + kFragmentShader);
  for (const auto& u : {std::make_pair(&p.clip_from_body, "clip_from_body"),
                        std::make_pair(&p.world_from_body, "world_from_body"),
                        std::make_pair(&p.scene_ambient, "scene_ambient"),
                        std::make_pair(&p.image, "image"), std::make_pair(&p.camera_origin, "camera_origin"),
                        std::make_pair(&p.camera_forward, "camera_forward"), std::make_pair(&p.towards_sun, "towards_sun"),
                        std::make_pair(&p.sun_diffuse, "sun_diffuse"), std::make_pair(&p.sun_specular, "sun_specular"),
                        std::make_pair(&p.static_shadow_from_world, "static_shadow_from_world"),
                        std::make_pair(&p.moving_shadow_from_world, "moving_shadow_from_world"),
                        std::make_pair(&p.static_shadow, "static_shadow"), std::make_pair(&p.moving_shadow, "moving_shadow"),
                        std::make_pair(&p.light_position, "light_position"),
                        std::make_pair(&p.light_direction, "light_direction"),
                        std::make_pair(&p.light_diffuse, "light_diffuse"),
                        std::make_pair(&p.light_specular, "light_specular"),
                        std::make_pair(&p.light_attenuation, "light_attenuation"),
                        std::make_pair(&p.light_spot, "light_spot")})
    *u.first = glGetUniformLocation(p.program, u.second);
  return p;
}

GlRenderer::~GlRenderer()
{
  context_.makeCurrent();
  for (Mesh& m : meshes_)
  {
    glDeleteVertexArrays(1, &m.vertex_array);
    glDeleteBuffers(1, &m.buffer);
    glDeleteBuffers(1, &m.material_buffer);
  }
  for (auto& uploaded : textures_)
    glDeleteTextures(1, &uploaded.second);
  for (Target& t : targets_)
  {
    const unsigned buffers[3] = {t.colour, t.depth, t.depth_buffer};
    glDeleteRenderbuffers(3, buffers);
    glDeleteFramebuffers(1, &t.framebuffer);
  }
  for (ShadowMap* map : {&static_shadow_, &moving_shadow_})
  {
    glDeleteTextures(1, &map->texture);
    glDeleteFramebuffers(1, &map->framebuffer);
  }
  for (const auto& p : camera_programs_)
    if (p.second.program)
      glDeleteProgram(p.second.program);
  glDeleteProgram(shadow_program_);
  context_.release();
}

namespace
{
constexpr size_t kVertexFloats = 12;  // position, normal, colour, texture coordinates
constexpr size_t kMaterialFloats = 10;  // ambient, emissive, specular, shininess: the material buffer's
constexpr size_t kCornerFloats = kVertexFloats + kMaterialFloats;
// Runs smaller than this are drawn as they are: a level of detail would save less than its draw.
constexpr int kLevelOfDetailMinTriangles = 64;

// The levels of detail of `count` vertices from `first` in `vertices` (kVertexFloats each) and
// `materials` (kMaterialFloats each), appended to them: meshoptimizer's simplifier halves the triangles level by level while it can, keeping the
// topology and the seams where the colour, the texture coordinates or a smooth normal change (the
// corners are welded on those; a flat face's normal is worked out again for each new triangle).
std::vector<LevelOfDetail> appendLevelsOfDetail(std::vector<float>& vertices, std::vector<float>& materials, int first,
                                               int count)
{
  std::vector<LevelOfDetail> levels;
  if (count < 3 * kLevelOfDetailMinTriangles)
    return levels;
  // each corner's vertex and material, side by side, so the welding keeps materials apart too
  std::vector<float> corners;
  corners.reserve(size_t(count) * kCornerFloats);
  for (size_t c = size_t(first); c < size_t(first + count); ++c)
  {
    corners.insert(corners.end(), &vertices[c * kVertexFloats], &vertices[c * kVertexFloats] + kVertexFloats);
    corners.insert(corners.end(), &materials[c * kMaterialFloats], &materials[c * kMaterialFloats] + kMaterialFloats);
  }
  // Smooth: some corner's normal is not its face's (a curved surface's, or a mesh file's own).
  bool smooth = false;
  for (size_t t = 0; t < size_t(count) / 3 && !smooth; ++t)
  {
    const float* c = &corners[3 * t * kCornerFloats];
    const std::vector<float> face = flatNormals({c[0], c[1], c[2], c[kCornerFloats], c[kCornerFloats + 1],
                                                 c[kCornerFloats + 2], c[2 * kCornerFloats], c[2 * kCornerFloats + 1],
                                                 c[2 * kCornerFloats + 2]});
    for (int k = 0; k < 3 && !smooth; ++k)
      for (int i = 0; i < 3; ++i)
        smooth = smooth || std::fabs(c[k * kCornerFloats + 3 + size_t(i)] - face[size_t(i)]) > 1e-5f;
  }
  if (!smooth)
    for (size_t c = 0; c < size_t(count); ++c)
      std::fill_n(&corners[c * kCornerFloats + 3], 3, 0.0f);  // flat normals are not the surface's
  std::vector<unsigned> indices(static_cast<size_t>(count));
  const size_t stride = kCornerFloats * sizeof(float);
  const size_t unique = meshopt_generateVertexRemap(indices.data(), nullptr, size_t(count), corners.data(), size_t(count),
                                                    stride);
  std::vector<float> welded(unique * kCornerFloats);
  meshopt_remapVertexBuffer(welded.data(), corners.data(), size_t(count), stride, indices.data());
  const float scale = meshopt_simplifyScale(welded.data(), unique, stride);
  // Each level is simplified from the one before, not from the whole: the work halves level by level
  // (from the whole, a 250k-triangle sphere's ten levels took a second and a half). Its error is the
  // sum of the steps' errors, each measured against the level it came from: no less than its
  // distance from the original surface.
  std::vector<unsigned> simplified(indices.size());
  size_t previous = indices.size();
  float error_so_far = 0;
  for (size_t target = previous / 6 * 3; target >= 3 * size_t(kLevelOfDetailMinTriangles) / 2; target = previous / 6 * 3)
  {
    float error = 0;
    const size_t kept = meshopt_simplify(simplified.data(), indices.data(), previous, welded.data(), unique, stride,
                                         target, 1.0f, 0, &error);
    if (kept == 0 || kept > previous * 3 / 4)
      break;  // it keeps what it cannot take away without tearing
    error_so_far += error * scale;
    LevelOfDetail level{int(vertices.size() / kVertexFloats), int(kept), error_so_far};
    for (size_t i = 0; i < kept; i += 3)
    {
      const float* corner[3] = {&welded[simplified[i] * kCornerFloats], &welded[simplified[i + 1] * kCornerFloats],
                                &welded[simplified[i + 2] * kCornerFloats]};
      float normal[3] = {0, 0, 0};
      if (!smooth)
      {
        const float a[3] = {corner[1][0] - corner[0][0], corner[1][1] - corner[0][1], corner[1][2] - corner[0][2]};
        const float b[3] = {corner[2][0] - corner[0][0], corner[2][1] - corner[0][1], corner[2][2] - corner[0][2]};
        normal[0] = a[1] * b[2] - a[2] * b[1];
        normal[1] = a[2] * b[0] - a[0] * b[2];
        normal[2] = a[0] * b[1] - a[1] * b[0];
        const float n = std::sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]);
        for (float& x : normal)
          x = n > 0 ? x / n : 0.0f;
      }
      for (const float* c : corner)
      {
        vertices.insert(vertices.end(), c, c + kVertexFloats);
        materials.insert(materials.end(), c + kVertexFloats, c + kCornerFloats);
        if (!smooth)
          std::copy(normal, normal + 3, vertices.end() - std::ptrdiff_t(kVertexFloats) + 3);
      }
    }
    levels.push_back(level);
    std::copy_n(simplified.begin(), kept, indices.begin());
    previous = kept;
  }
  return levels;
}
}  // namespace

int GlRenderer::addMesh(const GlTriangles& triangles)
{
  context_.makeCurrent();
  const size_t count = triangles.xyz.size() / 9;
  // position, normal, colour, texture coordinates: twelve floats a vertex
  std::vector<float> vertices;
  vertices.reserve(count * 36);
  const std::vector<float> normals = triangles.normal.empty() ? flatNormals(triangles.xyz) : triangles.normal;
  for (size_t t = 0; t < count; ++t)
  {
    const float* p = &triangles.xyz[9 * t];
    for (int v = 0; v < 3; ++v)
    {
      const float* normal = &normals[9 * t + 3 * size_t(v)];
      vertices.insert(vertices.end(), p + 3 * v, p + 3 * v + 3);
      vertices.insert(vertices.end(), normal, normal + 3);
      const Rgba& diffuse = triangles.materials[triangles.material[t]].diffuse;
      vertices.insert(vertices.end(), {diffuse.r, diffuse.g, diffuse.b, diffuse.a});
      if (triangles.uv.empty())
        vertices.insert(vertices.end(), {0.0f, 0.0f});
      else
        vertices.insert(vertices.end(), &triangles.uv[6 * t + 2 * size_t(v)], &triangles.uv[6 * t + 2 * size_t(v)] + 2);
    }
  }
  Mesh mesh;
  mesh.vertex_count = int(3 * count);
  for (size_t k = 0; k < triangles.xyz.size(); ++k)
  {
    mesh.lo[k % 3] = std::min(mesh.lo[k % 3], double(triangles.xyz[k]));
    mesh.hi[k % 3] = std::max(mesh.hi[k % 3], double(triangles.xyz[k]));
  }
  // Runs of one texture, one kind (opaque or transparent) and with specular or without: a run's
  // materials are its vertices' (below), so a mesh of many colours is still a few draws.
  // and of one part (GlTriangles::part_ends), each with its bounds: a frame culls them one by one.
  size_t part = 0;  // the part triangle t is in
  for (size_t t = 0; t < count; ++t)
  {
    const unsigned texture = triangles.texture.empty() ? 0 : textureOf(triangles.texture[t]);
    const Material& m = triangles.materials[triangles.material[t]];
    const bool transparent = m.transparent(), specular = m.hasSpecular();
    bool part_begins = t == 0;
    for (; part < triangles.part_ends.size() && triangles.part_ends[part] <= t; ++part)
      part_begins = true;
    if (part_begins || mesh.runs.back().texture != texture || mesh.runs.back().transparent != transparent ||
        mesh.runs.back().specular != specular)
    {
      Run run;
      run.first = int(3 * t);
      run.texture = texture;
      run.transparent = transparent;
      run.specular = specular;
      mesh.runs.push_back(run);
      mesh.any_transparent = mesh.any_transparent || transparent;
    }
    Run& run = mesh.runs.back();
    run.count += 3;
    if (specular)
      run.max_specular = std::max({run.max_specular, m.specular.r, m.specular.g, m.specular.b});
    for (size_t k = 9 * t; k < 9 * t + 9; ++k)
    {
      run.lo[k % 3] = std::min(run.lo[k % 3], triangles.xyz[k]);
      run.hi[k % 3] = std::max(run.hi[k % 3], triangles.xyz[k]);
    }
  }
  // each vertex's material besides its diffuse colour (the colour attribute): ambient, emissive,
  // specular and shininess, ten floats, in a buffer of their own
  std::vector<float> materials;
  materials.reserve(count * 30);
  for (size_t t = 0; t < count; ++t)
  {
    const Material& m = triangles.materials[triangles.material[t]];
    for (int v = 0; v < 3; ++v)
      materials.insert(materials.end(), {m.ambient.r, m.ambient.g, m.ambient.b, m.emissive.r, m.emissive.g, m.emissive.b,
                                         m.specular.r, m.specular.g, m.specular.b, float(m.shininess)});
  }
  for (Run& run : mesh.runs)
    run.levels = appendLevelsOfDetail(vertices, materials, run.first, run.count);
  glGenVertexArrays(1, &mesh.vertex_array);
  glGenBuffers(1, &mesh.buffer);
  glBindVertexArray(mesh.vertex_array);
  glBindBuffer(GL_ARRAY_BUFFER, mesh.buffer);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices.size() * sizeof(float)), vertices.data(), GL_STATIC_DRAW);
  const GLsizei stride = 12 * sizeof(float);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(0));
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(3 * sizeof(float)));
  glEnableVertexAttribArray(2);
  glVertexAttribPointer(2, 4, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(6 * sizeof(float)));
  glEnableVertexAttribArray(3);
  glVertexAttribPointer(3, 2, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<void*>(10 * sizeof(float)));
  glGenBuffers(1, &mesh.material_buffer);
  glBindBuffer(GL_ARRAY_BUFFER, mesh.material_buffer);
  glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(materials.size() * sizeof(float)), materials.data(), GL_STATIC_DRAW);
  const GLsizei material_stride = 10 * sizeof(float);
  for (int k = 0; k < 3; ++k)
  {
    glEnableVertexAttribArray(GLuint(4 + k));
    glVertexAttribPointer(GLuint(4 + k), k == 2 ? 4 : 3, GL_FLOAT, GL_FALSE, material_stride,
                          reinterpret_cast<void*>(size_t(3 * k) * sizeof(float)));
  }
  glBindVertexArray(0);
  // A freed slot is taken again (a world that spawns and deletes models all day keeps its size).
  auto slot = std::find_if(meshes_.begin(), meshes_.end(), [](const Mesh& m) { return !m.vertex_array; });
  if (slot == meshes_.end())
    slot = meshes_.insert(slot, mesh);
  else
  {
    mesh.generation = slot->generation + 1;
    *slot = std::move(mesh);
  }
  context_.release();
  return int(slot - meshes_.begin());
}

void GlRenderer::removeMesh(int mesh)
{
  Mesh& m = meshes_.at(size_t(mesh));
  if (!m.vertex_array)
    return;
  context_.makeCurrent();
  glDeleteVertexArrays(1, &m.vertex_array);
  glDeleteBuffers(1, &m.buffer);
  glDeleteBuffers(1, &m.material_buffer);
  context_.release();
  const unsigned generation = m.generation;
  m = Mesh();
  m.generation = generation;
}

// Gazebo's sampling (rendering/RenderEngine.cc: five mipmap levels, OGRE's TFO_ANISOTROPIC at its
// default anisotropy of 1): trilinear, repeating.
unsigned GlRenderer::textureOf(const std::shared_ptr<const Texture>& image)
{
  if (!image)
    return 0;
  for (const auto& uploaded : textures_)
    if (uploaded.first == image)
      return uploaded.second;
  unsigned id = 0;
  glGenTextures(1, &id);
  glBindTexture(GL_TEXTURE_2D, id);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB8, image->width, image->height, 0, GL_RGB, GL_UNSIGNED_BYTE, image->rgb.data());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, kMipmapLevels);
  glGenerateMipmap(GL_TEXTURE_2D);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
  textures_.emplace_back(image, id);
  return id;
}

namespace
{
// A 4 x 4 in double, row major, for the matrices worked out before they go to the GL as floats.
using Matrix4d = std::array<std::array<double, 4>, 4>;

Matrix4d fromFrameDouble(const Frame& f)
{
  Matrix4d m{};
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
      m[r][c] = f.R[3 * r + c];
    m[r][3] = f.t[r];
  }
  m[3][3] = 1;
  return m;
}

Matrix4d operator*(const Matrix4d& a, const Matrix4d& b)
{
  Matrix4d m{};
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c)
      for (int k = 0; k < 4; ++k)
        m[r][c] += a[r][k] * b[k][c];
  return m;
}

Matrix4 toGl(const Matrix4d& m)
{
  Matrix4 out;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c)
      out.at(r, c) = float(m[r][c]);
  return out;
}

// The directional light's view of `corners` (world points): an orthographic projection along the
// light's travel that holds them all. clip_from_world draws into a shadow map; texture_from_world
// looks a world point up in it (x, y and depth in [0, 1]), its depth moved kShadowBias towards the
// light, so a lit surface does not shadow itself.
struct LightView
{
  Matrix4d clip_from_world, texture_from_world;
};
constexpr double kShadowBias = 0.004;  // m
constexpr double kShadowMargin = 0.01;  // m, about the casters on every side

LightView lightView(const double towards_light[3], const std::vector<std::array<double, 3>>& corners)
{
  const double w[3] = {-towards_light[0], -towards_light[1], -towards_light[2]};
  const double a[3] = {std::fabs(w[2]) < 0.9 ? 0.0 : 1.0, 0.0, std::fabs(w[2]) < 0.9 ? 1.0 : 0.0};
  double u[3] = {w[1] * a[2] - w[2] * a[1], w[2] * a[0] - w[0] * a[2], w[0] * a[1] - w[1] * a[0]};
  const double n = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
  for (double& x : u)
    x /= n;
  const double v[3] = {w[1] * u[2] - w[2] * u[1], w[2] * u[0] - w[0] * u[2], w[0] * u[1] - w[1] * u[0]};
  const double* axes[3] = {u, v, w};
  double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  for (const auto& p : corners)
    for (int i = 0; i < 3; ++i)
    {
      const double d = axes[i][0] * p[0] + axes[i][1] * p[1] + axes[i][2] * p[2];
      lo[i] = std::min(lo[i], d - kShadowMargin);
      hi[i] = std::max(hi[i], d + kShadowMargin);
    }
  LightView view{};
  for (int i = 0; i < 3; ++i)
  {
    const double scale = 1.0 / (hi[i] - lo[i]);
    for (int c = 0; c < 3; ++c)
    {
      view.clip_from_world[i][c] = 2 * scale * axes[i][c];
      view.texture_from_world[i][c] = scale * axes[i][c];
    }
    view.clip_from_world[i][3] = -2 * scale * lo[i] - 1;
    view.texture_from_world[i][3] = -scale * lo[i] - (i == 2 ? kShadowBias * scale : 0.0);
  }
  view.clip_from_world[3][3] = view.texture_from_world[3][3] = 1;
  return view;
}
}  // namespace

bool GlRenderer::drawShadowMap(ShadowMap& map, const std::vector<Draw>& draws, bool moving, const Lighting& lighting)
{
  std::vector<std::array<double, 3>> corners;
  for (const Draw& d : draws)
  {
    if (!d.casts_shadow || d.moves != moving)
      continue;
    const Mesh& mesh = meshes_.at(size_t(d.mesh));
    for (int k = 0; k < 8; ++k)
    {
      const double in[3] = {k & 1 ? mesh.hi[0] : mesh.lo[0], k & 2 ? mesh.hi[1] : mesh.lo[1], k & 4 ? mesh.hi[2] : mesh.lo[2]};
      std::array<double, 3> at;
      d.world_from_body.apply(in, at.data());
      if (std::isfinite(at[0]) && std::isfinite(at[1]) && std::isfinite(at[2]) && std::fabs(at[0]) < 1e6 &&
          std::fabs(at[1]) < 1e6 && std::fabs(at[2]) < 1e6)
        corners.push_back(at);
    }
  }
  if (corners.empty())
    return false;
  const LightView view = lightView(lighting.towards_light, corners);
  if (!map.texture)
  {
    glGenTextures(1, &map.texture);
    glBindTexture(GL_TEXTURE_2D, map.texture);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT32F, map.size, map.size, 0, GL_DEPTH_COMPONENT, GL_FLOAT, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    glGenFramebuffers(1, &map.framebuffer);
    glBindFramebuffer(GL_FRAMEBUFFER, map.framebuffer);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, map.texture, 0);
    const GLenum none = GL_NONE;
    glDrawBuffers(1, &none);
    glReadBuffer(GL_NONE);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, map.framebuffer);
  glViewport(0, 0, map.size, map.size);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDisable(GL_CULL_FACE);
  const float farthest = 1.0f;
  glClearBufferfv(GL_DEPTH, 0, &farthest);
  // a face's depth pushed back by its slope across a texel: its own map texels do not shadow it
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(2.0f, 2.0f);
  glUseProgram(shadow_program_);
  for (const Draw& d : draws)
  {
    if (!d.casts_shadow || d.moves != moving)
      continue;
    const Mesh& mesh = meshes_.at(size_t(d.mesh));
    glUniformMatrix4fv(light_clip_from_body_, 1, GL_FALSE,
                       toGl(view.clip_from_world * fromFrameDouble(d.world_from_body)).m);
    glBindVertexArray(mesh.vertex_array);
    glDrawArrays(GL_TRIANGLES, 0, mesh.vertex_count);
  }
  glBindVertexArray(0);
  glDisable(GL_POLYGON_OFFSET_FILL);
  const Matrix4 texture_from_world = toGl(view.texture_from_world);
  std::copy(texture_from_world.m, texture_from_world.m + 16, map.texture_from_world);
  return true;
}

// Each map is drawn again only when its casters or the light changed: the static casters' once,
// the moving ones' when a body moved (not for a second camera in the same step, nor while the
// robots stand), fitted to them.
void GlRenderer::drawShadowMaps(const std::vector<Draw>& draws, const Lighting& lighting)
{
  for (const bool moving : {false, true})
  {
    ShadowMap& map = moving ? moving_shadow_ : static_shadow_;
    std::vector<double> key(lighting.towards_light, lighting.towards_light + 3);
    for (const Draw& d : draws)
      if (d.moves == moving && d.casts_shadow)
      {
        key.push_back(d.mesh);
        key.insert(key.end(), d.world_from_body.R, d.world_from_body.R + 9);
        key.insert(key.end(), d.world_from_body.t, d.world_from_body.t + 3);
      }
    if (key != map.key)
    {
      map.used = drawShadowMap(map, draws, moving, lighting);
      map.key = key;
    }
  }
}

const GlRenderer::Target& GlRenderer::target(int width, int height, bool sixteen_bit)
{
  for (const Target& t : targets_)
    if (t.width == width && t.height == height && t.sixteen_bit == sixteen_bit)
      return t;
  Target t;
  t.width = width;
  t.height = height;
  t.sixteen_bit = sixteen_bit;
  unsigned buffers[3];
  glGenRenderbuffers(3, buffers);
  t.colour = buffers[0];
  t.depth = buffers[1];
  t.depth_buffer = buffers[2];
  glBindRenderbuffer(GL_RENDERBUFFER, t.colour);
  glRenderbufferStorage(GL_RENDERBUFFER, sixteen_bit ? GL_RGBA16_EXT : GL_RGBA8, width, height);
  glBindRenderbuffer(GL_RENDERBUFFER, t.depth);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_R32F, width, height);
  glBindRenderbuffer(GL_RENDERBUFFER, t.depth_buffer);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT32F, width, height);
  glGenFramebuffers(1, &t.framebuffer);
  glBindFramebuffer(GL_FRAMEBUFFER, t.framebuffer);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, t.colour);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_RENDERBUFFER, t.depth);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, t.depth_buffer);
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  targets_.push_back(t);  // deleted with the renderer, complete or not
  if (status != GL_FRAMEBUFFER_COMPLETE)
    throw std::runtime_error("GL camera framebuffer of " + std::to_string(width) + " x " + std::to_string(height) +
                             " is incomplete on " + context_.renderer());
  return targets_.back();
}

std::vector<GlRenderer::VisibleRun> GlRenderer::visibleRuns(const std::vector<Draw>& draws, const Frame& pose,
                                                            const PinholeCamera& camera, double max_error)
{
  std::vector<VisibleRun> visible;
  draw_matrices_.resize(draws.size());
  last_frame_ = FrameStats();
  for (size_t d = 0; d < draws.size(); ++d)
  {
    const Mesh& mesh = meshes_.at(size_t(draws[d].mesh));
    const Matrix4 clip = clipFromBody(pose, draws[d].world_from_body, camera);
    std::copy(clip.m, clip.m + 16, draw_matrices_[d].clip_from_body);
    const Matrix4 world = fromFrame(draws[d].world_from_body);
    std::copy(world.m, world.m + 16, draw_matrices_[d].world_from_body);
    for (const Run& run : mesh.runs)
    {
      // Outside when every corner lies beyond one plane of the frustum (-w <= x, y, z <= w), with
      // a margin for the float arithmetic: what touches the frustum's edge is drawn.
      int beyond[6] = {0, 0, 0, 0, 0, 0};
      double nearest = HUGE_VAL;
      for (int corner = 0; corner < 8; ++corner)
      {
        const float p[3] = {corner & 1 ? run.hi[0] : run.lo[0], corner & 2 ? run.hi[1] : run.lo[1],
                            corner & 4 ? run.hi[2] : run.lo[2]};
        double c[4];
        for (int r = 0; r < 4; ++r)
          c[r] = double(clip.m[r]) * p[0] + double(clip.m[4 + r]) * p[1] + double(clip.m[8 + r]) * p[2] + clip.m[12 + r];
        const double margin = 1e-4 * std::fabs(c[3]) + 1e-6;
        for (int axis = 0; axis < 3; ++axis)
        {
          beyond[2 * axis] += c[axis] < -c[3] - margin;
          beyond[2 * axis + 1] += c[axis] > c[3] + margin;
        }
        nearest = std::min(nearest, c[3]);  // w: the depth along the optical axis
      }
      if (std::find(beyond, beyond + 6, 8) != beyond + 6)
      {
        ++last_frame_.runs_culled;
        continue;
      }
      // The coarsest level whose error spans at most kLevelOfDetailPixels at the run's nearest point.
      int first = run.first, count = run.count;
      if (!camera.depth && nearest > camera.near)
        for (const LevelOfDetail& level : run.levels)
          if (level.error <= max_error && level.error * std::max(camera.fx, camera.fy) <= kLevelOfDetailPixels * nearest)
          {
            first = level.first;
            count = level.count;
          }
      visible.push_back(VisibleRun{&mesh, &run, first, count, d, nearest});
      ++last_frame_.runs_drawn;
      last_frame_.vertices_drawn += count;
      last_frame_.vertices_in_runs += run.count;
    }
  }
  std::stable_sort(visible.begin(), visible.end(),
                   [](const VisibleRun& a, const VisibleRun& b) { return a.nearest < b.nearest; });
  return visible;
}

void GlRenderer::drawDepths(const std::vector<VisibleRun>& runs)
{
  size_t bound = size_t(-1);
  for (const VisibleRun& v : runs)
  {
    if (v.run->transparent)
      continue;
    if (v.draw != bound)
    {
      bound = v.draw;
      glUniformMatrix4fv(light_clip_from_body_, 1, GL_FALSE, draw_matrices_[v.draw].clip_from_body);
      glBindVertexArray(v.mesh->vertex_array);
    }
    glDrawArrays(GL_TRIANGLES, v.first, v.count);
  }
  glBindVertexArray(0);
}

namespace
{
// A specular share below a level of the image: left out (its shader variant costs a frame more
// than it shows).
constexpr float kSpecularFloor = 1.0f / 255.0f;
}  // namespace

void GlRenderer::selectLights(const Draw& d)
{
  frame_.lights.clear();
  std::fill(std::begin(frame_.lights_of_kind), std::end(frame_.lights_of_kind), 0);
  const Lighting& lighting = *frame_.lighting;
  float specular = lighting.has_sun ? std::max({lighting.sun.specular[0], lighting.sun.specular[1],
                                                lighting.sun.specular[2]})
                                    : 0.0f;
  if (!lighting.lights.empty())
  {
    // the mesh's bounding sphere in the world
    const Mesh& mesh = meshes_.at(size_t(d.mesh));
    const double centre[3] = {(mesh.lo[0] + mesh.hi[0]) / 2, (mesh.lo[1] + mesh.hi[1]) / 2, (mesh.lo[2] + mesh.hi[2]) / 2};
    const double radius = 0.5 * std::hypot(mesh.hi[0] - mesh.lo[0], mesh.hi[1] - mesh.lo[1], mesh.hi[2] - mesh.lo[2]);
    double at[3];
    d.world_from_body.apply(centre, at);
    std::vector<std::pair<double, int>> reach;
    for (size_t i = 0; i < lighting.lights.size(); ++i)
    {
      const Lighting::Light& l = lighting.lights[i];
      double distance = 0;  // a directional light: first, as OGRE sorts them
      if (l.kind != Lighting::Light::Directional)
      {
        distance = std::hypot(l.position[0] - at[0], l.position[1] - at[1], l.position[2] - at[2]);
        if (!(distance - radius <= l.attenuation[0]))  // out of range (or a mesh with no bounds)
          continue;
      }
      reach.emplace_back(distance, int(i));
    }
    std::stable_sort(reach.begin(), reach.end());
    const size_t room = Lighting::kMaxLights - (lighting.has_sun ? 1 : 0);
    reach.resize(std::min(reach.size(), room));
    // the shader's order: directional lights, point lights, spots (nearest first in each)
    std::stable_sort(reach.begin(), reach.end(), [&](const std::pair<double, int>& a, const std::pair<double, int>& b) {
      return lighting.lights[size_t(a.second)].kind < lighting.lights[size_t(b.second)].kind;
    });
    for (const auto& r : reach)
    {
      const Lighting::Light& l = lighting.lights[size_t(r.second)];
      frame_.lights.push_back(r.second);
      ++frame_.lights_of_kind[l.kind];
      // a lamp's specular at its brightest, 1 / constant (its attenuation's largest value)
      const float strongest = l.kind == Lighting::Light::Directional ? 1.0f : 1.0f / std::max(l.attenuation[1], 1e-3f);
      specular = std::max(specular, strongest * std::max({l.specular[0], l.specular[1], l.specular[2]}));
    }
  }
  frame_.draw = ++draws_made_;
  // remembered for drawRuns: the largest specular colour a surface of this draw can meet
  frame_.strongest_specular = specular;
}

void GlRenderer::drawRuns(const Draw& d, const std::vector<const VisibleRun*>& visible, bool transparent)
{
  const Mesh& mesh = meshes_.at(size_t(d.mesh));
  if (std::none_of(visible.begin(), visible.end(), [&](const VisibleRun* v) { return v->run->transparent == transparent; }))
    return;
  selectLights(d);
  const Lighting& lighting = *frame_.lighting;
  const Frame& pose = *frame_.pose;
  glBindVertexArray(mesh.vertex_array);
  for (const VisibleRun* v : visible)
  {
    const Run& run = *v->run;
    if (run.transparent != transparent)
      continue;
    const bool specular = run.specular && frame_.strongest_specular * run.max_specular >= kSpecularFloor;
    ProgramKey key;
    key.variant = (frame_.static_shadows ? kStaticShadows : 0) | (frame_.moving_shadows ? kMovingShadows : 0) |
                  (frame_.lights.empty() ? 0 : kLights) | (specular ? kSpecular : 0) | (run.texture ? kTextured : 0);
    key.directional = frame_.lights_of_kind[Lighting::Light::Directional];
    key.point = frame_.lights_of_kind[Lighting::Light::Point];
    key.spot = frame_.lights_of_kind[Lighting::Light::Spot];
    CameraProgram& program = cameraProgram(key);
    if (frame_.program != &program)
    {
      glUseProgram(program.program);
      frame_.program = &program;
    }
    if (program.frame != frame_.frame)  // the frame's uniforms
    {
      program.frame = frame_.frame;
      program.lights.assign(1, -1);  // none given yet
      const float forward[3] = {float(pose.R[0]), float(pose.R[3]), float(pose.R[6])};
      glUniform3f(program.camera_origin, float(pose.t[0]), float(pose.t[1]), float(pose.t[2]));
      glUniform3fv(program.camera_forward, 1, forward);
      const float towards[3] = {float(lighting.towards_light[0]), float(lighting.towards_light[1]),
                                float(lighting.towards_light[2])};
      const float none[3] = {0, 0, 0};
      glUniform3fv(program.towards_sun, 1, lighting.has_sun ? towards : none);
      glUniform3fv(program.sun_diffuse, 1, lighting.has_sun ? lighting.sun.diffuse : none);
      glUniform3fv(program.sun_specular, 1, lighting.has_sun ? lighting.sun.specular : none);
      glUniform3fv(program.scene_ambient, 1, lighting.ambient);
      glUniform1i(program.image, 0);
      if (frame_.static_shadows)
      {
        glUniform1i(program.static_shadow, 1);
        glUniformMatrix4fv(program.static_shadow_from_world, 1, GL_FALSE, static_shadow_.texture_from_world);
      }
      if (frame_.moving_shadows)
      {
        glUniform1i(program.moving_shadow, 2);
        glUniformMatrix4fv(program.moving_shadow_from_world, 1, GL_FALSE, moving_shadow_.texture_from_world);
      }
    }
    if (program.draw != frame_.draw)  // the draw's
    {
      program.draw = frame_.draw;
      glUniformMatrix4fv(program.clip_from_body, 1, GL_FALSE, draw_matrices_[v->draw].clip_from_body);
      glUniformMatrix4fv(program.world_from_body, 1, GL_FALSE, draw_matrices_[v->draw].world_from_body);
      if ((key.variant & kLights) && program.lights != frame_.lights)
      {
        program.lights = frame_.lights;
        std::vector<float> position, direction, diffuse, specular_colour, attenuation, spot;
        for (int i : frame_.lights)
        {
          const Lighting::Light& l = lighting.lights[size_t(i)];
          position.insert(position.end(), l.position, l.position + 3);
          direction.insert(direction.end(), l.direction, l.direction + 3);
          diffuse.insert(diffuse.end(), l.diffuse, l.diffuse + 3);
          specular_colour.insert(specular_colour.end(), l.specular, l.specular + 3);
          attenuation.insert(attenuation.end(), l.attenuation, l.attenuation + 4);
          spot.insert(spot.end(), l.spot, l.spot + 3);
        }
        const GLsizei n = GLsizei(frame_.lights.size());
        glUniform3fv(program.light_position, n, position.data());
        glUniform3fv(program.light_direction, n, direction.data());
        glUniform3fv(program.light_diffuse, n, diffuse.data());
        glUniform3fv(program.light_specular, n, specular_colour.data());
        glUniform4fv(program.light_attenuation, n, attenuation.data());
        glUniform3fv(program.light_spot, n, spot.data());
      }
    }
    if (run.texture)
      glBindTexture(GL_TEXTURE_2D, run.texture);
    glDrawArrays(GL_TRIANGLES, v->first, v->count);
  }
}

void GlRenderer::render(const std::vector<Draw>& snapshot, const Frame& pose, const PinholeCamera& camera,
                        const Lighting& lighting, PinholeImage& out)
{
  // A frame in flight on a worker may name a mesh removed since its snapshot (its slot empty, or
  // holding a mesh added since): it is left out (its bounds would spoil the shadow map's fit).
  std::vector<Draw> draws;
  draws.reserve(snapshot.size());
  for (const Draw& d : snapshot)
  {
    const Mesh& mesh = meshes_.at(size_t(d.mesh));
    if (mesh.vertex_array && mesh.generation == d.generation)
      draws.push_back(d);
  }
  context_.makeCurrent();
  if (lighting.shadows)
    drawShadowMaps(draws, lighting);
  const Target& frame = target(camera.width, camera.height, camera.bits == 16 && norm16_);
  glBindFramebuffer(GL_FRAMEBUFFER, frame.framebuffer);
  glViewport(0, 0, camera.width, camera.height);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  // Back faces culled, as OGRE renders Gazebo's cameras: a camera inside its own link's box sees out.
  // A face counter-clockwise seen from outside is clockwise in the window: clipFromBody puts the
  // image's top row at the window's bottom.
  glEnable(GL_CULL_FACE);
  glCullFace(GL_BACK);
  glFrontFace(GL_CW);
  glDisable(GL_DITHER);
  const float background[4] = {lighting.background[0], lighting.background[1], lighting.background[2], 1.0f};
  const float no_depth[4] = {std::numeric_limits<float>::infinity(), 0, 0, 0};
  // a colour camera's frame writes no depths
  const GLenum buffers[2] = {GL_COLOR_ATTACHMENT0, GLenum(camera.depth ? GL_COLOR_ATTACHMENT1 : GL_NONE)};
  glDrawBuffers(2, buffers);
  glClearBufferfv(GL_COLOR, 0, background);
  if (camera.depth)
    glClearBufferfv(GL_COLOR, 1, no_depth);
  const float farthest = 1.0f;
  glClearBufferfv(GL_DEPTH, 0, &farthest);
  frame_ = FrameState();
  frame_.lighting = &lighting;
  frame_.pose = &pose;
  frame_.static_shadows = lighting.shadows && static_shadow_.used;
  frame_.moving_shadows = lighting.shadows && moving_shadow_.used;
  frame_.frame = ++frames_drawn_;
  if (frame_.static_shadows)
  {
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, static_shadow_.texture);
  }
  if (frame_.moving_shadows)
  {
    glActiveTexture(GL_TEXTURE2);
    glBindTexture(GL_TEXTURE_2D, moving_shadow_.texture);
  }
  glActiveTexture(GL_TEXTURE0);
  // What the camera may see, nearest first: the depth test then spares the shading of what lies
  // behind (a shelf's books behind its front). A level of detail lies within its error of the
  // surface the shadow maps hold: with shadows, no further than half their bias, or it would shadow
  // itself. With lamps, whose per-pixel sum is a frame's main cost, the depths are drawn first and
  // each pixel is shaded once.
  const std::vector<VisibleRun> visible =
      visibleRuns(draws, pose, camera, frame_.static_shadows || frame_.moving_shadows ? kShadowBias / 2 : HUGE_VAL);
  std::vector<std::vector<const VisibleRun*>> by_draw(draws.size());
  for (const VisibleRun& v : visible)
    by_draw[v.draw].push_back(&v);
  const bool lamps = std::any_of(lighting.lights.begin(), lighting.lights.end(),
                                 [](const Lighting::Light& l) { return l.kind != Lighting::Light::Directional; });
  if (lamps)
  {
    glUseProgram(shadow_program_);  // depth only
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    drawDepths(visible);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthFunc(GL_LEQUAL);  // the same depths again: invariant gl_Position in both programs
    glDepthMask(GL_FALSE);
  }
  bool any_transparent = false;
  for (size_t d = 0; d < draws.size(); ++d)
  {
    const Mesh& mesh = meshes_.at(size_t(draws[d].mesh));
    any_transparent = any_transparent || mesh.any_transparent;
    drawRuns(draws[d], by_draw[d], false);
  }
  glDepthMask(GL_TRUE);
  glDepthFunc(GL_LESS);
  if (any_transparent)
  {
    // OGRE's transparent_alpha blending: after the opaque surfaces, farthest first (by the mesh's
    // centre), writing no depth; the depth image keeps what lies behind.
    std::vector<std::pair<double, size_t>> order;
    for (size_t k = 0; k < draws.size(); ++k)
    {
      const Draw& d = draws[k];
      const Mesh& mesh = meshes_.at(size_t(d.mesh));
      if (!mesh.any_transparent)
        continue;
      const double centre[3] = {(mesh.lo[0] + mesh.hi[0]) / 2, (mesh.lo[1] + mesh.hi[1]) / 2, (mesh.lo[2] + mesh.hi[2]) / 2};
      double at[3];
      d.world_from_body.apply(centre, at);
      order.emplace_back(-std::hypot(at[0] - pose.t[0], at[1] - pose.t[1], at[2] - pose.t[2]), k);
    }
    std::stable_sort(order.begin(), order.end(),
                     [](const std::pair<double, size_t>& a, const std::pair<double, size_t>& b) {
                       return a.first < b.first;
                     });
    const GLenum colour_only[2] = {GL_COLOR_ATTACHMENT0, GL_NONE};
    glDrawBuffers(2, colour_only);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glDepthMask(GL_FALSE);
    for (const auto& o : order)
    {
      // farthest first within the draw too
      std::vector<const VisibleRun*> back_to_front(by_draw[o.second].rbegin(), by_draw[o.second].rend());
      drawRuns(draws[o.second], back_to_front, true);
    }
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
  }
  glBindVertexArray(0);
  glActiveTexture(GL_TEXTURE0);
  // Read back: the rows come in the image's order (clipFromBody).
  const size_t pixels = size_t(camera.width) * size_t(camera.height);
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  if (frame.sixteen_bit)
  {
    colour16_pixels_.resize(pixels * 4);
    glReadPixels(0, 0, camera.width, camera.height, GL_RGBA, GL_UNSIGNED_SHORT, colour16_pixels_.data());
  }
  else
  {
    colour_pixels_.resize(pixels * 4);
    glReadPixels(0, 0, camera.width, camera.height, GL_RGBA, GL_UNSIGNED_BYTE, colour_pixels_.data());
  }
  out.depth.resize(camera.depth ? pixels : 0);
  if (camera.depth)
  {
    glReadBuffer(GL_COLOR_ATTACHMENT1);
    GLint format = 0, type = 0;
    glGetIntegerv(GL_IMPLEMENTATION_COLOR_READ_FORMAT, &format);
    glGetIntegerv(GL_IMPLEMENTATION_COLOR_READ_TYPE, &type);
    if (format == GL_RED && type == GL_FLOAT)
      glReadPixels(0, 0, camera.width, camera.height, GL_RED, GL_FLOAT, out.depth.data());
    else  // ES 3 reads a float buffer as RGBA: the depth and three unused floats
    {
      depth_pixels_.resize(pixels * 4);
      glReadPixels(0, 0, camera.width, camera.height, GL_RGBA, GL_FLOAT, depth_pixels_.data());
      for (size_t k = 0; k < pixels; ++k)
        out.depth[k] = depth_pixels_[4 * k];
    }
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  context_.release();
  out.rgb8.resize(pixels * 3);
  if (camera.bits != 16)
  {
    out.rgb16.clear();
    noisyRgbFromRgba(camera, colour_pixels_.data(), out.rgb8.data());
    return;
  }
  if (!frame.sixteen_bit)  // a GL without 16-bit targets: the 8-bit levels spread over 16 bits
  {
    colour16_pixels_.resize(pixels * 4);
    spreadTo16Bits(colour_pixels_.data(), pixels * 4, colour16_pixels_.data());
  }
  out.rgb16.resize(pixels * 3);
  noisyRgb16FromRgba16(camera, colour16_pixels_.data(), out.rgb16.data());
  rgb8FromRgb16(out.rgb16.data(), out.rgb8.data(), pixels * 3);
}

}  // namespace bullet_plant
