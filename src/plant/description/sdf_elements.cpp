#include "description/sdf_elements.h"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "bullet_plant/log.h"
#include "description/resource_uri.h"
#include "description/xml_util.h"

namespace bullet_plant
{
namespace sdf
{
void parseXml(tinyxml2::XMLDocument& doc, const std::string& text, const Source& source)
{
  if (doc.Parse(text.c_str(), text.size()) != tinyxml2::XML_SUCCESS)
    throw DescriptionError("SDF " + source.describe() + " is not well-formed XML: line " +
                           std::to_string(doc.ErrorLineNum()) + ": " + doc.ErrorStr());
}

std::string readFile(const std::string& path, const std::string& what)
{
  std::ifstream in(path);
  if (!in)
    throw DescriptionError("cannot read " + what + " '" + path + "'");
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string directoryOf(const std::string& path) { return std::filesystem::absolute(path).parent_path().string(); }

bool isTrue(const std::string& text) { return text == "true" || text == "1"; }

bool readFlag(const tinyxml2::XMLElement* parent, const char* tag, bool fallback, const std::string& where)
{
  const tinyxml2::XMLElement* e = parent ? parent->FirstChildElement(tag) : nullptr;
  if (!e)
    return fallback;
  const std::string text = xml::trimmed(e->GetText() ? e->GetText() : "");
  std::string lower = text;
  for (char& c : lower)
    c = char(std::tolower(static_cast<unsigned char>(c)));
  if (lower == "true" || lower == "1")
    return true;
  if (lower == "false" || lower == "0")
    return false;
  throw DescriptionError(where + ": <" + tag + "> '" + text + "' is not a boolean: give true or false (1 or 0)");
}

namespace
{
bool readMesh(const tinyxml2::XMLElement* mesh, const std::string& where, const Source& source, Shape& shape,
              std::vector<std::string>& warnings, const std::string& left_out)
{
  shape.kind = Shape::Kind::Mesh;
  shape.mesh_uri = xml::childText(mesh, "uri", "");
  std::vector<double> scale = xml::numbers(xml::childText(mesh, "scale", "1 1 1"), 3, where + " <mesh><scale>");
  shape.scale = urdf::Vector3(scale[0], scale[1], scale[2]);
  std::string reason;
  shape.mesh_file = resolveUri(shape.mesh_uri, source.dir, reason);
  if (shape.mesh_file.empty())
    warnings.push_back(where + " in " + source.describe() + ": <mesh> " + reason + "; " + left_out);
  return !shape.mesh_file.empty();
}
}  // namespace

bool readGeometry(const tinyxml2::XMLElement* geometry, const std::string& where, const Source& source, Shape& shape,
                  std::vector<std::string>& warnings, const std::string& left_out)
{
  if (auto* box = geometry->FirstChildElement("box"))
  {
    shape.kind = Shape::Kind::Box;
    std::vector<double> size = xml::numbers(xml::childText(box, "size", "1 1 1"), 3, where + " <box><size>");
    for (int i = 0; i < 3; ++i)
    {
      if (!(size[i] > 0 && size[i] <= kMaxLength))
        throw DescriptionError(where + ": <box><size> " + xml::childText(box, "size", "") +
                               ": box sizes must be positive and at most " + formatNumber(kMaxLength) + " m");
      shape.box_size[i] = size[i];
    }
  }
  else if (auto* cylinder = geometry->FirstChildElement("cylinder"))
  {
    shape.kind = Shape::Kind::Cylinder;
    shape.radius = xml::childDouble(cylinder, "radius", 1.0);
    shape.length = xml::childDouble(cylinder, "length", 1.0);
    if (!(shape.radius > 0 && shape.length > 0 && shape.radius <= kMaxLength && shape.length <= kMaxLength))
      throw DescriptionError(where + ": <cylinder> radius " + formatNumber(shape.radius) + " length " +
                             formatNumber(shape.length) + ": both must be positive and at most " +
                             formatNumber(kMaxLength) + " m");
  }
  else if (auto* sphere = geometry->FirstChildElement("sphere"))
  {
    shape.kind = Shape::Kind::Sphere;
    shape.radius = xml::childDouble(sphere, "radius", 1.0);
    if (!(shape.radius > 0 && shape.radius <= kMaxLength))
      throw DescriptionError(where + ": <sphere><radius> " + formatNumber(shape.radius) +
                             " must be positive and at most " + formatNumber(kMaxLength) + " m");
  }
  else if (auto* capsule = geometry->FirstChildElement("capsule"))
  {
    // SDF 1.8's (sdformat 11); defaults radius 0.5, length 1.
    shape.kind = Shape::Kind::Capsule;
    auto size = [&](const char* tag, double fallback) {
      const std::string text = xml::childText(capsule, tag, "");
      return text.empty() ? fallback : xml::numbers(text, 1, where + ": <capsule><" + tag + ">")[0];
    };
    shape.radius = size("radius", 0.5);
    shape.length = size("length", 1.0);
    if (!(shape.radius > 0 && shape.length >= 0 && shape.radius <= kMaxLength && shape.length <= kMaxLength))
      throw DescriptionError(where + ": <capsule> radius " + formatNumber(shape.radius) + " length " +
                             formatNumber(shape.length) + ": the radius must be positive, the length at least 0, "
                             "both at most " + formatNumber(kMaxLength) + " m");
  }
  else if (auto* ellipsoid = geometry->FirstChildElement("ellipsoid"))
  {
    // SDF 1.8's (sdformat 11); default radii 1 1 1.
    shape.kind = Shape::Kind::Ellipsoid;
    const std::string text = xml::childText(ellipsoid, "radii", "1 1 1");
    std::vector<double> radii = xml::numbers(text, 3, where + " <ellipsoid><radii>");
    for (int i = 0; i < 3; ++i)
    {
      if (!(radii[i] > 0 && radii[i] <= kMaxLength))
        throw DescriptionError(where + ": <ellipsoid><radii> " + xml::trimmed(text) +
                               ": each radius must be positive and at most " + formatNumber(kMaxLength) + " m");
      shape.radii[i] = radii[i];
    }
  }
  else if (auto* plane = geometry->FirstChildElement("plane"))
  {
    shape.kind = Shape::Kind::Plane;
    std::vector<double> n = xml::numbers(xml::childText(plane, "normal", "0 0 1"), 3, where + " <plane><normal>");
    double norm = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (!(norm >= 1e-9 && std::isfinite(norm)))
      throw DescriptionError(where + ": <plane><normal> must be a finite vector that is not zero");
    shape.normal = urdf::Vector3(n[0] / norm, n[1] / norm, n[2] / norm);
  }
  else if (auto* mesh = geometry->FirstChildElement("mesh"))
    return readMesh(mesh, where, source, shape, warnings, left_out);
  else
  {
    const tinyxml2::XMLElement* first = geometry->FirstChildElement();
    warnings.push_back(where + " in " + source.describe() + ": geometry <" + std::string(first ? first->Name() : "") +
                       "> is not supported (box, cylinder, sphere, capsule, ellipsoid, plane, mesh); " + left_out);
    return false;
  }
  return true;
}

namespace
{
// gazebo.material's materials that are colours alone (no texture, no shader), as each draws: a
// pass's `ambient`, `diffuse`, `specular r g b [a] shininess` and `emissive`; where a material has
// two passes the second draws over the first (Gazebo/White: OGRE's default white ambient, diffuse
// 1, specular 0.1 at 128). The *Transparent ones' alpha comes from their texture unit's alpha_op;
// RedTransparent is unlit (lighting off): its red is drawn as is.
struct GazeboMaterial
{
  const char* name;
  float ambient[3], diffuse[4], specular[3], shininess, emissive[3];
};
const GazeboMaterial kGazeboMaterials[] = {
    {"Gazebo/Grey", {.3f, .3f, .3f}, {.7f, .7f, .7f, 1}, {.01f, .01f, .01f}, 1.5f, {0, 0, 0}},
    {"Gazebo/DarkGrey", {.175f, .175f, .175f}, {.175f, .175f, .175f, 1}, {.175f, .175f, .175f}, 1.5f, {0, 0, 0}},
    {"Gazebo/White", {1, 1, 1}, {1, 1, 1, 1}, {.1f, .1f, .1f}, 128, {0, 0, 0}},
    {"Gazebo/FlatBlack", {.1f, .1f, .1f}, {.1f, .1f, .1f, 1}, {.01f, .01f, .01f}, 1, {0, 0, 0}},
    {"Gazebo/Black", {0, 0, 0}, {0, 0, 0, 1}, {.1f, .1f, .1f}, 5, {0, 0, 0}},
    {"Gazebo/Red", {1, 0, 0}, {1, 0, 0, 1}, {.1f, .1f, .1f}, 1, {0, 0, 0}},
    {"Gazebo/RedBright", {.87f, .26f, .07f}, {.87f, .26f, .07f, 1}, {.87f, .26f, .07f}, 1, {0, 0, 0}},
    {"Gazebo/Green", {0, 1, 0}, {0, 1, 0, 1}, {.1f, .1f, .1f}, 1, {0, 0, 0}},
    {"Gazebo/Blue", {0, 0, 1}, {0, 0, 1, 1}, {.1f, .1f, .1f}, 1, {0, 0, 0}},
    {"Gazebo/SkyBlue", {.13f, .44f, .70f}, {0, 0, 1, 1}, {.1f, .1f, .1f}, 1, {0, 0, 0}},
    {"Gazebo/Yellow", {1, 1, 0}, {1, 1, 0, 1}, {0, 0, 0}, 0, {0, 0, 0}},
    {"Gazebo/ZincYellow", {.9725f, .9529f, .2078f}, {.9725f, .9529f, .2078f, 1}, {.9725f, .9529f, .2078f}, 1, {0, 0, 0}},
    {"Gazebo/Purple", {1, 0, 1}, {1, 0, 1, 1}, {.1f, .1f, .1f}, 1, {0, 0, 0}},
    {"Gazebo/Turquoise", {0, 1, 1}, {0, 1, 1, 1}, {.1f, .1f, .1f}, 1, {0, 0, 0}},
    {"Gazebo/Orange", {1, .5088f, .0468f}, {1, .5088f, .0468f, 1}, {.5f, .5f, .5f}, 128, {0, 0, 0}},
    {"Gazebo/Gold", {.4f, .24869f, .020759f}, {.8f, .64869f, .120759f, 1}, {.4f, .4f, .4f}, 12.5f, {0, 0, 0}},
    {"Gazebo/Pioneer2Body", {.481193f, .000123f, .000123f}, {.681193f, .000923f, .000923f, 1}, {.5f, .5f, .5f},
     12.5f, {0, 0, 0}},
    {"Gazebo/GreyTransparent", {.5f, .5f, .5f}, {.5f, .5f, .5f, .5f}, {0, 0, 0}, 0, {0, 0, 0}},
    {"Gazebo/GreenTransparent", {0, 1, 0}, {0, 1, 0, .5f}, {0, 0, 0}, 0, {0, 0, 0}},
    {"Gazebo/BlueTransparent", {0, 0, 1}, {0, 0, 1, .5f}, {0, 0, 0}, 0, {0, 0, 0}},
    {"Gazebo/YellowTransparent", {1, 1, 0}, {1, 1, 0, .5f}, {0, 0, 0}, 0, {0, 0, 0}},
    {"Gazebo/DarkMagentaTransparent", {.6f, 0, .6f}, {.6f, 0, .6f, .5f}, {0, 0, 0}, 0, {0, 0, 0}},
    {"Gazebo/OrangeTransparent", {1, .44f, 0}, {1, .44f, 0, .4f}, {0, 0, 0}, 0, {0, 0, 0}},
    {"Gazebo/RedTransparent", {0, 0, 0}, {0, 0, 0, .5f}, {0, 0, 0}, 0, {1, 0, 0}},
};

Rgba colourOf(const tinyxml2::XMLElement* material, const char* tag, const std::string& where)
{
  const std::string text = xml::childText(material, tag, "");
  std::istringstream words(text);
  size_t count = 0;
  for (std::string word; words >> word;)
    ++count;
  const std::vector<double> c = xml::numbers(text, count == 3 ? 3 : 4, where + " <material><" + tag + ">");
  return {float(c[0]), float(c[1]), float(c[2]), c.size() == 4 ? float(c[3]) : 1.0f};
}
}  // namespace

bool gazeboMaterial(const std::string& name, Material& out)
{
  for (const GazeboMaterial& g : kGazeboMaterials)
    if (name == g.name)
    {
      out.ambient = {g.ambient[0], g.ambient[1], g.ambient[2], 1};
      out.diffuse = {g.diffuse[0], g.diffuse[1], g.diffuse[2], g.diffuse[3]};
      out.specular = {g.specular[0], g.specular[1], g.specular[2], 1};
      out.emissive = {g.emissive[0], g.emissive[1], g.emissive[2], 1};
      out.shininess = g.shininess;
      return true;
    }
  return false;
}

VisualMaterial readMaterial(const tinyxml2::XMLElement* visual, const std::string& where,
                            std::vector<std::string>& warnings)
{
  VisualMaterial out;
  if (!visual)
    return out;
  if (visual->FirstChildElement("transparency"))
    out.transparency = std::max(0.0, std::min(1.0, xml::childDouble(visual, "transparency", 0.0)));
  const tinyxml2::XMLElement* material = visual->FirstChildElement("material");
  if (!material)
    return out;
  const std::string script = xml::trimmed(xml::childText(material, "script/name", ""));
  if (!script.empty())
  {
    out.has_replace = gazeboMaterial(script, out.replace);
    if (!out.has_replace)
      warnings.push_back(where + ": <material><script> '" + script + "' is not one of gazebo.material's plain "
                         "colours the plant knows (a material script's textures and shaders are not read); the "
                         "visual keeps its own colours");
  }
  struct Given
  {
    const char* tag;
    bool* has;
    Rgba* colour;
  };
  for (const Given& g : {Given{"ambient", &out.has_ambient, &out.ambient}, Given{"diffuse", &out.has_diffuse, &out.diffuse},
                         Given{"specular", &out.has_specular, &out.specular},
                         Given{"emissive", &out.has_emissive, &out.emissive}})
    if (material->FirstChildElement(g.tag))
    {
      *g.has = true;
      *g.colour = colourOf(material, g.tag, where);
    }
  out.shininess = std::max(0.0, xml::childDouble(material, "shininess", 0.0));
  return out;
}

SurfaceDescription readSurface(const tinyxml2::XMLElement* collision, const std::string& where)
{
  SurfaceDescription s;
  const tinyxml2::XMLElement* surface = collision ? collision->FirstChildElement("surface") : nullptr;
  if (!surface)
    return s;
  s.given = true;
  s.mu1 = xml::childDouble(surface, "friction/ode/mu", s.mu1);
  s.mu2 = xml::childDouble(surface, "friction/ode/mu2", s.mu2);
  const std::string fdir1 = xml::childText(surface, "friction/ode/fdir1", "");
  if (!fdir1.empty())
  {
    const std::vector<double> d = xml::numbers(fdir1, 3, where + " <surface><friction><ode><fdir1>");
    s.fdir1 = urdf::Vector3(d[0], d[1], d[2]);
  }
  s.slip1 = xml::childDouble(surface, "friction/ode/slip1", s.slip1);
  s.slip2 = xml::childDouble(surface, "friction/ode/slip2", s.slip2);
  s.kp = xml::childDouble(surface, "contact/ode/kp", s.kp);
  s.kd = xml::childDouble(surface, "contact/ode/kd", s.kd);
  s.max_vel = xml::childDouble(surface, "contact/ode/max_vel", s.max_vel);
  s.min_depth = xml::childDouble(surface, "contact/ode/min_depth", s.min_depth);
  s.restitution = xml::childDouble(surface, "bounce/restitution_coefficient", s.restitution);
  s.restitution_threshold = xml::childDouble(surface, "bounce/threshold", s.restitution_threshold);
  return s;
}

std::string modelFile(const std::string& model_dir)
{
  tinyxml2::XMLDocument config;
  const std::string config_path = model_dir + "/model.config";
  if (config.LoadFile(config_path.c_str()) != tinyxml2::XML_SUCCESS)
  {
    if (config.ErrorID() == tinyxml2::XML_ERROR_FILE_NOT_FOUND)
      return model_dir + "/model.sdf";
    throw DescriptionError("model config '" + config_path + "' is not well-formed XML: line " +
                           std::to_string(config.ErrorLineNum()) + ": " + config.ErrorStr());
  }
  const tinyxml2::XMLElement* root = config.FirstChildElement("model");
  std::string best = "model.sdf";
  std::vector<double> best_version;
  for (auto* sdf = root ? root->FirstChildElement("sdf") : nullptr; sdf; sdf = sdf->NextSiblingElement("sdf"))
  {
    std::vector<double> version;
    std::stringstream parts(sdf->Attribute("version") ? sdf->Attribute("version") : "0");
    for (std::string part; std::getline(parts, part, '.');)
      version.push_back(std::atof(part.c_str()));
    if (sdf->GetText() && (best_version.empty() || version > best_version))
    {
      best = xml::trimmed(sdf->GetText());
      best_version = version;
    }
  }
  return model_dir + "/" + best;
}

std::string includedModelDir(const std::string& uri, const Source& source, std::string& reason)
{
  if (uri.rfind("model://", 0) == 0)
  {
    std::string name = uri.substr(8);
    while (!name.empty() && name.back() == '/')
      name.pop_back();
    return findModelDir(name, reason);
  }
  std::string dir = uri.rfind("file://", 0) == 0 ? uri.substr(7) : uri;
  if (!dir.empty() && dir[0] != '/' && !source.dir.empty())
    dir = source.dir + "/" + dir;
  std::error_code ec;
  if (std::filesystem::is_directory(dir, ec))
    return dir;
  reason = "no model directory at '" + dir + "'";
  return "";
}

Source includedSource(const std::string& model_file, const std::string& model_dir, const Source& from,
                      std::string& loop)
{
  Source source{model_file, model_dir, from.includers};
  if (!from.file.empty())
    source.includers.push_back(from.file);
  loop.clear();
  std::error_code ec;
  const std::filesystem::path canonical = std::filesystem::weakly_canonical(model_file, ec);
  for (size_t i = 0; i < source.includers.size(); ++i)
  {
    std::error_code other_ec;
    if (std::filesystem::weakly_canonical(source.includers[i], other_ec) != canonical)
      continue;
    for (size_t j = i; j < source.includers.size(); ++j)
      loop += "'" + source.includers[j] + "' -> ";
    loop += "'" + model_file + "'";
    break;
  }
  return source;
}

const tinyxml2::XMLElement* readIncludedModel(const std::string& uri, const Source& from, int depth,
                                              tinyxml2::XMLDocument& doc, Source& model_source, std::string& why)
{
  if (depth > kMaxModelDepth)
  {
    why = "models nested too deep (an include loop?)";
    return nullptr;
  }
  const std::string dir = includedModelDir(uri, from, why);
  if (dir.empty())
    return nullptr;
  std::string loop;
  model_source = includedSource(modelFile(dir), dir, from, loop);
  if (!loop.empty())
  {
    why = "an include loop (" + loop + ")";
    return nullptr;
  }
  parseXml(doc, readFile(model_source.file, "model file"), model_source);
  const tinyxml2::XMLElement* sdf = doc.FirstChildElement("sdf");
  const tinyxml2::XMLElement* model = sdf ? sdf->FirstChildElement("model") : nullptr;
  if (!model)
    why = model_source.describe() + " has no <sdf><model>";
  return model;
}

int versionOf(const tinyxml2::XMLElement* element)
{
  const tinyxml2::XMLElement* root = element ? element->GetDocument()->FirstChildElement("sdf") : nullptr;
  const char* version = root ? root->Attribute("version") : nullptr;
  if (!version)
    return 106;
  const std::string text = version;
  const size_t dot = text.find('.');
  return std::atoi(text.substr(0, dot).c_str()) * 100 + (dot == std::string::npos ? 0 : std::atoi(text.c_str() + dot + 1));
}

}  // namespace sdf
}  // namespace bullet_plant
