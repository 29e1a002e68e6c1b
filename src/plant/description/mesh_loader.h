// Mesh files as the plant simulates them: STL (ASCII and binary), Collada (.dae) and OBJ read
// through Assimp into one triangle list at a given scale, with each sub-mesh's material and
// texture for the cameras, as Gazebo 11 reads them (common/ColladaLoader.cc, OBJLoader.cc). Collada
// files come out z up in metres, as Gazebo reads them: the file's <unit> is applied and a Y_UP (or
// X_UP) file is turned so its up axis is z.
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
    // The file's material for these triangles; false: it gives none (an STL, an OBJ without a
    // .mtl), and Gazebo draws them in Material::gazeboWhite. A Collada effect's colours as
    // Gazebo's ColladaLoader takes them: its common::Material's ambient 0.4, diffuse 0.5 (a diffuse
    // <texture> leaves it so), specular and emissive 0, shininess 0 where the effect gives none,
    // <specular> and <shininess> only from phong and blinn, a constant effect's colours not at all;
    // its opacity from <transparent> and <transparency> as the Collada specification reads them
    // (Assimp's). An OBJ's Ka, Kd, Ks, Ke, Ns and d (Assimp's defaults where absent).
    bool has_material = false;
    Material material;
    std::string name;         // the material's name in the file (Assimp's: a Collada material's name, an OBJ's newmtl)
    std::string texture;      // the diffuse texture's file name as the file writes it, or ""
    // That texture: beside the mesh file, else in ../materials/textures/ (where Gazebo looks next),
    // null if none or unreadable.
    std::shared_ptr<const Texture> image;
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

// Why the textures a mesh's sub-meshes name are not drawn (not found, unreadable, no texture
// coordinates), each once: what a world's or robot's loader warns about, naming the visual.
std::vector<std::string> textureProblems(const MeshData& mesh);

// The mesh in `file` (a resolved path) scaled by `scale`, loaded once per (file, scale) while any
// copy is alive. Null with `reason` saying why (unreadable or unknown format, no triangles, a zero
// scale).
std::shared_ptr<const MeshData> loadMesh(const std::string& file, const urdf::Vector3& scale, std::string& reason);

}  // namespace bullet_plant
