// Files named in URDF and SDF, found as Gazebo and ROS find them: model://NAME/... through
// GAZEBO_MODEL_PATH and the gazebo_model_path exports of the packages on ROS_PACKAGE_PATH,
// package://PKG/... through ROS_PACKAGE_PATH, file://, absolute paths, and paths relative to the
// directory of the file that names them. Only the environment is read (no ROS master, no rospack).
#pragma once

#include <string>
#include <vector>

namespace bullet_plant
{
// The path of the file `uri` names, or "" with `reason` saying what was tried. `base_dir`: the
// directory of the URDF/SDF file that names it ("" when it came as text: then relative paths are
// relative to the working directory).
std::string resolveUri(const std::string& uri, const std::string& base_dir, std::string& reason);

// The directory of Gazebo model `name` (model://name): the first directory of modelSearchPath()
// holding a directory `name`; "" with `reason` when none does. (model://name/file resolves to the
// first one holding name/file, as Gazebo's resolver does.)
std::string findModelDir(const std::string& name, std::string& reason);

// Where model:// looks, in order: GAZEBO_MODEL_PATH's entries, then the gazebo_ros
// gazebo_model_path exports (`${prefix}` = the exporting package's directory) of the packages on
// ROS_PACKAGE_PATH, as gazebo_ros's launch scripts add them.
std::vector<std::string> modelSearchPath();

// Where Gazebo looks for a world file named relatively (gazebo_ros's default `worlds/empty.world`):
// GAZEBO_RESOURCE_PATH's entries, then the gazebo_media_path exports of the packages on
// ROS_PACKAGE_PATH (gazebo_ros adds them to GAZEBO_RESOURCE_PATH).
std::vector<std::string> resourceSearchPath();

// The world file `name` names: itself when it exists (absolute, or relative to the working
// directory), else the first resourceSearchPath() directory holding it; "" with `reason` when none does.
std::string findWorldFile(const std::string& name, std::string& reason);

}  // namespace bullet_plant
