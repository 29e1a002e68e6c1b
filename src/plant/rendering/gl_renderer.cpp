#include "rendering/gl_renderer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>

#include <GLES3/gl3.h>

namespace bullet_plant
{
namespace
{
const char* const kVertexShader = R"(#version 300 es
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec4 colour;
layout(location = 3) in vec2 uv;
uniform mat4 clip_from_body;
uniform mat4 world_from_body;
out vec3 world_position;
out vec3 world_normal;
out vec2 texture_uv;
flat out vec4 face_colour;
void main()
{
  texture_uv = uv;
  world_position = (world_from_body * vec4(position, 1.0)).xyz;
  world_normal = mat3(world_from_body) * normal;
  face_colour = colour;
  gl_Position = clip_from_body * vec4(position, 1.0);
}
)";

// The face the camera sees lit by the directional light over the
// ambient term, rounded to bytes by the GL (the noise is added on the CPU), and the depth along
// the optical axis into a float attachment, read back only when wanted.
const char* const kFragmentShader = R"(#version 300 es
precision highp float;
in vec3 world_position;
in vec3 world_normal;
in vec2 texture_uv;
flat in vec4 face_colour;
uniform sampler2D image;
uniform bool textured;
uniform vec3 camera_origin;
uniform vec3 camera_forward;
uniform vec3 towards_light;
uniform float ambient;
layout(location = 0) out vec4 colour;
layout(location = 1) out float depth;
void main()
{
  vec3 ray = world_position - camera_origin;
  float length_n = length(world_normal);
  float facing = dot(world_normal, ray) > 0.0 ? -1.0 : 1.0;
  float diffuse = length_n > 0.0 ? max(0.0, facing * dot(world_normal, towards_light) / length_n) : 0.0;
  float lit = ambient + (1.0 - ambient) * diffuse;
  // the texture's rows from the top, its t up from the bottom (mesh_loader.h's Texture::at)
  vec3 base = textured ? texture(image, vec2(texture_uv.x, 1.0 - texture_uv.y)).rgb : face_colour.rgb;
  colour = vec4(base * lit, 1.0);
  depth = dot(ray, camera_forward);
}
)";

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
  auto colour = [&](const Rgba& c) { out.colour.insert(out.colour.end(), {c.r, c.g, c.b, c.a}); };
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
        colour(primitive.colour);
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
        colour(primitive.colour);
    }
  }
  else if (primitive.kind == Shape::Kind::Sphere || primitive.kind == Shape::Kind::Cylinder)
  {
    const double r = primitive.radius;
    // segments around: the chord's sagitta r (1 - cos(pi / n)) within the tolerance
    const int n = std::min(1024, std::max(8, int(std::ceil(M_PI / std::acos(std::max(-1.0, 1.0 - kCurvedTolerance / r))))));
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
      colour(primitive.colour);
      colour(primitive.colour);
    };
    if (primitive.kind == Shape::Kind::Sphere)
    {
      const int rings = std::max(4, n / 2);
      auto point = [&](int ring, int segment) {
        const double polar = M_PI * ring / rings, azimuth = 2 * M_PI * segment / n;
        const double x = std::sin(polar) * std::cos(azimuth), y = std::sin(polar) * std::sin(azimuth), z = std::cos(polar);
        return std::array<double, 6>{r * x, r * y, r * z, x, y, z};
      };
      for (int ring = 0; ring < rings; ++ring)
        for (int segment = 0; segment < n; ++segment)
          quad(point(ring, segment), point(ring + 1, segment), point(ring + 1, segment + 1), point(ring, segment + 1));
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
          colour(primitive.colour);
        }
      }
    }
  }
  else if (primitive.kind == Shape::Kind::Mesh && primitive.mesh)
  {
    const MeshData& mesh = *primitive.mesh;
    const bool any_textured = !mesh.uvs.empty() && std::any_of(mesh.submeshes.begin(), mesh.submeshes.end(),
                                                               [](const MeshData::SubMesh& s) { return bool(s.image); });
    for (int t = 0; t < mesh.triangleCount(); ++t)
    {
      for (int k = 0; k < 3; ++k)
      {
        const float* v = &mesh.vertices[3 * size_t(mesh.indices[3 * size_t(t) + size_t(k)])];
        vertex(v[0], v[1], v[2]);
      }
      const MeshData::SubMesh& sub = mesh.subMeshOf(t);
      colour(sub.has_colour ? sub.diffuse : primitive.colour);
      const bool textured = sub.image && !mesh.uvs.empty();
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
  const unsigned vertex = compile(GL_VERTEX_SHADER, kVertexShader), fragment = compile(GL_FRAGMENT_SHADER, kFragmentShader);
  program_ = glCreateProgram();
  glAttachShader(program_, vertex);
  glAttachShader(program_, fragment);
  glLinkProgram(program_);
  glDeleteShader(vertex);
  glDeleteShader(fragment);
  try
  {
    requireBuilt(program_, GL_LINK_STATUS, glGetProgramiv, glGetProgramInfoLog, "program does not link");
  }
  catch (const std::runtime_error&)
  {
    context_.release();
    throw;
  }
  for (const auto& u : {std::make_pair(&uniforms_.clip_from_body, "clip_from_body"),
                        std::make_pair(&uniforms_.world_from_body, "world_from_body"),
                        std::make_pair(&uniforms_.textured, "textured"), std::make_pair(&uniforms_.image, "image"),
                        std::make_pair(&uniforms_.camera_origin, "camera_origin"),
                        std::make_pair(&uniforms_.camera_forward, "camera_forward"),
                        std::make_pair(&uniforms_.towards_light, "towards_light"),
                        std::make_pair(&uniforms_.ambient, "ambient")})
    *u.first = glGetUniformLocation(program_, u.second);
  context_.release();
}

GlRenderer::~GlRenderer()
{
  context_.makeCurrent();
  for (Mesh& m : meshes_)
  {
    glDeleteVertexArrays(1, &m.vertex_array);
    glDeleteBuffers(1, &m.buffer);
  }
  for (auto& uploaded : textures_)
    glDeleteTextures(1, &uploaded.second);
  for (Target& t : targets_)
  {
    const unsigned buffers[3] = {t.colour, t.depth, t.depth_buffer};
    glDeleteRenderbuffers(3, buffers);
    glDeleteFramebuffers(1, &t.framebuffer);
  }
  glDeleteProgram(program_);
  context_.release();
}

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
      vertices.insert(vertices.end(), &triangles.colour[4 * t], &triangles.colour[4 * t] + 4);
      if (triangles.uv.empty())
        vertices.insert(vertices.end(), {0.0f, 0.0f});
      else
        vertices.insert(vertices.end(), &triangles.uv[6 * t + 2 * size_t(v)], &triangles.uv[6 * t + 2 * size_t(v)] + 2);
    }
  }
  Mesh mesh;
  for (size_t t = 0; t < count; ++t)
  {
    const unsigned texture = triangles.texture.empty() ? 0 : textureOf(triangles.texture[t]);
    if (mesh.runs.empty() || mesh.runs.back().texture != texture)
      mesh.runs.push_back(Run{int(3 * t), 0, texture});
    mesh.runs.back().count += 3;
  }
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
  glBindVertexArray(0);
  meshes_.push_back(mesh);
  context_.release();
  return int(meshes_.size()) - 1;
}

