#include "description/mesh_loader.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <map>
#include <mutex>
#include <tuple>

#include <assimp/Importer.hpp>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <stb/stb_image.h>
#include <tinyxml2.h>

#include <cstdlib>
#include <filesystem>
#include <sstream>

namespace bullet_plant
{
namespace
{
bool isCollada(const std::string& file)
{
  if (file.size() < 4)
    return false;
  std::string ext = file.substr(file.size() - 4);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext == ".dae";
}

// A Collada <effect>'s colours, as Gazebo 11's ColladaLoader::LoadMaterial reads them.
const tinyxml2::XMLElement* childNamed(const tinyxml2::XMLElement* e, const char* name)
{
  return e ? e->FirstChildElement(name) : nullptr;
}

// "r g b a" of a <color>, or false.
bool readColour(const tinyxml2::XMLElement* slot, Rgba& out)
{
  const tinyxml2::XMLElement* colour = childNamed(slot, "color");
  if (!colour || !colour->GetText())
    return false;
  std::istringstream words(colour->GetText());
  float c[4] = {0, 0, 0, 1};
  int n = 0;
  while (n < 4 && words >> c[n])
    ++n;
  if (n < 3)
    return false;
  out = {c[0], c[1], c[2], c[3]};
  return true;
}

// The file's <material> elements by name (and id), each with its effect's colours: Assimp names a
// Collada material by its name attribute, else its id.
std::map<std::string, Material> colladaMaterials(const std::string& file)
{
  std::map<std::string, Material> out;
  tinyxml2::XMLDocument doc;
  if (doc.LoadFile(file.c_str()) != tinyxml2::XML_SUCCESS)
    return out;
  const tinyxml2::XMLElement* root = doc.FirstChildElement("COLLADA");
  std::map<std::string, const tinyxml2::XMLElement*> effects;
  for (auto* library = childNamed(root, "library_effects"); library;
       library = library->NextSiblingElement("library_effects"))
    for (auto* effect = library->FirstChildElement("effect"); effect; effect = effect->NextSiblingElement("effect"))
      if (effect->Attribute("id"))
        effects[effect->Attribute("id")] = effect;
  for (auto* library = childNamed(root, "library_materials"); library;
       library = library->NextSiblingElement("library_materials"))
    for (auto* material = library->FirstChildElement("material"); material;
         material = material->NextSiblingElement("material"))
    {
      const tinyxml2::XMLElement* instance = material->FirstChildElement("instance_effect");
      std::string url = instance && instance->Attribute("url") ? instance->Attribute("url") : "";
      if (!url.empty() && url[0] == '#')
        url = url.substr(1);
      const auto effect = effects.find(url);
      if (effect == effects.end())
        continue;
      // common::Material's defaults (gazebo/common/Material.cc)
      Material m;
      m.ambient = {0.4f, 0.4f, 0.4f, 1.0f};
      m.diffuse = {0.5f, 0.5f, 0.5f, 1.0f};
      const tinyxml2::XMLElement* technique = childNamed(childNamed(effect->second, "profile_COMMON"), "technique");
      const tinyxml2::XMLElement* lambert = childNamed(technique, "lambert");
      const tinyxml2::XMLElement* shaded = lambert ? lambert : childNamed(technique, "phong");
      if (!shaded)
        shaded = childNamed(technique, "blinn");
      if (shaded)
      {
        readColour(shaded->FirstChildElement("ambient"), m.ambient);
        readColour(shaded->FirstChildElement("emission"), m.emissive);
        readColour(shaded->FirstChildElement("diffuse"), m.diffuse);
        if (!lambert)
        {
          readColour(shaded->FirstChildElement("specular"), m.specular);
          const tinyxml2::XMLElement* shininess = childNamed(shaded->FirstChildElement("shininess"), "float");
          if (shininess && shininess->GetText())
            m.shininess = std::max(0.0, std::atof(shininess->GetText()));
        }
      }
      m.ambient.a = m.specular.a = m.emissive.a = 1.0f;
      m.diffuse.a = 1.0f;  // the opacity is Assimp's (subMeshFor)
      if (material->Attribute("id"))
        out[material->Attribute("id")] = m;
      if (material->Attribute("name"))
        out[material->Attribute("name")] = m;
    }
  return out;
}

MeshData::SubMesh subMeshFor(const aiMaterial* material, const std::map<std::string, Material>* collada)
{
  MeshData::SubMesh s;
  if (!material)
    return s;
  aiString name;
  material->Get(AI_MATKEY_NAME, name);
  s.name = name.C_Str();
  // Assimp gives files without materials (STL, OBJ without .mtl) its default material.
  if (std::string(name.C_Str()) != AI_DEFAULT_MATERIAL_NAME)
  {
    auto colour = [&](const char* key, unsigned type, unsigned index, Rgba& out) {
      aiColor4D c;
      if (material->Get(key, type, index, c) == AI_SUCCESS)
        out = {c.r, c.g, c.b, 1.0f};
    };
    const auto found = collada ? collada->find(name.C_Str()) : std::map<std::string, Material>::const_iterator();
    if (collada && found != collada->end())
      s.material = found->second;
    else
    {
      s.material.ambient = {0, 0, 0, 1};
      colour(AI_MATKEY_COLOR_AMBIENT, s.material.ambient);
      colour(AI_MATKEY_COLOR_DIFFUSE, s.material.diffuse);
      colour(AI_MATKEY_COLOR_SPECULAR, s.material.specular);
      colour(AI_MATKEY_COLOR_EMISSIVE, s.material.emissive);
      float shininess = 0;
      if (material->Get(AI_MATKEY_SHININESS, shininess) == AI_SUCCESS)
        s.material.shininess = std::max(0.0f, shininess);
    }
    float opacity = 1;
    if (material->Get(AI_MATKEY_OPACITY, opacity) == AI_SUCCESS)
      s.material.diffuse.a = std::max(0.0f, std::min(1.0f, opacity));
    s.has_material = true;
  }
  aiString texture;
  if (material->GetTexture(aiTextureType_DIFFUSE, 0, &texture) == AI_SUCCESS)
    s.texture = texture.C_Str();
  return s;
}

// A texture file name as a mesh file writes it, resolved as Gazebo's common::Material::SetTextureImage
// does: against the mesh file's directory, else its ../materials/textures/.
std::string texturePath(const std::string& mesh_file, std::string name)
{
  if (name.compare(0, 7, "file://") == 0)
    name = name.substr(7);
  if (!name.empty() && name[0] == '/')
    return name;
  const size_t slash = mesh_file.rfind('/');
  const std::string dir = slash == std::string::npos ? "" : mesh_file.substr(0, slash + 1);
  std::error_code ec;
  if (std::filesystem::exists(dir + name, ec) || !std::filesystem::exists(dir + "../materials/textures/" + name, ec))
    return dir + name;
  return dir + "../materials/textures/" + name;
}

// Every mesh instance of the node tree, in the scene's frame, appended to `out`.
void appendNode(const aiScene& scene, const aiNode& node, const aiMatrix4x4& parent,
                const std::map<std::string, Material>* collada, MeshData& out)
{
  const aiMatrix4x4 transform = parent * node.mTransformation;
  for (unsigned k = 0; k < node.mNumMeshes; ++k)
  {
    const aiMesh& mesh = *scene.mMeshes[node.mMeshes[k]];
    const int first_vertex = out.vertexCount();
    for (unsigned v = 0; v < mesh.mNumVertices; ++v)
    {
      const aiVector3D p = transform * mesh.mVertices[v];
      out.vertices.insert(out.vertices.end(), {p.x, p.y, p.z});
      const aiVector3D uv = mesh.HasTextureCoords(0) ? mesh.mTextureCoords[0][v] : aiVector3D(0, 0, 0);
      out.uvs.insert(out.uvs.end(), {uv.x, uv.y});
    }
    MeshData::SubMesh sub = subMeshFor(scene.mMaterials ? scene.mMaterials[mesh.mMaterialIndex] : nullptr, collada);
    if (!sub.texture.empty() && mesh.HasTextureCoords(0))
      sub.image = loadTexture(texturePath(out.file, sub.texture), sub.texture_problem);
    else if (!sub.texture.empty())
      sub.texture_problem = "texture '" + sub.texture + "' is not drawn: the mesh has no texture coordinates";
    sub.first_triangle = out.triangleCount();
    for (unsigned f = 0; f < mesh.mNumFaces; ++f)
    {
      const aiFace& face = mesh.mFaces[f];
      if (face.mNumIndices != 3)
        continue;  // points and lines: nothing to collide with
      for (int i = 0; i < 3; ++i)
        out.indices.push_back(first_vertex + int(face.mIndices[i]));
    }
    sub.triangle_count = out.triangleCount() - sub.first_triangle;
    if (sub.triangle_count > 0)
      out.submeshes.push_back(sub);
  }
  for (unsigned c = 0; c < node.mNumChildren; ++c)
    appendNode(scene, *node.mChildren[c], transform, collada, out);
}

// One vertex per position and texture coordinate: Assimp keeps a corner once per normal (an STL
// facet's, a hard edge's).
void weldVertices(MeshData& mesh)
{
  std::map<std::array<float, 5>, int> index_of;
  std::vector<int> remap(mesh.vertexCount());
  std::vector<float> welded, welded_uvs;
  for (int v = 0; v < mesh.vertexCount(); ++v)
  {
    const std::array<float, 5> p{{mesh.vertices[3 * v], mesh.vertices[3 * v + 1], mesh.vertices[3 * v + 2],
                                  mesh.uvs[2 * v], mesh.uvs[2 * v + 1]}};
    auto inserted = index_of.emplace(p, int(welded.size() / 3));
    if (inserted.second)
    {
      welded.insert(welded.end(), p.begin(), p.begin() + 3);
      welded_uvs.insert(welded_uvs.end(), p.begin() + 3, p.end());
    }
    remap[v] = inserted.first->second;
  }
  mesh.vertices.swap(welded);
  mesh.uvs.swap(welded_uvs);
  for (int& i : mesh.indices)
    i = remap[i];
}

std::shared_ptr<MeshData> readMesh(const std::string& file, const urdf::Vector3& scale, std::string& reason)
{
  Assimp::Importer importer;
  // Points and lines are dropped below.
  const aiScene* scene = importer.ReadFile(
      file, aiProcess_Triangulate | aiProcess_SortByPType);
  if (!scene || !scene->mRootNode)
  {
    reason = "cannot be read (" + std::string(importer.GetErrorString()) + ")";
    return nullptr;
  }
  auto mesh = std::make_shared<MeshData>();
  mesh->file = file;
  const std::map<std::string, Material> collada =
      isCollada(file) ? colladaMaterials(file) : std::map<std::string, Material>();
  appendNode(*scene, *scene->mRootNode, aiMatrix4x4(), isCollada(file) ? &collada : nullptr, *mesh);
  if (mesh->indices.empty())
  {
    reason = "has no triangles";
    return nullptr;
  }
  // Assimp turns every Collada file y up (its <unit> applied); Gazebo's frame is z up.
  const bool y_up = isCollada(file);
  const double s[3] = {scale.x, scale.y, scale.z};
  for (size_t v = 0; v < mesh->vertices.size(); v += 3)
  {
    float* p = &mesh->vertices[v];
    if (y_up)
    {
      const float y = p[1];
      p[1] = -p[2];
      p[2] = y;
    }
    for (int i = 0; i < 3; ++i)
    {
      p[i] = float(p[i] * s[i]);
      mesh->min[i] = v == 0 ? p[i] : std::min(mesh->min[i], p[i]);
      mesh->max[i] = v == 0 ? p[i] : std::max(mesh->max[i], p[i]);
    }
  }
  weldVertices(*mesh);
  return mesh;
}
}  // namespace

std::vector<std::string> textureProblems(const MeshData& mesh)
{
  std::vector<std::string> out;
  for (const MeshData::SubMesh& s : mesh.submeshes)
    if (!s.texture_problem.empty() && std::find(out.begin(), out.end(), s.texture_problem) == out.end())
      out.push_back(s.texture_problem);
  return out;
}

const MeshData::SubMesh& MeshData::subMeshOf(int triangle) const
{
  if (submeshes.size() == 1)  // most meshes: no search per camera ray
    return submeshes.front();
  auto after = std::upper_bound(submeshes.begin(), submeshes.end(), triangle,
                                [](int t, const SubMesh& s) { return t < s.first_triangle; });
  return *(after - 1);
}

std::shared_ptr<const Texture> loadTexture(const std::string& file, std::string& reason)
{
  static std::mutex mutex;
  static std::map<std::string, std::weak_ptr<const Texture>> cache;
  std::lock_guard<std::mutex> lock(mutex);
  if (std::shared_ptr<const Texture> loaded = cache[file].lock())
    return loaded;
  int width = 0, height = 0, channels = 0;
  unsigned char* pixels = stbi_load(file.c_str(), &width, &height, &channels, 3);
  if (!pixels)
  {
    reason = "texture '" + file + "' cannot be read (" + std::string(stbi_failure_reason()) + ")";
    return nullptr;
  }
  auto texture = std::make_shared<Texture>();
  texture->width = width;
  texture->height = height;
  texture->rgb.assign(pixels, pixels + size_t(width) * size_t(height) * 3);
  stbi_image_free(pixels);
  cache[file] = texture;
  return texture;
}

std::shared_ptr<const MeshData> loadMesh(const std::string& file, const urdf::Vector3& scale, std::string& reason)
{
  if (!(scale.x != 0 && scale.y != 0 && scale.z != 0) ||
      !std::isfinite(scale.x + scale.y + scale.z))
  {
    reason = "has a zero or non-finite scale";
    return nullptr;
  }
  using Key = std::tuple<std::string, double, double, double>;
  static std::mutex mutex;
  static std::map<Key, std::weak_ptr<const MeshData>> cache;
  const Key key(file, scale.x, scale.y, scale.z);
  std::lock_guard<std::mutex> lock(mutex);
  if (std::shared_ptr<const MeshData> loaded = cache[key].lock())
    return loaded;
  std::shared_ptr<const MeshData> mesh = readMesh(file, scale, reason);
  if (mesh)
    cache[key] = mesh;
  return mesh;
}

}  // namespace bullet_plant
