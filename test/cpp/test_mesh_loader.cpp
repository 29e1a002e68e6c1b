// mesh_loader.cpp: STL (ASCII, binary), Collada (unit, up axis) and OBJ through Assimp, at a scale,
// with the sub-meshes' colours, cached per (file, scale), and failures with their reasons.
#include <gtest/gtest.h>

#include <filesystem>

#include <cmath>
#include <string>

#include <stb/stb_image_write.h>

#include "mesh_fixtures.h"
#include "description/mesh_loader.h"

using namespace bullet_plant;
using namespace mesh_fixtures;

namespace
{
const urdf::Vector3 kUnit(1, 1, 1);

std::shared_ptr<const MeshData> load(const std::string& file, const urdf::Vector3& scale = kUnit)
{
  std::string reason;
  std::shared_ptr<const MeshData> mesh = loadMesh(file, scale, reason);
  EXPECT_TRUE(mesh) << file << ": " << reason;
  return mesh;
}

void expectBounds(const MeshData& m, float x0, float y0, float z0, float x1, float y1, float z1)
{
  EXPECT_NEAR(m.min[0], x0, 1e-6);
  EXPECT_NEAR(m.min[1], y0, 1e-6);
  EXPECT_NEAR(m.min[2], z0, 1e-6);
  EXPECT_NEAR(m.max[0], x1, 1e-6);
  EXPECT_NEAR(m.max[1], y1, 1e-6);
  EXPECT_NEAR(m.max[2], z1, 1e-6);
}
}  // namespace

TEST(LoadMesh, ReadsAnAsciiStl)
{
  const std::string dir = tempDir();
  auto mesh = load(write(dir, "wedge.stl",
                         "solid wedge\n"
                         " facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n   vertex 2 0 0\n   vertex 0 3 0\n"
                         "  endloop\n endfacet\n"
                         " facet normal 0 -1 0\n  outer loop\n   vertex 0 0 0\n   vertex 0 0 1\n   vertex 2 0 0\n"
                         "  endloop\n endfacet\n"
                         "endsolid wedge\n"));
  ASSERT_TRUE(mesh);
  EXPECT_EQ(mesh->triangleCount(), 2);
  EXPECT_EQ(mesh->vertexCount(), 4) << "shared corners are joined";
  expectBounds(*mesh, 0, 0, 0, 2, 3, 1);
  ASSERT_EQ(mesh->submeshes.size(), 1u);
  EXPECT_FALSE(mesh->submeshes[0].has_material) << "an STL has no material of its own";
}

TEST(LoadMesh, ReadsABinaryStlAtAScale)
{
  const std::string dir = tempDir();
  const float lo[3] = {-0.1f, -0.05f, 0.0f}, hi[3] = {0.1f, 0.05f, 0.06f};
  const std::string file = binaryBoxStl(dir, "slab.stl", lo, hi);
  auto mesh = load(file);
  ASSERT_TRUE(mesh);
  EXPECT_EQ(mesh->triangleCount(), 12);
  EXPECT_EQ(mesh->vertexCount(), 8);
  expectBounds(*mesh, -0.1f, -0.05f, 0, 0.1f, 0.05f, 0.06f);

  auto scaled = load(file, urdf::Vector3(2, 3, 0.5));
  ASSERT_TRUE(scaled);
  expectBounds(*scaled, -0.2f, -0.15f, 0, 0.2f, 0.15f, 0.03f);
}

TEST(LoadMesh, LoadsAFileOncePerScaleWhileACopyIsAlive)
{
  const std::string dir = tempDir();
  const float lo[3] = {0, 0, 0}, hi[3] = {1, 1, 1};
  const std::string file = binaryBoxStl(dir, "cube.stl", lo, hi);
  auto first = load(file);
  EXPECT_EQ(load(file).get(), first.get());
  EXPECT_NE(load(file, urdf::Vector3(2, 2, 2)).get(), first.get());
}

