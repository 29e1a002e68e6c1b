// Where plugin libraries are looked for (gazebo/common/SystemPaths.hh).
#include "gazebo/common/SystemPaths.hh"

#include <algorithm>
#include <cstdlib>
#include <sstream>

namespace gazebo
{
namespace common
{
namespace
{
void appendFolders(const std::string& colon_separated, std::list<std::string>& paths)
{
  std::stringstream folders(colon_separated);
  std::string folder;
  while (std::getline(folders, folder, ':'))
  {
    while (folder.size() > 1 && folder.back() == '/')
      folder.pop_back();
    if (!folder.empty() && std::find(paths.begin(), paths.end(), folder) == paths.end())
      paths.push_back(folder);
  }
}
}  // namespace

SystemPaths* SystemPaths::Instance()
{
  static SystemPaths instance;
  return &instance;
}

const std::list<std::string>& SystemPaths::GetPluginPaths()
{
  plugin_paths_.clear();
  if (const char* env = std::getenv("GAZEBO_PLUGIN_PATH"))
    appendFolders(env, plugin_paths_);
  for (const std::string& folder : added_paths_)
    appendFolders(folder, plugin_paths_);
  return plugin_paths_;
}

void SystemPaths::AddPluginPaths(const std::string& paths) { appendFolders(paths, added_paths_); }

void SystemPaths::ClearPluginPaths() { added_paths_.clear(); }
}  // namespace common
}  // namespace gazebo
