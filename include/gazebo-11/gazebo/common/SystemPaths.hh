// common::SystemPaths: where Gazebo looks for plugin libraries: GAZEBO_PLUGIN_PATH (read again at
// each call, as Gazebo reads it), then the folders added by AddPluginPaths (gazebo_ros adds the
// ROS packages' plugin_path exports); a file found in none is left to dlopen, which searches
// LD_LIBRARY_PATH and the system's folders.
#pragma once

#include <list>
#include <string>

#include "gazebo/util/system.hh"

namespace gazebo
{
namespace common
{
class GZ_COMMON_VISIBLE SystemPaths
{
public:
  static SystemPaths* Instance();

  const std::list<std::string>& GetPluginPaths();
  // Colon-separated folders, each added once.
  void AddPluginPaths(const std::string& paths);
  void ClearPluginPaths();

private:
  SystemPaths() = default;
  std::list<std::string> plugin_paths_, added_paths_;
};
}  // namespace common
}  // namespace gazebo
