#include "bullet_plant/scene.h"

#include <nlohmann/json.hpp>

#include "bullet_plant/robot.h"
#include "bullet_plant/world.h"
#include "description/mesh_loader.h"
#include "simulation/collision_shapes.h"

#include <algorithm>

namespace bullet_plant
{
namespace
{
// A visual's material as cameras see it (RayPrimitive::surfaceMaterial): its own, and for a mesh
// each of its file's named materials.
SceneVisual visualOf(const std::string& model, const std::string& link, const Shape& shape, const urdf::Pose& pose,
                     const VisualMaterial& material)
{
  SceneVisual out{model, link, shape, pose, Material(), {}};
  bool textured = false;
  out.material = material.resolve(Material::gazeboWhite(), textured);
  std::string reason;
  const std::shared_ptr<const MeshData> mesh =
      shape.kind == Shape::Kind::Mesh ? loadMesh(shape.mesh_file, shape.scale, reason) : nullptr;
  if (mesh)
    for (const MeshData::SubMesh& sub : mesh->submeshes)
    {
      if (!sub.has_material ||
          std::any_of(out.mesh_materials.begin(), out.mesh_materials.end(),
                      [&](const SceneVisual::MeshMaterial& m) { return m.name == sub.name; }))
        continue;
      SceneVisual::MeshMaterial m;
      m.name = sub.name;
      m.material = material.resolve(sub.material, textured);
      m.textured = textured && sub.image;
      out.mesh_materials.push_back(m);
    }
  return out;
}
}  // namespace

Scene sceneOf(World& world)
{
  const WorldDescription& d = world.description();
  Scene scene;
  scene.world = d.name;
  scene.background = d.background;
  scene.ambient = d.ambient;
  for (const LightDescription& light : d.lights)
    if (light.lights())
      scene.lights.push_back(light);
  scene.shadows = d.shadows;
  for (const StaticVisual& v : d.visuals)
    scene.visuals.push_back(visualOf("", v.name, v.shape, v.pose, v.material));
  const Log quiet;  // shapeFromUrdf's words are about collisions; spawning said what a visual lacks
  for (Robot* robot : world.robots())
  {
    scene.robots.push_back(robot->name());
    scene.root_links.push_back(robot->name() + "::" + robot->description().model->getRoot()->name);
    for (const RobotDescription* tree : robot->treeDescriptions())
      for (const auto& kv : tree->model->links_)
        for (size_t index = 0; index < kv.second->visual_array.size(); ++index)
        {
          const urdf::VisualSharedPtr& v = kv.second->visual_array[index];
          Shape shape;
          if (!v || !v->geometry || !shapeFromUrdf(*v->geometry, kv.first, quiet, shape) ||
              (shape.kind == Shape::Kind::Mesh && shape.mesh_file.empty()))
            continue;
          scene.visuals.push_back(visualOf(robot->name(), robot->name() + "::" + kv.first, shape, v->origin,
                                           visualMaterial(*tree, kv.first, index, *v)));
        }
  }
  return scene;
}

namespace
{
std::vector<double> rgba(const Rgba& c) { return {c.r, c.g, c.b, c.a}; }
std::vector<double> rgb(const Rgba& c) { return {c.r, c.g, c.b}; }
std::vector<double> xyz(const urdf::Vector3& v) { return {v.x, v.y, v.z}; }
nlohmann::json materialJson(const Material& m)
{
  return {{"ambient", rgba(m.ambient)}, {"diffuse", rgba(m.diffuse)}, {"specular", rgba(m.specular)},
          {"emissive", rgba(m.emissive)}, {"shininess", m.shininess}};
}
}  // namespace

std::string sceneJson(const Scene& scene)
{
  static const char* kind_names[] = {"box", "cylinder", "sphere", "plane", "mesh", "capsule", "ellipsoid"};
  nlohmann::json visuals = nlohmann::json::array();
  for (const SceneVisual& v : scene.visuals)
  {
    const Shape& s = v.shape;
    nlohmann::json out = {{"model", v.model},
                          {"link", v.link},
                          {"kind", kind_names[static_cast<int>(s.kind)]},
                          {"pose", {v.pose.position.x, v.pose.position.y, v.pose.position.z, v.pose.rotation.x,
                                    v.pose.rotation.y, v.pose.rotation.z, v.pose.rotation.w}},
                          {"colour", rgba(v.material.diffuse)},
                          {"material", materialJson(v.material)}};
    putShapeDimensions(s, [&](const char* key, const auto& value) { out[key] = value; });
    if (s.kind == Shape::Kind::Mesh)
    {
      out["mesh"] = s.mesh_file;
      out["scale"] = xyz(s.scale);
      nlohmann::json materials = nlohmann::json::array();
      for (const SceneVisual::MeshMaterial& m : v.mesh_materials)
        materials.push_back({{"name", m.name}, {"material", materialJson(m.material)}, {"textured", m.textured}});
      out["mesh_materials"] = std::move(materials);
    }
    visuals.push_back(std::move(out));
  }
  static const char* light_types[] = {"directional", "point", "spot"};
  nlohmann::json lights = nlohmann::json::array();
  for (const LightDescription& l : scene.lights)
    lights.push_back({{"name", l.name},
                      {"type", light_types[static_cast<int>(l.kind)]},
                      {"position", xyz(l.position)},
                      {"direction", xyz(l.direction)},
                      {"diffuse", rgb(l.diffuse)},
                      {"specular", rgb(l.specular)},
                      {"attenuation", {l.range, l.constant, l.linear, l.quadratic}},
                      {"spot", {l.inner_angle, l.outer_angle, l.falloff}},
                      {"cast_shadows", l.cast_shadows}});
  const nlohmann::json json = {{"world", scene.world},
                               {"background", rgba(scene.background)},
                               {"ambient", rgb(scene.ambient)},
                               {"lights", std::move(lights)},
                               {"shadows", scene.shadows},
                               {"robots", scene.robots},
                               {"root_links", scene.root_links},
                               {"visuals", std::move(visuals)}};
  return json.dump();
}

}  // namespace bullet_plant
