// Checks a graph resource name before it reaches the ROS client library, so a bad name in a URDF
// refuses that robot's spawn with a message naming its owner instead of throwing from deep inside.
#pragma once

#include <stdexcept>
#include <string>

#include <ros/names.h>

namespace bullet_plant
{
inline const std::string& requireValidRosName(const std::string& name, const std::string& owner)
{
  std::string error;
  if (!ros::names::validate(name, error))
    throw std::invalid_argument(owner + ": '" + name + "' is not a valid ROS name (" + error + ")");
  return name;
}

}  // namespace bullet_plant
