#include "resource_uri.h"

#include <cstdlib>
#include <fstream>
#include <iterator>
#include <sstream>

namespace bullet_plant
{
namespace
{
bool fileExists(const std::string& path)
{
  std::ifstream f(path);
  return f.good();
}

// package://PKG/rest -> <dir of PKG>/rest, looking for PKG/package.xml under ROS_PACKAGE_PATH.
std::string packagePath(const std::string& package)
{
  const char* env = std::getenv("ROS_PACKAGE_PATH");
  std::stringstream paths(env ? env : "");
  std::string root;
  while (std::getline(paths, root, ':'))
    for (const std::string& candidate : {root + "/" + package, root})
    {
      std::ifstream manifest(candidate + "/package.xml");
      if (!manifest)
        continue;
      std::string text((std::istreambuf_iterator<char>(manifest)), std::istreambuf_iterator<char>());
      if (text.find("<name>" + package + "</name>") != std::string::npos)
        return candidate;
    }
  return "";
}
}  // namespace

std::string resolveUri(const std::string& uri, const std::string& base_dir, std::string& reason)
{
  std::string path = uri;
  if (uri.rfind("file://", 0) == 0)
    path = uri.substr(7);
  else if (uri.rfind("package://", 0) == 0)
  {
    const std::string rest = uri.substr(10);
    const size_t slash = rest.find('/');
    const std::string package = rest.substr(0, slash);
    const std::string root = packagePath(package);
    if (root.empty())
    {
      reason = "package '" + package + "' of '" + uri + "' is not on ROS_PACKAGE_PATH";
      return "";
    }
    path = root + (slash == std::string::npos ? "" : rest.substr(slash));
  }
  else if (!uri.empty() && uri[0] != '/' && !base_dir.empty())
    path = base_dir + "/" + uri;
  if (!fileExists(path))
  {
    reason = "'" + uri + "' not found (looked at '" + path + "')";
    return "";
  }
  return path;
}

}  // namespace bullet_plant
