// What a viewer draws of a world, as gzclient shows it: every visual of the world's static models,
// placed in the world, and every visual of each robot's links, in its link's frame (a viewer poses
// the links from /gazebo/link_states, which names them model::link), with the world's lights, ambient
// light and background colour, and what each visual is made of.
#pragma once

#include <string>
#include <vector>

#include "bullet_plant/geometry.h"
#include "bullet_plant/world_description.h"  // LightDescription

namespace bullet_plant
{
class World;

struct SceneVisual
{
  std::string model;  // the robot's name; "" for the world's static models
  std::string link;   // model::link (link_states' name); for the world's, model::link::visual
  Shape shape;        // a mesh with its resolved file and scale
  urdf::Pose pose;    // a robot's visual in its link's frame; the world's in the world
  // What cameras see on it (RayPrimitive::surfaceMaterial): a primitive's material; a mesh's for
  // its sub-meshes without a material of their own, and each named material of its file, with
  // whether that sub-mesh's texture shows.
  Material material;
  struct MeshMaterial
  {
    std::string name;
    Material material;
    bool textured = false;
  };
  std::vector<MeshMaterial> mesh_materials;
};

struct Scene
{
  std::string world;
  Rgba background;
  Rgba ambient;                         // <scene><ambient>
  std::vector<LightDescription> lights;  // the world's (world_description.h)
  bool shadows = true;
  std::vector<std::string> robots;      // in spawn order
  std::vector<std::string> root_links;  // each robot's root link, model::link: its pose is the model's
  std::vector<SceneVisual> visuals;     // the world's first, then each robot's
};

// The scene of `world` as it is now. A robot visual whose geometry the plant does not draw (a mesh
// file not found) is left out, as the cameras leave it out.
Scene sceneOf(World& world);

// The scene as JSON, what the node publishes on /gazebo/scene for viewers: {"world", "background"
// [r g b a], "ambient" [r g b], "lights" [{"name", "type" (directional point spot), "position"
// [x y z], "direction" [x y z] (unit, the way it shines), "diffuse" [r g b], "specular" [r g b],
// "attenuation" [range constant linear quadratic], "spot" [inner_angle outer_angle falloff],
// "cast_shadows"}], "shadows", "robots" [names], "root_links" [each robot's root link, model::link],
// "visuals" [{"model", "link", "kind" (box cylinder sphere plane mesh capsule ellipsoid), "size"
// [x y z] (box), "radius", "length" (cylinder, sphere), "normal" [x y z] (plane), "mesh" (the file),
// "scale" [x y z] (mesh), "pose" [x y z qx qy qz qw], "colour" [r g b a] (the diffuse colour),
// "material" {"ambient" "diffuse" "specular" "emissive" [r g b a], "shininess"}, "mesh_materials"
// [{"name", "material" {...}, "textured"}] (mesh)}]}.
std::string sceneJson(const Scene& scene);

}  // namespace bullet_plant
