// Mesh files as the plant simulates them: STL (ASCII and binary), Collada (.dae) and OBJ read
// through Assimp into one triangle list at a given scale, with each sub-mesh's diffuse colour and
// texture for the cameras. Collada files come out z up in metres, as Gazebo reads them: the file's
// <unit> is applied and a Y_UP (or X_UP) file is turned so its up axis is z.
#pragma once

#include <cmath>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "bullet_plant/geometry.h"

namespace bullet_plant
{
// A diffuse texture as 8-bit RGB, rows from the top of the image.
struct Texture
{
  int width = 0, height = 0;
  std::vector<uint8_t> rgb;
  // The texel at texture coordinates (s, t), t up from the image's bottom row as OBJ and Collada
  // give them, repeating beyond [0, 1); the nearest texel. Inline: it runs per camera ray.
  Rgba at(float s, float t) const
  {
    const int column = wrapIndex(s * float(width), width);
    const int row = wrapIndex((1.0f - t) * float(height), height);  // rows from the top, t up from the bottom
    const uint8_t* texel = &rgb[3 * (size_t(row) * size_t(width) + size_t(column))];
    constexpr float kScale = 1.0f / 255.0f;
    return {texel[0] * kScale, texel[1] * kScale, texel[2] * kScale, 1.0f};
  }
  // floor(x) mod n, the texel a repeating coordinate falls on (without libm's floor).
  static int wrapIndex(float x, int n)
  {
    if (!(std::abs(x) < 1e9f))
      return 0;
    int i = int(x);
    i -= x < float(i);
    // the cases that need no division (an integer division costs as much as the rest of a pixel):
    // inside the image, or a power-of-two size, where the mask is the modulo also below zero
    if (unsigned(i) < unsigned(n))
      return i;
    if ((n & (n - 1)) == 0)
      return i & (n - 1);
    i %= n;
    return i < 0 ? i + n : i;
  }
};

// A PNG or JPEG (stb_image), once per file while any copy is alive. Null with `reason` saying why.
std::shared_ptr<const Texture> loadTexture(const std::string& file, std::string& reason);

struct MeshData
{
  // A run of triangles drawn with one material.
  struct SubMesh
  {
    int first_triangle = 0, triangle_count = 0;
    bool has_colour = false;  // false: the file gives no diffuse colour (STL); use the visual's
    Rgba diffuse;
    std::string texture;      // the diffuse texture's file name as the file writes it, or ""
    std::shared_ptr<const Texture> image;  // that texture (relative to the mesh file), null if none or unreadable
    std::string texture_problem;           // why a named texture is not used, or ""
  };
  std::string file;
  std::vector<float> vertices;  // x y z per vertex, scaled, in metres (Bullet's btScalar is float)
  std::vector<int> indices;     // three vertex indices per triangle
  std::vector<float> uvs;       // texture coordinates s t per vertex (first channel), or empty
  std::vector<SubMesh> submeshes;
  float min[3] = {0, 0, 0}, max[3] = {0, 0, 0};  // bounds of the vertices

  int triangleCount() const { return int(indices.size() / 3); }
  int vertexCount() const { return int(vertices.size() / 3); }
  // The sub-mesh a triangle belongs to.
  const SubMesh& subMeshOf(int triangle) const;
};

// The mesh in `file` (a resolved path) scaled by `scale`, loaded once per (file, scale) while any
// copy is alive. Null with `reason` saying why (unreadable or unknown format, no triangles, a zero
// scale).
std::shared_ptr<const MeshData> loadMesh(const std::string& file, const urdf::Vector3& scale, std::string& reason);

}  // namespace bullet_plant