TEST(LoadMesh, AppliesAColladaFilesUnitAndTurnsItsYUpToZUp)
{
  const std::string dir = tempDir();
  // In centimetres, y up: the corner at y = 100 cm is 1 m above the others.
  auto y_up = load(colladaTriangle(dir, "y_up.dae", "0.01", "Y_UP", "0 0 0 100 0 0 0 100 0"));
  ASSERT_TRUE(y_up);
  EXPECT_EQ(y_up->triangleCount(), 1);
  expectBounds(*y_up, 0, 0, 0, 1, 0, 1);

  // In metres, z up: as written.
  auto z_up = load(colladaTriangle(dir, "z_up.dae", "1", "Z_UP", "0 0 0 2 0 0 0 0 3"));
  ASSERT_TRUE(z_up);
  expectBounds(*z_up, 0, 0, 0, 2, 0, 3);
}

TEST(LoadMesh, KeepsEachSubMeshsDiffuseColourAndTexture)
{
  const std::string dir = tempDir();
  auto dae = load(colladaTriangle(dir, "green.dae", "1", "Z_UP", "0 0 0 1 0 0 0 1 0", "0.1 0.8 0.2 1"));
  ASSERT_TRUE(dae);
  ASSERT_EQ(dae->submeshes.size(), 1u);
  EXPECT_TRUE(dae->submeshes[0].has_material);
  EXPECT_NEAR(dae->submeshes[0].material.diffuse.g, 0.8f, 1e-6);

  write(dir, "paint.mtl",
        "newmtl red\nKd 1 0 0\n"
        "newmtl blue\nKd 0 0 1\nmap_Kd stripes.png\n");
  auto obj = load(write(dir, "two.obj",
                        "mtllib paint.mtl\n"
                        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nv 1 1 1\n"
                        "usemtl red\nf 1 2 3\n"
                        "usemtl blue\nf 1 2 4\nf 2 5 4\n"));
  ASSERT_TRUE(obj);
  EXPECT_EQ(obj->triangleCount(), 3);
  ASSERT_EQ(obj->submeshes.size(), 2u);
  const MeshData::SubMesh& red = obj->subMeshOf(obj->submeshes[0].first_triangle);
  const MeshData::SubMesh& blue = obj->subMeshOf(obj->submeshes[1].first_triangle + 1);
  EXPECT_EQ(red.triangle_count + blue.triangle_count, 3);
  EXPECT_TRUE(red.has_material && blue.has_material);
  // The order of the sub-meshes is Assimp's; the colours go with their own triangles.
  const bool red_first = red.material.diffuse.r > 0.5f;
  const MeshData::SubMesh& one = red_first ? red : blue;
  const MeshData::SubMesh& two = red_first ? blue : red;
  EXPECT_EQ(one.triangle_count, 1);
  EXPECT_FLOAT_EQ(one.material.diffuse.r, 1.0f);
  EXPECT_EQ(two.triangle_count, 2);
  EXPECT_FLOAT_EQ(two.material.diffuse.b, 1.0f);
  EXPECT_EQ(two.texture, "stripes.png");
  EXPECT_FALSE(two.image) << "stripes.png does not exist";
  EXPECT_FALSE(two.texture_problem.empty());
}

