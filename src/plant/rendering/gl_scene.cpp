#include "rendering/gl_scene.h"

#include <algorithm>

namespace bullet_plant
{
GlTriangles GlScene::camerasView(const std::vector<RayPrimitive>& shapes, Planes planes)
{
  std::vector<GlTriangles> each;
  bool any_textured = false;
  for (const RayPrimitive& p : shapes)
    if ((p.seen_by & kSeenByCameras) && (planes == Planes::Included || (p.kind == Shape::Kind::Plane) == (planes == Planes::Only)))
    {
      each.push_back(glTrianglesOf(p));
      any_textured = any_textured || !each.back().texture.empty();
    }
  GlTriangles all;
  for (const GlTriangles& t : each)
  {
    if (any_textured)
    {
      const size_t n = t.colour.size() / 4;
      if (t.texture.empty())
      {
        all.texture.insert(all.texture.end(), n, nullptr);
        all.uv.insert(all.uv.end(), 6 * n, 0.0f);
      }
      else
      {
        all.texture.insert(all.texture.end(), t.texture.begin(), t.texture.end());
        all.uv.insert(all.uv.end(), t.uv.begin(), t.uv.end());
      }
    }
    all.xyz.insert(all.xyz.end(), t.xyz.begin(), t.xyz.end());
    all.part_ends.push_back(all.xyz.size() / 9);
    all.colour.insert(all.colour.end(), t.colour.begin(), t.colour.end());
    all.normal.insert(all.normal.end(), t.normal.begin(), t.normal.end());
  }
  return all;
}

GlScene::GlScene(const GlContext& context, const std::vector<RayPrimitive>& world_shapes)
  : context_(context), renderer_(context)
{
  // The world's planes receive shadows and cast none (nothing is below them); its other shapes cast.
  const GlTriangles world = camerasView(world_shapes, Planes::Excluded), planes = camerasView(world_shapes, Planes::Only);
  bodies_.push_back(Body{nullptr, world.xyz.empty() ? -1 : renderer_.addMesh(world), Frame(), false, true});
  bodies_.push_back(Body{nullptr, planes.xyz.empty() ? -1 : renderer_.addMesh(planes), Frame(), false, false});
}

int GlScene::addBody(const void* owner, const std::vector<RayPrimitive>& shapes)
{
  const GlTriangles body = camerasView(shapes, Planes::Included);
  std::lock_guard<std::mutex> lock(gl_);
  const Body added{owner, body.xyz.empty() ? -1 : renderer_.addMesh(body), Frame(), true, true};
  // A removed body's slot is taken again: a world that spawns and deletes models all day keeps its size.
  auto slot = std::find_if(bodies_.begin(), bodies_.end(), [](const Body& b) { return b.moves && !b.owner; });
  if (slot == bodies_.end())
    slot = bodies_.insert(slot, added);
  else
    *slot = added;
  return int(slot - bodies_.begin());
}

void GlScene::removeOwner(const void* owner)
{
  std::lock_guard<std::mutex> lock(gl_);  // a worker may be drawing
  for (Body& b : bodies_)
    if (b.owner == owner && owner)
    {
      if (b.mesh >= 0)
        renderer_.removeMesh(b.mesh);
      b.mesh = -1;
      b.owner = nullptr;  // the slot is free
    }
}

void GlScene::setPose(int body, const Frame& world_from_body) { bodies_.at(size_t(body)).pose = world_from_body; }

std::vector<GlRenderer::Draw> GlScene::snapshot(const void* hidden) const
{
  std::vector<GlRenderer::Draw> draws;
  for (const Body& b : bodies_)
    if (b.mesh >= 0 && !(hidden && b.owner == hidden))
      draws.push_back(GlRenderer::Draw{b.mesh, b.pose, b.moves, b.casts_shadow, renderer_.meshGeneration(b.mesh)});
  return draws;
}

void GlScene::render(const std::vector<GlRenderer::Draw>& draws, const Frame& pose, const PinholeCamera& camera,
                     const Lighting& lighting, PinholeImage& out)
{
  std::lock_guard<std::mutex> lock(gl_);
  renderer_.render(draws, pose, camera, lighting, out);
}

void GlScene::renderPinhole(const Frame& pose, const PinholeCamera& camera, const Lighting& lighting, PinholeImage& out,
                            const void* hidden)
{
  render(snapshot(hidden), pose, camera, lighting, out);
}

}  // namespace bullet_plant
