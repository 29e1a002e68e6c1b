// The physics library's free functions a plugin calls: get_world, as Gazebo 11's. The others
// (load, init, create_world, run_world ...) start a simulation of Gazebo's own: the plant starts
// its worlds itself (docs/gazebo_api.md).
#pragma once

#include <string>

#include "gazebo/physics/PhysicsTypes.hh"
#include "gazebo/util/system.hh"

namespace gazebo
{
namespace physics
{
// The running world of that name, or the first one where `name` is empty; for none, a gzerr and a
// common::Exception, as Gazebo's.
GZ_PHYSICS_VISIBLE WorldPtr get_world(const std::string& name = "");
}  // namespace physics
}  // namespace gazebo