// A Collada effect's colours as Gazebo 11's ColladaLoader takes them (common::Material's defaults
// where it gives none: ambient 0.4, diffuse 0.5, no specular), its opacity as the Collada
// specification reads <transparent> and <transparency>; an OBJ's Ka Kd Ks Ke Ns d.
TEST(LoadMesh, ReadsEachSubMeshsMaterialAsGazeboDoes)
{
  const std::string dir = tempDir();
  const std::string corners = "0 0 0 1 0 0 0 1 0";
  auto phong = load(colladaTriangleOf(dir, "phong.dae", "1", "Z_UP", corners,
                                      "<phong><emission><color>0.1 0.2 0.3 1</color></emission>"
                                      "<ambient><color>0.2 0.25 0.3 1</color></ambient>"
                                      "<diffuse><color>0.5 0.6 0.7 1</color></diffuse>"
                                      "<specular><color>0.4 0.45 0.5 1</color></specular>"
                                      "<shininess><float>30</float></shininess>"
                                      "<transparent opaque=\"A_ONE\"><color>1 1 1 0.25</color></transparent>"
                                      "<transparency><float>1</float></transparency></phong>"));
  ASSERT_TRUE(phong);
  const Material& p = phong->submeshes.at(0).material;
  EXPECT_TRUE(phong->submeshes[0].has_material);
  EXPECT_EQ(phong->submeshes[0].name, "paint");
  EXPECT_FLOAT_EQ(p.emissive.b, 0.3f);
  EXPECT_FLOAT_EQ(p.ambient.g, 0.25f);
  EXPECT_FLOAT_EQ(p.diffuse.b, 0.7f);
  EXPECT_FLOAT_EQ(p.specular.g, 0.45f);
  EXPECT_DOUBLE_EQ(p.shininess, 30);
  EXPECT_FLOAT_EQ(p.diffuse.a, 0.25f) << "A_ONE: opacity = the transparent colour's alpha x <transparency>";
  EXPECT_TRUE(p.hasSpecular() && p.transparent());

  auto lambert = load(colladaTriangleOf(dir, "lambert.dae", "1", "Z_UP", corners,
                                        "<lambert><diffuse><color>0.3 0.3 0.3 1</color></diffuse>"
                                        "<specular><color>1 1 1 1</color></specular></lambert>"));
  ASSERT_TRUE(lambert);
  const Material& l = lambert->submeshes.at(0).material;
  EXPECT_FLOAT_EQ(l.ambient.r, 0.4f) << "no <ambient>: common::Material's 0.4";
  EXPECT_FLOAT_EQ(l.specular.r, 0.0f) << "a lambert's <specular> is not read";
  EXPECT_FALSE(l.hasSpecular());
  EXPECT_FALSE(l.transparent());

  // a diffuse <texture> leaves the diffuse colour at common::Material's 0.5; the image is not beside
  // the file but in ../materials/textures/, where Gazebo looks next
  std::filesystem::create_directories(dir + "/model/meshes");
  std::filesystem::create_directories(dir + "/model/materials/textures");
  const uint8_t pixels[3] = {10, 200, 30};
  ASSERT_TRUE(stbi_write_png((dir + "/model/materials/textures/leaf.png").c_str(), 1, 1, 3, pixels, 3));
  auto textured = load(colladaTriangleOf(dir + "/model/meshes", "textured.dae", "1", "Z_UP", corners,
                                         "<phong><diffuse><texture texture=\"sampler\" texcoord=\"UVMap\"/></diffuse></phong>",
                                         "<image id=\"picture\" name=\"picture\"><init_from>leaf.png</init_from></image>"));
  ASSERT_TRUE(textured);
  const MeshData::SubMesh& t = textured->submeshes.at(0);
  EXPECT_FLOAT_EQ(t.material.diffuse.r, 0.5f);
  EXPECT_FLOAT_EQ(t.material.ambient.r, 0.4f);
  ASSERT_TRUE(t.image) << t.texture_problem;
  EXPECT_EQ(t.image->rgb[1], 200);

  // an image that is nowhere: said, naming the file
  auto missing = load(colladaTriangleOf(dir, "missing.dae", "1", "Z_UP", corners,
                                        "<phong><diffuse><texture texture=\"sampler\" texcoord=\"UVMap\"/></diffuse></phong>",
                                        "<image id=\"picture\" name=\"picture\"><init_from>nowhere.png</init_from></image>"));
  ASSERT_TRUE(missing);
  ASSERT_EQ(textureProblems(*missing).size(), 1u);
  EXPECT_NE(textureProblems(*missing)[0].find("nowhere.png"), std::string::npos) << textureProblems(*missing)[0];

  write(dir, "full.mtl", "newmtl full\nKa 0.1 0.2 0.3\nKd 0.4 0.5 0.6\nKs 0.7 0.7 0.7\nKe 0.05 0 0\nNs 25\nd 0.5\n");
  auto obj = load(write(dir, "full.obj", "mtllib full.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl full\nf 1 2 3\n"));
  ASSERT_TRUE(obj);
  const Material& o = obj->submeshes.at(0).material;
  EXPECT_FLOAT_EQ(o.ambient.b, 0.3f);
  EXPECT_FLOAT_EQ(o.diffuse.g, 0.5f);
  EXPECT_FLOAT_EQ(o.specular.r, 0.7f);
  EXPECT_FLOAT_EQ(o.emissive.r, 0.05f);
  EXPECT_DOUBLE_EQ(o.shininess, 25);
  EXPECT_FLOAT_EQ(o.diffuse.a, 0.5f);
}

