#include "mesh_bounds.h"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>
#include <vector>


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
std::string resolve(const std::string& uri)
{
  if (uri.rfind("file://", 0) == 0)
    return uri.substr(7);
  if (uri.rfind("package://", 0) != 0)
    return uri;
  std::string rest = uri.substr(10);
  size_t slash = rest.find('/');
  std::string package = rest.substr(0, slash), tail = slash == std::string::npos ? "" : rest.substr(slash);
  const char* env = std::getenv("ROS_PACKAGE_PATH");
  std::stringstream paths(env ? env : "");
  std::string root;
  while (std::getline(paths, root, ':'))
  {
    for (const std::string& candidate : {root + "/" + package, root})
    {
      std::ifstream manifest(candidate + "/package.xml");
      if (!manifest)
        continue;
      std::string text((std::istreambuf_iterator<char>(manifest)), std::istreambuf_iterator<char>());
      if (text.find("<name>" + package + "</name>") != std::string::npos)
        return candidate + tail;
    }
  }
  return "";
}

void grow(MeshBounds& b, bool& first, double x, double y, double z)
{
  double p[3] = {x, y, z};
  for (int i = 0; i < 3; ++i)
  {
    b.min[i] = first ? p[i] : std::min(b.min[i], p[i]);
    b.max[i] = first ? p[i] : std::max(b.max[i], p[i]);
  }
  first = false;
}

bool readStl(const std::string& path, MeshBounds& b, bool& first)
{
  std::ifstream f(path, std::ios::binary);
  std::vector<char> data((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  if (data.size() >= 84)
  {
    uint32_t count;
    std::memcpy(&count, &data[80], 4);
    if (data.size() == 84 + size_t(count) * 50)
    {
      for (uint32_t t = 0; t < count; ++t)
        for (int v = 0; v < 3; ++v)
        {
          float xyz[3];
          std::memcpy(xyz, &data[84 + t * 50 + 12 + v * 12], 12);
          grow(b, first, xyz[0], xyz[1], xyz[2]);
        }
      return !first;
    }
  }
  std::istringstream text(std::string(data.begin(), data.end()));
  std::string word;
  while (text >> word)
    if (word == "vertex")
    {
      double x, y, z;
      if (text >> x >> y >> z)
        grow(b, first, x, y, z);
    }
  return !first;
}

bool readObj(const std::string& path, MeshBounds& b, bool& first)
{
  std::ifstream f(path);
  std::string line;
  while (std::getline(f, line))
    if (line.rfind("v ", 0) == 0)
    {
      std::istringstream in(line.substr(2));
      double x, y, z;
      if (in >> x >> y >> z)
        grow(b, first, x, y, z);
    }
  return !first;
}
}  // namespace

bool readMeshBounds(const std::string& uri, MeshBounds& bounds, std::string& reason)
{
  std::string path = resolve(uri);
  if (path.empty() || !fileExists(path))
  {
    reason = "cannot find '" + uri + "'";
    return false;
  }
  std::string lower = path;
  std::transform(lower.begin(), lower.end(), lower.begin(), ::tolower);
  bool first = true;
  bool ok = false;
  if (lower.size() > 4 && lower.compare(lower.size() - 4, 4, ".stl") == 0)
    ok = readStl(path, bounds, first);
  else if (lower.size() > 4 && lower.compare(lower.size() - 4, 4, ".obj") == 0)
    ok = readObj(path, bounds, first);
  else
  {
    reason = "cannot read the format of '" + uri + "' (STL and OBJ are read)";
    return false;
  }
  if (!ok)
    reason = "found no vertices in '" + uri + "'";
  return ok;
}

}  // namespace bullet_plant
