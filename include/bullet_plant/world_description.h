// The part of an SDF world that Gazebo's own worlds use for static scenes: <physics>, <gravity>,
// static models with box/cylinder/sphere/plane collisions, the ground_plane and sun includes.
#pragma once

#include <string>
#include <vector>

#include "bullet_plant/geometry.h"

namespace bullet_plant
{
struct StaticCollision
{
  std::string name;   // model::link::collision, as Gazebo names them
  Shape shape;
  urdf::Pose pose;    // in the world
  double mu = 1.0;    // Gazebo's default friction
  Rgba colour;        // from the matching <visual>'s material, for cameras
};

struct WorldDescription
{
  std::string name = "default";
  double max_step_size = 0.001;      // s
  double real_time_factor = 1.0;
  urdf::Vector3 gravity{0, 0, -9.8};
  urdf::Vector3 light_direction{-0.5, 0.1, -0.9};  // Gazebo's sun
  std::vector<StaticCollision> collisions;
  std::vector<std::string> warnings;
};

// Parses SDF text (<sdf><world>...). Throws DescriptionError naming what is wrong. Adds a ground
// plane when the world has none, as an empty Gazebo world has one.
WorldDescription parseWorldDescription(const std::string& sdf_xml);
// The empty world: default physics and a ground plane.
WorldDescription emptyWorldDescription();

}  // namespace bullet_plant
