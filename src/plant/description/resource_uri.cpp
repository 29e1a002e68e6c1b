#include "description/resource_uri.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

#include <tinyxml2.h>

namespace bullet_plant
{
namespace fs = std::filesystem;

namespace
{
struct PackageDir
{
  std::string name;
  std::string dir;
  std::string model_path_export;  // <export><gazebo_ros gazebo_model_path="..."/>, as written
  std::string media_path_export;  // <export><gazebo_ros gazebo_media_path="..."/>, as written
};

std::vector<std::string> pathList(const char* variable)
{
  const char* env = std::getenv(variable);
  std::stringstream paths(env ? env : "");
  std::vector<std::string> dirs;
  std::string dir;
  while (std::getline(paths, dir, ':'))
    if (!dir.empty())
      dirs.push_back(dir);
  return dirs;
}

std::string joined(const std::vector<std::string>& items)
{
  std::string out;
  for (const std::string& item : items)
    out += (out.empty() ? "" : ":") + item;
  return out.empty() ? "(empty)" : out;
}

bool isFile(const std::string& path)
{
  std::error_code ec;
  return fs::is_regular_file(path, ec);
}

bool isDirectory(const std::string& path)
{
  std::error_code ec;
  return fs::is_directory(path, ec);
}

bool readPackage(const fs::path& dir, PackageDir& package)
{
  tinyxml2::XMLDocument doc;
  if (doc.LoadFile((dir / "package.xml").c_str()) != tinyxml2::XML_SUCCESS)
    return false;
  const tinyxml2::XMLElement* root = doc.FirstChildElement("package");
  const tinyxml2::XMLElement* name = root ? root->FirstChildElement("name") : nullptr;
  if (!name || !name->GetText())
    return false;
  package.name = name->GetText();
  package.dir = dir.string();
  const tinyxml2::XMLElement* gazebo = root->FirstChildElement("export");
  gazebo = gazebo ? gazebo->FirstChildElement("gazebo_ros") : nullptr;
  const char* model_path = gazebo ? gazebo->Attribute("gazebo_model_path") : nullptr;
  package.model_path_export = model_path ? model_path : "";
  const char* media_path = gazebo ? gazebo->Attribute("gazebo_media_path") : nullptr;
  package.media_path_export = media_path ? media_path : "";
  return true;
}

// rospack's crawl: a directory holding package.xml is a package and is not descended into;
// hidden directories and those marked CATKIN_IGNORE are skipped. The depth bound stops symlink loops.
void crawlPackages(const fs::path& dir, int depth, std::vector<PackageDir>& out)
{
  PackageDir package;
  if (readPackage(dir, package))
  {
    out.push_back(package);
    return;
  }
  std::error_code ec;
  if (depth == 0 || fs::exists(dir / "CATKIN_IGNORE", ec))
    return;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
    if (it->path().filename().string()[0] != '.' && it->is_directory(ec))
      crawlPackages(it->path(), depth - 1, out);
}

std::vector<PackageDir> packagesOnPath()
{
  std::vector<PackageDir> packages;
  for (const std::string& root : pathList("ROS_PACKAGE_PATH"))
    crawlPackages(root, 8, packages);
  return packages;
}

std::string packagePath(const std::string& name)
{
  for (const PackageDir& package : packagesOnPath())
    if (package.name == name)
      return package.dir;
  return "";
}

// gazebo_ros's rule for the export: ${prefix} is the package's directory; several paths are ':'-separated.
std::vector<std::string> exportedPaths(const PackageDir& package, std::string text)
{
  const std::string prefix = "${prefix}";
  for (size_t at = text.find(prefix); at != std::string::npos; at = text.find(prefix, at + package.dir.size()))
    text.replace(at, prefix.size(), package.dir);
  std::vector<std::string> dirs;
  std::stringstream parts(text);
  std::string dir;
  while (std::getline(parts, dir, ':'))
    if (!dir.empty())
      dirs.push_back(fs::path(dir).is_absolute() ? dir : package.dir + "/" + dir);
  return dirs;
}

// "scheme://first/rest" -> first and "/rest" (or "").
void splitAuthority(const std::string& after_scheme, std::string& first, std::string& rest)
{
  const size_t slash = after_scheme.find('/');
  first = after_scheme.substr(0, slash);
  rest = slash == std::string::npos ? "" : after_scheme.substr(slash);
}

// The variable's directories, then every package's export of that kind (as gazebo_ros's setup
// appends them).
std::vector<std::string> searchPath(const char* variable, std::string PackageDir::*exported)
{
  std::vector<std::string> dirs = pathList(variable);
  for (const PackageDir& package : packagesOnPath())
    for (const std::string& dir : exportedPaths(package, package.*exported))
      dirs.push_back(dir);
  return dirs;
}

// The first dir/name among `dirs` that `exists` says is there (a file or a directory), or "".
std::string firstIn(const std::vector<std::string>& dirs, const std::string& name, bool (*exists)(const std::string&))
{
  for (const std::string& dir : dirs)
    if (exists(dir + "/" + name))
      return dir + "/" + name;
  return "";
}
}  // namespace

std::vector<std::string> modelSearchPath()
{
  return searchPath("GAZEBO_MODEL_PATH", &PackageDir::model_path_export);
}

std::string findModelDir(const std::string& name, std::string& reason)
{
  const std::vector<std::string> search = modelSearchPath();
  const std::string found = name.empty() ? "" : firstIn(search, name, isDirectory);
  if (!found.empty())
    return found;
  reason = "model '" + name + "' is in none of GAZEBO_MODEL_PATH and the gazebo_model_path exports of the "
           "packages on ROS_PACKAGE_PATH (looked in " + joined(search) + ")";
  return "";
}

std::vector<std::string> resourceSearchPath()
{
  return searchPath("GAZEBO_RESOURCE_PATH", &PackageDir::media_path_export);
}

std::string findWorldFile(const std::string& name, std::string& reason)
{
  if (isFile(name))
    return name;
  const std::vector<std::string> search = fs::path(name).is_absolute() ? std::vector<std::string>() : resourceSearchPath();
  const std::string found = firstIn(search, name, isFile);
  if (!found.empty())
    return found;
  reason = "world file '" + name + "' not found (as given, then in GAZEBO_RESOURCE_PATH and the gazebo_media_path "
           "exports of the packages on ROS_PACKAGE_PATH: " + joined(search) + ")";
  return "";
}

std::string resolveUri(const std::string& uri, const std::string& base_dir, std::string& reason)
{
  std::string path = uri;
  if (uri.rfind("model://", 0) == 0)
  {
    // Gazebo's rule: the first model path directory where the whole of NAME/rest exists.
    const std::vector<std::string> search = modelSearchPath();
    const std::string found = firstIn(search, uri.substr(8), isFile);
    if (!found.empty())
      return found;
    reason = "'" + uri + "' is in none of GAZEBO_MODEL_PATH and the gazebo_model_path exports of the packages on "
             "ROS_PACKAGE_PATH (looked in " + joined(search) + ")";
    return "";
  }
  else if (uri.rfind("package://", 0) == 0)
  {
    std::string package, rest;
    splitAuthority(uri.substr(10), package, rest);
    const std::string root = packagePath(package);
    if (root.empty())
    {
      reason = "'" + uri + "': package '" + package + "' is not on ROS_PACKAGE_PATH (" +
               joined(pathList("ROS_PACKAGE_PATH")) + ")";
      return "";
    }
    path = root + rest;
  }
  else
  {
    if (uri.rfind("file://", 0) == 0)
      path = uri.substr(7);
    if (!path.empty() && path[0] != '/')
    {
      // Relative: beside the file that names it, then where Gazebo's FindFile looks (the working
      // directory, then GAZEBO_RESOURCE_PATH: worlds shipped as packages name their meshes
      // file://models/NAME/meshes/... under their gazebo_media_path export).
      const std::string relative = path;
      if (!base_dir.empty())
        path = base_dir + "/" + relative;
      if (!isFile(path))
      {
        std::vector<std::string> search = resourceSearchPath();
        search.insert(search.begin(), fs::current_path().string());
        const std::string found = firstIn(search, relative, isFile);
        if (!found.empty())
          return found;
        reason = "'" + uri + "' not found (looked at '" + path + "', then in the working directory, "
                 "GAZEBO_RESOURCE_PATH and the gazebo_media_path exports: " + joined(search) + ")";
        return "";
      }
    }
  }
  if (!isFile(path))
  {
    reason = "'" + uri + "' not found (looked at '" + path + "')";
    return "";
  }
  return path;
}

}  // namespace bullet_plant
