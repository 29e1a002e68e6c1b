// Pinhole frames (pinhole.h) by OpenGL ES 3 rasterization on a GlContext (gl_context.h), into an
// off-screen framebuffer: cameras rendered the way Gazebo renders them. Triangles are uploaded once
// per mesh and drawn with a pose per frame. Shading: OGRE's per-pixel lighting of each surface's
// Material under the world's lights (pinhole.h's Lighting), on the face the camera sees (flat on flat
// faces, the surface's normal on curved ones); transparent surfaces blended over the opaque ones,
// back to front by mesh; depth is the distance along the optical axis, written by the fragment shader
// into a float attachment (exact where a depth buffer is not), +inf where nothing opaque is drawn
// within the clip range.
#pragma once

#include <cmath>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "physics/spatial.h"
#include "rendering/gl_context.h"
#include "rendering/pinhole.h"
#include "rendering/ray_caster.h"  // RayPrimitive

namespace bullet_plant
{
// Triangles in their body's frame: three vertices each (x y z), each triangle with its material
// and, for a curved surface, each vertex's normal.
struct GlTriangles
{
  std::vector<float> xyz;            // 9 per triangle
  std::vector<Material> materials;   // the surfaces' materials (geometry.h)
  std::vector<uint32_t> material;    // 1 per triangle: its index in materials
  std::vector<float> normal;         // 9 per triangle: the surface's at each vertex (empty: each triangle's own)
  // A textured triangle's image (in place of its colour) and its texture coordinates (s, t) at each
  // vertex; both empty when no triangle is textured.
  std::vector<std::shared_ptr<const Texture>> texture;  // 1 per triangle, null: its colour
  std::vector<float> uv;                                 // 6 per triangle
  // Where each part (a primitive: one visual's shape) ends, in triangles, in order; a frame culls
  // and orders the parts one by one. Empty: one part.
  std::vector<size_t> part_ends;
};

// A primitive's triangles in the frame it is placed in (its frame applied), each with the material
// and texture cameras see on it (RayPrimitive::surfaceMaterial). Boxes and meshes exactly, each triangle with its own
// normal; a plane as the lidars' square (planeTriangles); spheres and cylinders tessellated finely
// enough that no facet lies more than kCurvedTolerance from the surface (with at most
// kMaxCurvedSegments around), with the surface's normals at the vertices.
constexpr double kCurvedTolerance = 2e-5;  // m: 1 mm in depth even where a ray grazes the surface
constexpr int kMaxCurvedSegments = 256;     // around a curved shape at the most (radii above 0.27 m)
GlTriangles glTrianglesOf(const RayPrimitive& primitive);

// A coarser version of some triangles (meshoptimizer's simplifier): its vertices in the mesh's
// buffer and the most any point of it lies from the original surface.
struct LevelOfDetail
{
  int first = 0, count = 0;  // vertices
  float error = 0;           // m
};
// The geometric error a colour frame tolerates, in pixels at the nearest point of what is drawn:
// beneath it a coarser level looks the same (depth frames always get every triangle).
constexpr double kLevelOfDetailPixels = 0.5;

class GlRenderer
{
public:
  // Compiles its program on `context` (made current here and whenever it draws); throws
  // std::runtime_error with the GL's log if it cannot (no float colour attachments: a driver too old).
  explicit GlRenderer(const GlContext& context);
  ~GlRenderer();
  GlRenderer(const GlRenderer&) = delete;
  GlRenderer& operator=(const GlRenderer&) = delete;

  // Uploads a mesh once; its handle for draws.
  int addMesh(const GlTriangles& triangles);
  // Frees a mesh's GL storage (its robot was deleted). Its slot is taken by a later addMesh; a draw of
  // it from a frame snapshotted before draws nothing (meshGeneration tells the two apart).
  void removeMesh(int mesh);
  // Which of the meshes its slot held `mesh` is: slots are taken again once freed, so a draw made
  // before a removal (a frame in flight) tells its mesh from the slot's next one.
  unsigned meshGeneration(int mesh) const { return meshes_.at(size_t(mesh)).generation; }

