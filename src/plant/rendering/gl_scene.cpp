#include "rendering/gl_scene.h"

#include <algorithm>
#include <array>

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
  // One list of the materials, each once; the triangles in the order they are drawn in: the opaque
  // ones, then the transparent ones (drawn after all opaque surfaces), each kind grouped by texture
  // and by whether it has specular, so that a mesh is drawn in as few runs as that takes.
  GlTriangles joined;
  std::vector<size_t> part_of;  // each triangle's part: the shape it came from
  for (const GlTriangles& t : each)
  {
    std::vector<uint32_t> remap(t.materials.size());
    for (size_t k = 0; k < t.materials.size(); ++k)
    {
      const auto found = std::find(joined.materials.begin(), joined.materials.end(), t.materials[k]);
      remap[k] = uint32_t(found - joined.materials.begin());
      if (found == joined.materials.end())
        joined.materials.push_back(t.materials[k]);
    }
    const size_t n = t.material.size();
    for (size_t k = 0; k < n; ++k)
      joined.material.push_back(remap[t.material[k]]);
    part_of.insert(part_of.end(), n, &t - each.data());
    joined.xyz.insert(joined.xyz.end(), t.xyz.begin(), t.xyz.end());
    joined.normal.insert(joined.normal.end(), t.normal.begin(), t.normal.end());
    if (any_textured)
    {
      if (t.texture.empty())
      {
        joined.texture.insert(joined.texture.end(), n, nullptr);
        joined.uv.insert(joined.uv.end(), 6 * n, 0.0f);
      }
      else
      {
        joined.texture.insert(joined.texture.end(), t.texture.begin(), t.texture.end());
        joined.uv.insert(joined.uv.end(), t.uv.begin(), t.uv.end());
      }
    }
  }
  const size_t count = joined.material.size();
  std::vector<size_t> order(count);
  for (size_t k = 0; k < count; ++k)
    order[k] = k;
  std::vector<const Texture*> first_seen;  // textures in the order they come, for a stable key
  auto textureRank = [&](size_t t) -> size_t {
    if (joined.texture.empty() || !joined.texture[t])
      return 0;
    const auto found = std::find(first_seen.begin(), first_seen.end(), joined.texture[t].get());
    if (found == first_seen.end())
    {
      first_seen.push_back(joined.texture[t].get());
      return first_seen.size();
    }
    return size_t(found - first_seen.begin()) + 1;
  };
  // Each part (a primitive) stays whole, in its place: a frame culls and orders the parts one by one.
  std::vector<std::array<size_t, 5>> key(count);
  for (size_t k = 0; k < count; ++k)
  {
    const Material& m = joined.materials[joined.material[k]];
    key[k] = {part_of[k], m.transparent() ? size_t(1) : size_t(0), textureRank(k),
              m.hasSpecular() ? size_t(1) : size_t(0), joined.material[k]};
  }
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return key[a] < key[b]; });
  GlTriangles all;
  all.materials = joined.materials;
  all.material.reserve(count);
  all.xyz.reserve(joined.xyz.size());
  all.normal.reserve(joined.normal.size());
  for (size_t t : order)
  {
    if (all.material.size() > 0 && part_of[t] != part_of[order[all.material.size() - 1]])
      all.part_ends.push_back(all.material.size());
    all.material.push_back(joined.material[t]);
    all.xyz.insert(all.xyz.end(), joined.xyz.begin() + long(9 * t), joined.xyz.begin() + long(9 * t + 9));
    if (!joined.normal.empty())
      all.normal.insert(all.normal.end(), joined.normal.begin() + long(9 * t), joined.normal.begin() + long(9 * t + 9));
    if (any_textured)
    {
      all.texture.push_back(joined.texture[t]);
      all.uv.insert(all.uv.end(), joined.uv.begin() + long(6 * t), joined.uv.begin() + long(6 * t + 6));
    }
  }
  if (!all.material.empty())
    all.part_ends.push_back(all.material.size());
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
