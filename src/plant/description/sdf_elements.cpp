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

Rgba readColour(const tinyxml2::XMLElement* visual)
{
  Rgba colour;
  const tinyxml2::XMLElement* material = visual ? visual->FirstChildElement("material") : nullptr;
  if (!material)
    return colour;
  std::string text = xml::childText(material, "diffuse", xml::childText(material, "ambient", ""));
  if (text.empty())
    return colour;
  std::vector<double> c = xml::numbers(text, 4, "<material><diffuse>");
  return {float(c[0]), float(c[1]), float(c[2]), float(c[3])};
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