// The ray caster's sampling: the nearest texel, repeating, no mipmaps.
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
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
  textures_.emplace_back(image, id);
  return id;
}

const GlRenderer::Target& GlRenderer::target(int width, int height)
{
  for (const Target& t : targets_)
    if (t.width == width && t.height == height)
      return t;
  Target t;
  t.width = width;
  t.height = height;
  unsigned buffers[3];
  glGenRenderbuffers(3, buffers);
  t.colour = buffers[0];
  t.depth = buffers[1];
  t.depth_buffer = buffers[2];
  glBindRenderbuffer(GL_RENDERBUFFER, t.colour);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
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

void GlRenderer::render(const std::vector<Draw>& draws, const Frame& pose, const PinholeCamera& camera,
                        const Lighting& lighting, PinholeImage& out)
{
  context_.makeCurrent();
  const Target& frame = target(camera.width, camera.height);
  glBindFramebuffer(GL_FRAMEBUFFER, frame.framebuffer);
  glViewport(0, 0, camera.width, camera.height);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDisable(GL_CULL_FACE);
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
  glUseProgram(program_);
  const float forward[3] = {float(pose.R[0]), float(pose.R[3]), float(pose.R[6])};
  glUniform3f(uniforms_.camera_origin, float(pose.t[0]), float(pose.t[1]), float(pose.t[2]));
  glUniform3fv(uniforms_.camera_forward, 1, forward);
  glUniform3f(uniforms_.towards_light, float(lighting.towards_light[0]), float(lighting.towards_light[1]),
              float(lighting.towards_light[2]));
  glUniform1f(uniforms_.ambient, float(lighting.ambient));
  glUniform1i(uniforms_.image, 0);
  glActiveTexture(GL_TEXTURE0);
  for (const Draw& d : draws)
  {
    const Mesh& mesh = meshes_.at(size_t(d.mesh));
    glUniformMatrix4fv(uniforms_.clip_from_body, 1, GL_FALSE, clipFromBody(pose, d.world_from_body, camera).m);
    glUniformMatrix4fv(uniforms_.world_from_body, 1, GL_FALSE, fromFrame(d.world_from_body).m);
    glBindVertexArray(mesh.vertex_array);
    for (const Run& run : mesh.runs)
    {
      glUniform1i(uniforms_.textured, run.texture != 0);
      glBindTexture(GL_TEXTURE_2D, run.texture);
      glDrawArrays(GL_TRIANGLES, run.first, run.count);
    }
  }
  glBindVertexArray(0);
  // Read back: the rows come in the image's order (clipFromBody).
  const size_t pixels = size_t(camera.width) * size_t(camera.height);
  colour_pixels_.resize(pixels * 4);
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glReadPixels(0, 0, camera.width, camera.height, GL_RGBA, GL_UNSIGNED_BYTE, colour_pixels_.data());
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
  noisyRgbFromRgba(camera, colour_pixels_.data(), out.rgb8.data());
}

}  // namespace bullet_plant