  struct Draw
  {
    int mesh;
    Frame world_from_body;
    bool moves = true;         // false: where it was last frame (the static shadow map is kept)
    bool casts_shadow = true;  // false: only receives shadows (a ground plane)
    unsigned generation = 0;   // the mesh's (meshGeneration) when the draw was made
  };
  // The frame of `camera` at `pose` (x forward, y left, z up; the optical frame is z forward, x
  // right, y down): rgb8 rounded by the GL, then the camera's noise (noisyRgbFromRgba), or for a
  // 16-bit camera rgb16 so (noisyRgb16FromRgba16) and rgb8 from it (on a GL without 16-bit
  // colour targets, rgb16 is the 8-bit frame's levels times 257); depth in
  // metres when camera.depth, else none. With lighting.shadows, the draws that cast shadows do so
  // from the directional light: two shadow maps, the static draws' (drawn again only when they or
  // the light change) and the moving ones' (every frame, fitted to them).
  void render(const std::vector<Draw>& draws, const Frame& pose, const PinholeCamera& camera, const Lighting& lighting,
              PinholeImage& out);
  // What the last frame drew: its runs (a part of a mesh in one texture) within the view frustum and
  // those left out, and the vertices drawn (fewer than the runs' own where levels of detail stood in).
  struct FrameStats
  {
    int runs_drawn = 0, runs_culled = 0;
    long vertices_drawn = 0, vertices_in_runs = 0;
  };
  const FrameStats& lastFrame() const { return last_frame_; }

private:
  // Consecutive vertices of one part (GlTriangles::part_ends) drawn with one texture (0: none), one
  // kind (opaque or transparent) and with specular or without, their materials their own.
  struct Run
  {
    int first = 0, count = 0;
    unsigned texture = 0;
    bool transparent = false;  // its materials are
    bool specular = false;     // its materials have specular, at most this strong
    float max_specular = 0;
    float lo[3] = {HUGE_VALF, HUGE_VALF, HUGE_VALF}, hi[3] = {-HUGE_VALF, -HUGE_VALF, -HUGE_VALF};  // bounds, body frame
    std::vector<LevelOfDetail> levels;  // coarser and coarser
  };
  struct Mesh
  {
    unsigned vertex_array = 0, buffer = 0, material_buffer = 0;
    int vertex_count = 0;  // the triangles as given (the levels of detail follow them in the buffers)
    std::vector<Run> runs;
    bool any_transparent = false;
    double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};  // bounds, body frame
    unsigned generation = 0;  // how many meshes this slot has held: a draw of an earlier one is stale
  };
  struct ShadowMap  // depth from the light, compared on lookup (sampler2DShadow)
  {
    int size = 0;
    unsigned texture = 0, framebuffer = 0;
    bool used = false;                 // it holds casters
    float texture_from_world[16] = {};  // column major: x, y, depth in [0, 1]
    std::vector<double> key;            // the light and the casters' meshes and poses it holds
  };
  // Gazebo's shadow texture size for the world; a robot's map is fitted to the robots (a 0.5 m car
  // at 1 mm a texel), and drawing it costs a frame of its size whenever a robot moves.
  static constexpr int kStaticShadowMapSize = 2048;
  static constexpr int kMovingShadowMapSize = 512;
  // Draws the casters of `draws` that move (or not) into `map`; false when there are none.
  bool drawShadowMap(ShadowMap& map, const std::vector<Draw>& draws, bool moving, const Lighting& lighting);
  void drawShadowMaps(const std::vector<Draw>& draws, const Lighting& lighting);
  // An off-screen framebuffer of one size and colour depth: a world's cameras of different sizes (or
  // 8- and 16-bit ones) each draw into their own, made once (renderbuffer storage is allocated and
  // cleared by the driver).
  struct Target
  {
    int width = 0, height = 0;
    bool sixteen_bit = false;  // colours in 16 bits a channel (GL_EXT_texture_norm16), else 8
    unsigned framebuffer = 0, colour = 0, depth = 0, depth_buffer = 0;
  };
  // A run the camera may see (its bounds within the view frustum), and its draw's matrices.
  struct VisibleRun
  {
    const Mesh* mesh;
    const Run* run;
    int first, count;  // the vertices drawn: the run's or one of its levels of detail
    size_t draw;       // into draw_matrices_
    double nearest;   // the least depth along the optical axis of its bounds' corners
  };
  struct DrawMatrices
  {
    float clip_from_body[16], world_from_body[16];  // column major
  };
  // The runs of `draws` whose bounds reach into the camera's view frustum (near and far clip
  // planes included), nearest first, each at the coarsest level of detail whose error is at most
  // `max_error` (m) and spans at most kLevelOfDetailPixels; fills draw_matrices_.
  std::vector<VisibleRun> visibleRuns(const std::vector<Draw>& draws, const Frame& pose, const PinholeCamera& camera,
                                      double max_error);
  // The opaque runs' depths alone, with the shadow program bound (the depth pre-pass).
  void drawDepths(const std::vector<VisibleRun>& runs);
  unsigned textureOf(const std::shared_ptr<const Texture>& image);
  const Target& target(int width, int height, bool sixteen_bit);

