// A joint made while the world runs (Gazebo's PhysicsEngine::CreateJoint, Joint::Load and Attach, as
// gripper and harness plugins make them): what it holds to what, and how.
#pragma once

#include <limits>
#include <string>

#include <urdf_model/pose.h>

namespace bullet_plant
{
struct RunTimeJoint
{
  enum class Type
  {
    Fixed,      // no relative motion
    Prismatic,  // a slide along the axis
    Revolute,   // a turn about the axis
    Ball        // any turn about the anchor
  };
  Type type = Type::Fixed;
  // `child_link` of `child_model` held to `parent_link` of `parent_model`, or to the world where
  // `parent_model` is empty, from where they are when the joint is made.
  std::string parent_model, parent_link, child_model, child_link;
  urdf::Vector3 anchor;          // the joint's origin, world coordinates
  urdf::Vector3 axis{0, 0, 1};   // prismatic and revolute: world coordinates
  // Prismatic and revolute: the travel allowed (m or rad) from where the joint is made, a damping
  // against its rate (N s/m or N m s/rad) and the most effort an effort set gives (N or N m).
  double lower = -std::numeric_limits<double>::infinity();
  double upper = std::numeric_limits<double>::infinity();
  double damping = 0.0;
  double effort_limit = std::numeric_limits<double>::infinity();
};

}  // namespace bullet_plant
