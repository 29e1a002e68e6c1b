// An SDF <model> (1.4 to 1.7, as sdformat 9 and Gazebo 11 read it) as the plant simulates it: the
// same RobotDescription a URDF gives, so that a model from a world file, from spawn_model -sdf or
// from a URDF is one kind of thing to the world, gazebo_ros and the viewer.
//
// Links keep their SDF frames. What URDF cannot say is carried beside its tree: the model frame
// and joint frames apart from their child link (RobotDescription::frame_links), joint springs,
// bounce, SDF collision names. Nested models are scoped as Gazebo scopes them ("outer::link").
#pragma once

#include <string>

#include "bullet_plant/robot_description.h"

namespace bullet_plant
{
// A model and where its parent (the world, spawn_model) puts its model frame.
struct ModelDescription
{
  std::string name;
  urdf::Pose pose;
  RobotDescription robot;
};

// Reads the first <model> of SDF text (<sdf><model>, or a bare <model>; a <world>'s first model).
// Throws DescriptionError naming the model, the element and the value for what cannot be simulated:
// a mass that is not positive, an inertia that is not positive definite, a joint naming a link the
// model lacks, an axis of zero length, an unknown joint type, a link name given twice, joints that
// close a loop. `base_dir`: the directory relative URIs resolve against.
ModelDescription parseSdfModel(const std::string& sdf_xml, const std::string& base_dir = "");

// URDF (<robot>) or SDF (<sdf>, <model>), told by the root element, as gazebo_ros's spawn services
// take either: the description and, for SDF, the model's own name and pose.
ModelDescription parseModelXml(const std::string& xml, const std::string& base_dir = "");

}  // namespace bullet_plant