  const GlContext& context_;
  struct CameraProgram  // a variant of the camera's program and its uniforms' locations
  {
    unsigned program = 0;
    int clip_from_body, world_from_body, scene_ambient, image, camera_origin, camera_forward, towards_sun, sun_diffuse;
    int sun_specular;
    int static_shadow_from_world, moving_shadow_from_world, static_shadow, moving_shadow;  // -1: not in it
    int light_position, light_direction, light_diffuse, light_specular, light_attenuation, light_spot;
    // what of this frame it has been given: the frame's uniforms, the draw's, the lights it holds
    unsigned frame = 0, draw = 0;
    std::vector<int> lights;
  };
  // Variants of the program, compiled when first used: a frame without shadows, lamps or specular
  // pays nothing for them, and the lights a draw sums are counted by kind in the program itself.
  enum Variant { kStaticShadows = 1, kMovingShadows = 2, kLights = 4, kSpecular = 8, kTextured = 16 };
  struct ProgramKey
  {
    int variant = 0;                           // Variant flags
    int directional = 0, point = 0, spot = 0;  // the draw's lights of each kind
    bool operator<(const ProgramKey& o) const
    {
      return std::tie(variant, directional, point, spot) < std::tie(o.variant, o.directional, o.point, o.spot);
    }
  };
  std::map<ProgramKey, CameraProgram> camera_programs_;
  CameraProgram& cameraProgram(const ProgramKey& key);
  // What a frame's draws share while it is drawn (render).
  struct FrameState
  {
    const Lighting* lighting = nullptr;
    const Frame* pose = nullptr;
    bool static_shadows = false, moving_shadows = false;
    unsigned frame = 0, draw = 0;
    std::vector<int> lights;                 // the draw's: indices in lighting->lights
    int lights_of_kind[3] = {0, 0, 0};       // how many of them are of each Lighting::Light::Kind
    float strongest_specular = 0;            // the largest specular light the draw's surfaces can meet
    const CameraProgram* program = nullptr;  // the program in use
  };
  FrameState frame_;
  unsigned frames_drawn_ = 0, draws_made_ = 0;
  // The lights that reach a draw (its mesh's bounds in the world), nearest first, at most
  // Lighting::kMaxLights with the sun.
  void selectLights(const Draw& d);
  // Draws a draw's visible opaque runs (or its transparent ones), each with its material and the
  // program variant it needs.
  void drawRuns(const Draw& d, const std::vector<const VisibleRun*>& visible, bool transparent);
  unsigned shadow_program_ = 0;
  int light_clip_from_body_ = -1;  // the shadow program's
  ShadowMap static_shadow_, moving_shadow_;
  std::vector<Target> targets_;
  std::vector<Mesh> meshes_;
  std::vector<std::pair<std::shared_ptr<const Texture>, unsigned>> textures_;  // uploaded once each
  std::vector<DrawMatrices> draw_matrices_;  // a frame's, one per draw
  FrameStats last_frame_;
  std::vector<uint8_t> colour_pixels_;  // read back: r g b a per pixel
  std::vector<uint16_t> colour16_pixels_;  // a 16-bit target's, read back
  bool norm16_ = false;  // the GL renders into 16-bit colours (GL_EXT_texture_norm16)
  std::vector<float> depth_pixels_;     // read back as RGBA where the driver reads no single float channel
};

}  // namespace bullet_plant
