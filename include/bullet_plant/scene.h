// What a viewer draws of a world, as gzclient shows it: every visual of the world's static models,
// placed in the world, and every visual of each robot's links, in its link's frame (a viewer poses
// the links from /gazebo/link_states, which names them model::link), with the world's sun, ambient
// light and background colour.
#pragma once

#include <string>
#include <vector>

#include "bullet_plant/geometry.h"

namespace bullet_plant
{
class World;

struct SceneVisual
{
  std::string model;  // the robot's name; "" for the world's static models
  std::string link;   // model::link (link_states' name); for the world's, model::link::visual
  Shape shape;        // a mesh with its resolved file and scale
  urdf::Pose pose;    // a robot's visual in its link's frame; the world's in the world
  Rgba colour;        // its material's (URDF <material><color>, SDF <material><diffuse>)
};

struct Scene
{
  std::string world;
  Rgba background;
  double ambient = 0.0;                 // the mean of <scene><ambient>'s red, green and blue
  urdf::Vector3 light_direction;        // the sun's, as it travels
  bool shadows = true;
  std::vector<std::string> robots;      // in spawn order
  std::vector<std::string> root_links;  // each robot's root link, model::link: its pose is the model's
  std::vector<SceneVisual> visuals;     // the world's first, then each robot's
};

// The scene of `world` as it is now. A robot visual whose geometry the plant does not draw (a mesh
// file not found) is left out, as the cameras leave it out.
Scene sceneOf(World& world);

// The scene as JSON, what the node publishes on /gazebo/scene for viewers: {"world", "background"
// [r g b a], "ambient", "light_direction" [x y z], "shadows", "robots" [names], "root_links" [each
// robot's root link, model::link], "visuals" [{"model",
// "link", "kind" (box cylinder sphere plane mesh), "size" [x y z] (box), "radius", "length"
// (cylinder, sphere), "normal" [x y z] (plane), "mesh" (the file), "scale" [x y z] (mesh), "pose"
// [x y z qx qy qz qw], "colour" [r g b a]}]}.
std::string sceneJson(const Scene& scene);

}  // namespace bullet_plant
