#include "bullet_plant/scene.h"

#include <nlohmann/json.hpp>

#include "bullet_plant/robot.h"
#include "bullet_plant/world.h"
#include "simulation/collision_shapes.h"

namespace bullet_plant
{
Scene sceneOf(World& world)
{
  const WorldDescription& d = world.description();
  Scene scene;
  scene.world = d.name;
  scene.background = d.background;
  scene.ambient = d.ambient;
  scene.light_direction = d.light_direction;
  scene.shadows = d.shadows;
  for (const StaticVisual& v : d.visuals)
    scene.visuals.push_back(SceneVisual{"", v.name, v.shape, v.pose, v.colour});
  const Log quiet;  // shapeFromUrdf's words are about collisions; spawning said what a visual lacks
  for (Robot* robot : world.robots())
  {
    scene.robots.push_back(robot->name());
    const urdf::ModelInterface& model = *robot->description().model;
    scene.root_links.push_back(robot->name() + "::" + model.getRoot()->name);
    for (const auto& kv : model.links_)
      for (const urdf::VisualSharedPtr& v : kv.second->visual_array)
      {
        Shape shape;
        if (!v || !v->geometry || !shapeFromUrdf(*v->geometry, kv.first, quiet, shape) ||
            (shape.kind == Shape::Kind::Mesh && shape.mesh_file.empty()))
          continue;
        Rgba colour;
        if (v->material)
          colour = {float(v->material->color.r), float(v->material->color.g), float(v->material->color.b),
                    float(v->material->color.a)};
        scene.visuals.push_back(SceneVisual{robot->name(), robot->name() + "::" + kv.first, shape, v->origin, colour});
      }
  }
  return scene;
}

namespace
{
std::vector<double> rgba(const Rgba& c) { return {c.r, c.g, c.b, c.a}; }
std::vector<double> xyz(const urdf::Vector3& v) { return {v.x, v.y, v.z}; }
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
                          {"colour", rgba(v.colour)}};
    switch (s.kind)
    {
      case Shape::Kind::Box: out["size"] = s.box_size; break;
      case Shape::Kind::Cylinder:
      case Shape::Kind::Capsule: out["length"] = s.length; [[fallthrough]];
      case Shape::Kind::Sphere: out["radius"] = s.radius; break;
      case Shape::Kind::Ellipsoid: out["radii"] = s.radii; break;
      case Shape::Kind::Plane: out["normal"] = xyz(s.normal); break;
      case Shape::Kind::Mesh:
        out["mesh"] = s.mesh_file;
        out["scale"] = xyz(s.scale);
        break;
    }
    visuals.push_back(std::move(out));
  }
  const nlohmann::json json = {{"world", scene.world},
                               {"background", rgba(scene.background)},
                               {"ambient", scene.ambient},
                               {"light_direction", xyz(scene.light_direction)},
                               {"shadows", scene.shadows},
                               {"robots", scene.robots},
                               {"root_links", scene.root_links},
                               {"visuals", std::move(visuals)}};
  return json.dump();
}

}  // namespace bullet_plant
