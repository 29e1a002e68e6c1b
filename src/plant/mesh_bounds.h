// Axis-aligned bounds of a mesh file, so a mesh collision can stand in as a box (the plant has no
// mesh collision). Reads STL (binary and ASCII) and OBJ; resolves package:// through ROS_PACKAGE_PATH.
#pragma once

#include <array>
#include <string>

namespace bullet_plant
{
struct MeshBounds
{
  std::array<double, 3> min{{0, 0, 0}}, max{{0, 0, 0}};
};

// Returns false with a reason when the file cannot be found or read.
bool readMeshBounds(const std::string& uri, MeshBounds& bounds, std::string& reason);

}  // namespace bullet_plant
