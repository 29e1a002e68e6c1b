// What cameras see of the world, for the GL renderer: RayScene's bodies and poses (ray_caster.h)
// on the GPU (or llvmpipe). The world's static shapes form one mesh, each robot body another, each
// uploaded once; a frame only sets the bodies' poses and draws. Only the shapes cameras see
// (visuals: kSeenByCameras) are uploaded.
#pragma once

#include <memory>
#include <mutex>
#include <vector>

#include "rendering/gl_renderer.h"

namespace bullet_plant
{
class GlScene
{
public:
  GlScene(const GlContext& context, const std::vector<RayPrimitive>& world_shapes);

  // A robot body's shapes in the body frame, uploaded once; its handle for setPose.
  int addBody(const void* owner, const std::vector<RayPrimitive>& shapes);
  // Takes every body of `owner` out of the frames from now on, and frees their meshes.
  void removeOwner(const void* owner);
  void setPose(int body, const Frame& world_from_body);

  // The bodies where they are now, `hidden`'s left out (null: none): what a frame draws, rendered
  // then or later (on a FrameWorker) by render.
  std::vector<GlRenderer::Draw> snapshot(const void* hidden = nullptr) const;
  // GlRenderer::render of `draws`, from any thread: the GL is used by one at a time.
  void render(const std::vector<GlRenderer::Draw>& draws, const Frame& pose, const PinholeCamera& camera,
              const Lighting& lighting, PinholeImage& out);
  // render of the snapshot, now.
  void renderPinhole(const Frame& pose, const PinholeCamera& camera, const Lighting& lighting, PinholeImage& out,
                     const void* hidden = nullptr);
  const GlContext& context() const { return context_; }

private:
  struct Body
  {
    const void* owner;
    int mesh;  // -1: nothing cameras see, or removed
    Frame pose;
    bool moves;         // a robot's body; the world's never move
    bool casts_shadow;  // the world's planes do not
  };
  enum class Planes { Included, Excluded, Only };
  // The triangles cameras see of `shapes` (visuals), with their planes or without, or only those.
  static GlTriangles camerasView(const std::vector<RayPrimitive>& shapes, Planes planes);

  const GlContext& context_;
  std::mutex gl_;  // held while the renderer runs: uploads on the simulation's thread, frames on a worker's
  GlRenderer renderer_;
  std::vector<Body> bodies_;  // [0]: the world's static shapes but planes, [1]: its planes; robots' bodies
};

}  // namespace bullet_plant