TEST(LoadMesh, KeepsTextureCoordinatesAndReadsTheTextureBesideTheMesh)
{
  const std::string dir = tempDir();
  // a 2 x 1 PNG: red on the left, blue on the right
  const uint8_t pixels[6] = {255, 0, 0, 0, 0, 255};
  ASSERT_TRUE(stbi_write_png((dir + "/two.png").c_str(), 2, 1, 3, pixels, 6));
  write(dir, "tex.mtl", "newmtl picture\nKd 1 1 1\nmap_Kd two.png\n");
  // Two triangles sharing an edge whose corners have different texture coordinates on each side:
  // the corners stay apart (a seam), each with its own coordinates.
  auto mesh = load(write(dir, "seam.obj",
                         "mtllib tex.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n"
                         "vt 0 0\nvt 1 0\nvt 0 1\nvt 0.5 0.5\nvt 0.25 0.25\n"
                         "usemtl picture\nf 1/1 2/2 3/3\nf 2/4 4/2 3/5\n"));
  ASSERT_TRUE(mesh);
  ASSERT_EQ(mesh->uvs.size(), size_t(2 * mesh->vertexCount()));
  EXPECT_EQ(mesh->vertexCount(), 6) << "corners 2 and 3 twice: their coordinates differ across the edge";
  const MeshData::SubMesh& sub = mesh->submeshes[0];
  ASSERT_TRUE(sub.image) << sub.texture_problem;
  EXPECT_EQ(sub.image->width, 2);
  EXPECT_FLOAT_EQ(sub.image->at(0.25f, 0.5f).r, 1.0f) << "s < 0.5: the left texel";
  EXPECT_FLOAT_EQ(sub.image->at(0.75f, 0.5f).b, 1.0f) << "s > 0.5: the right texel";
  EXPECT_FLOAT_EQ(sub.image->at(1.25f, 0.5f).r, 1.0f) << "repeats beyond 1";
  EXPECT_FLOAT_EQ(sub.image->at(-0.25f, 0.5f).b, 1.0f) << "and below 0";
  // the first triangle's corners keep their (s, t)
  const int* corner = &mesh->indices[0];
  for (int k = 0; k < 3; ++k)
  {
    const float* p = &mesh->vertices[3 * corner[k]];
    const float* uv = &mesh->uvs[2 * corner[k]];
    EXPECT_FLOAT_EQ(uv[0], p[0]) << "corner " << k;
    EXPECT_FLOAT_EQ(uv[1], p[1]) << "corner " << k;
  }
}

TEST(LoadMesh, SaysWhyAMeshCannotBeLoaded)
{
  const std::string dir = tempDir();
  std::string reason;
  EXPECT_FALSE(loadMesh(dir + "/missing.stl", kUnit, reason));
  EXPECT_NE(reason.find("cannot be read"), std::string::npos) << reason;

  reason.clear();
  EXPECT_FALSE(loadMesh(write(dir, "points.obj", "v 0 0 0\nv 1 0 0\nl 1 2\n"), kUnit, reason));
  EXPECT_FALSE(reason.empty());

  reason.clear();
  const float lo[3] = {0, 0, 0}, hi[3] = {1, 1, 1};
  EXPECT_FALSE(loadMesh(binaryBoxStl(dir, "box.stl", lo, hi), urdf::Vector3(1, 0, 1), reason));
  EXPECT_NE(reason.find("scale"), std::string::npos) << reason;
}

TEST(Texture, WrapsACoordinateToFloorModuloTheSizeForAnySize)
{
  // Texture::wrapIndex skips the division where it can (inside the image, power-of-two sizes);
  // every path must give floor(x) mod n.
  for (int n : {1, 3, 4, 64, 100, 256, 1000})
    for (double x = -2000.25; x < 2000.0; x += 0.75)
    {
      const long floor_x = long(std::floor(x));
      const long expected = ((floor_x % n) + n) % n;
      EXPECT_EQ(Texture::wrapIndex(float(x), n), expected) << "x = " << x << ", n = " << n;
    }
  EXPECT_EQ(Texture::wrapIndex(-0.5f, 64), 63);
  EXPECT_EQ(Texture::wrapIndex(std::nanf(""), 64), 0) << "a coordinate that is not a number: the first texel";
  EXPECT_EQ(Texture::wrapIndex(1e20f, 100), 0);
}
