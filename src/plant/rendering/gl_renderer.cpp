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

// ray_caster's CameraShading: the face the camera sees lit by the directional light over the
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
// integer pixel coordinates (window coordinates have them at + 0.5) and rows from the top.
Matrix4 clipFromBody(const Frame& pose, const Frame& world_from_body, const PinholeRays& rays)
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
  const double w = rays.width, h = rays.height, n = rays.near, f = rays.far;
  double projection[4][3] = {{2 * rays.fx / w, 0, 2 * (rays.cx + 0.5) / w - 1},
                             {0, -2 * rays.fy / h, 1 - 2 * (rays.cy + 0.5) / h},
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
  glGenFramebuffers(1, &framebuffer_);
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
  glDeleteRenderbuffers(1, &colour_);
  glDeleteRenderbuffers(1, &depth_);
  glDeleteRenderbuffers(1, &depth_buffer_);
  glDeleteFramebuffers(1, &framebuffer_);
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

void GlRenderer::resize(int width, int height)
{
  if (width == width_ && height == height_)
    return;
  width_ = width;
  height_ = height;
  glDeleteRenderbuffers(1, &colour_);
  glDeleteRenderbuffers(1, &depth_);
  glDeleteRenderbuffers(1, &depth_buffer_);
  glGenRenderbuffers(1, &colour_);
  glBindRenderbuffer(GL_RENDERBUFFER, colour_);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
  glGenRenderbuffers(1, &depth_);
  glBindRenderbuffer(GL_RENDERBUFFER, depth_);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_R32F, width, height);
  glGenRenderbuffers(1, &depth_buffer_);
  glBindRenderbuffer(GL_RENDERBUFFER, depth_buffer_);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT32F, width, height);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour_);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_RENDERBUFFER, depth_);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_buffer_);
  const GLenum buffers[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
  glDrawBuffers(2, buffers);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    throw std::runtime_error("GL camera framebuffer of " + std::to_string(width) + " x " + std::to_string(height) +
                             " is incomplete on " + context_.renderer());
}

void GlRenderer::render(const std::vector<Draw>& draws, const Frame& pose, const PinholeRays& rays,
                        const Lighting& lighting, PinholeImage& out)
{
  context_.makeCurrent();
  resize(rays.width, rays.height);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  glViewport(0, 0, rays.width, rays.height);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDisable(GL_CULL_FACE);
  glDisable(GL_DITHER);
  const float background[4] = {lighting.background[0], lighting.background[1], lighting.background[2], 1.0f};
  const float no_depth[4] = {std::numeric_limits<float>::infinity(), 0, 0, 0};
  // a colour camera's frame writes no depths
  const GLenum buffers[2] = {GL_COLOR_ATTACHMENT0, GLenum(rays.depth ? GL_COLOR_ATTACHMENT1 : GL_NONE)};
  glDrawBuffers(2, buffers);
  glClearBufferfv(GL_COLOR, 0, background);
  if (rays.depth)
    glClearBufferfv(GL_COLOR, 1, no_depth);
  const float farthest = 1.0f;
  glClearBufferfv(GL_DEPTH, 0, &farthest);
  glUseProgram(program_);
  const float forward[3] = {float(pose.R[0]), float(pose.R[3]), float(pose.R[6])};
  glUniform3f(glGetUniformLocation(program_, "camera_origin"), float(pose.t[0]), float(pose.t[1]), float(pose.t[2]));
  glUniform3fv(glGetUniformLocation(program_, "camera_forward"), 1, forward);
  glUniform3f(glGetUniformLocation(program_, "towards_light"), float(lighting.towards_light[0]),
              float(lighting.towards_light[1]), float(lighting.towards_light[2]));
  glUniform1f(glGetUniformLocation(program_, "ambient"), float(lighting.ambient));
  const GLint clip_from_body = glGetUniformLocation(program_, "clip_from_body");
  const GLint world_from_body = glGetUniformLocation(program_, "world_from_body");
  const GLint textured = glGetUniformLocation(program_, "textured");
  glUniform1i(glGetUniformLocation(program_, "image"), 0);
  glActiveTexture(GL_TEXTURE0);
  for (const Draw& d : draws)
  {
    const Mesh& mesh = meshes_.at(size_t(d.mesh));
    glUniformMatrix4fv(clip_from_body, 1, GL_FALSE, clipFromBody(pose, d.world_from_body, rays).m);
    glUniformMatrix4fv(world_from_body, 1, GL_FALSE, fromFrame(d.world_from_body).m);
    glBindVertexArray(mesh.vertex_array);
    for (const Run& run : mesh.runs)
    {
      glUniform1i(textured, run.texture != 0);
      glBindTexture(GL_TEXTURE_2D, run.texture);
      glDrawArrays(GL_TRIANGLES, run.first, run.count);
    }
  }
  glBindVertexArray(0);
  // Read back, rows from the top as the image's.
  const size_t w = size_t(rays.width), h = size_t(rays.height);
  colour_pixels_.resize(w * h * 4);
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glReadPixels(0, 0, rays.width, rays.height, GL_RGBA, GL_UNSIGNED_BYTE, colour_pixels_.data());
  size_t depth_stride = 4;  // ES 3 reads a float buffer as RGBA, or as the driver's own format
  if (rays.depth)
  {
    glReadBuffer(GL_COLOR_ATTACHMENT1);
    GLint format = 0, type = 0;
    glGetIntegerv(GL_IMPLEMENTATION_COLOR_READ_FORMAT, &format);
    glGetIntegerv(GL_IMPLEMENTATION_COLOR_READ_TYPE, &type);
    depth_stride = format == GL_RED && type == GL_FLOAT ? 1 : 4;
    depth_pixels_.resize(w * h * depth_stride);
    glReadPixels(0, 0, rays.width, rays.height, depth_stride == 1 ? GL_RED : GL_RGBA, GL_FLOAT, depth_pixels_.data());
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  context_.release();
  out.rgb8.resize(w * h * 3);
  out.depth.resize(rays.depth ? w * h : 0);
  for (size_t row = 0; row < h; ++row)  // GL's rows from the bottom, the image's from the top
  {
    const size_t from = (h - 1 - row) * w;
    const uint8_t* colour = &colour_pixels_[4 * from];
    uint8_t* rgb8 = &out.rgb8[3 * row * w];
    for (size_t column = 0; column < w; ++column)
      for (int c = 0; c < 3; ++c)
        rgb8[3 * column + size_t(c)] = colour[4 * column + size_t(c)];
    if (rays.noise)
      for (size_t column = 0; column < w; ++column)
        addPixelNoise(rays, row * w + column, rgb8 + 3 * column);
    if (rays.depth)
      for (size_t column = 0; column < w; ++column)
        out.depth[row * w + column] = depth_pixels_[depth_stride * (from + column)];
  }
}

}  // namespace bullet_plant
