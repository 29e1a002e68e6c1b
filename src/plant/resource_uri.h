// Files named in URDF and SDF, found as Gazebo and ROS find them: model://NAME/... through
// GAZEBO_MODEL_PATH and the gazebo_model_path exports of the packages on ROS_PACKAGE_PATH,
// package://PKG/... through ROS_PACKAGE_PATH, file://, absolute paths, and paths relative to the
// directory of the file that names them.
#pragma once

#include <string>

namespace bullet_plant
{
// The path of the file `uri` names, or "" with `reason` saying what was tried. `base_dir`: the
// directory of the URDF/SDF file that names it ("" when it came as text: then relative paths are
// relative to the working directory).
std::string resolveUri(const std::string& uri, const std::string& base_dir, std::string& reason);

}  // namespace bullet_plant
