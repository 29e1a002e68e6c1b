#include "bullet_plant/world_description.h"
#include "bullet_plant/log.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <tinyxml2.h>

#include "bullet_plant/log.h"
#include "bullet_plant/robot_description.h"
#include "description/resource_uri.h"
#include "description/xml_util.h"

namespace bullet_plant
{
namespace
{
// Where SDF elements come from: the file messages name, and the directory their relative URIs
// resolve against (the world file's, or the included model's).
struct Source
{
  std::string file;  // "" for SDF given as text
  std::string dir;
  std::string describe() const { return file.empty() ? "the SDF text" : "'" + file + "'"; }
};

// Where a model goes: its name (with the enclosing models' names, as Gazebo scopes them) and pose.
struct Placement
{
  std::string name;
  urdf::Pose pose;  // in the world
  bool is_static = false;
};

// Nested includes deeper than this are a loop (a model including itself).
constexpr int kMaxModelDepth = 16;
// The strongest <gravity> the plant takes, m/s^2 (100 g): beyond it the robots only diverge.
constexpr double kMaxGravity = 1000.0;

StaticCollision groundPlane(const std::string& model_name, const urdf::Pose& pose)
{
  StaticCollision ground;
  ground.name = model_name + "::link::collision";
  ground.shape.kind = Shape::Kind::Plane;
  ground.pose = pose;
  return ground;
}

// What cameras see of the ground plane: the plane itself, grey.
StaticVisual groundPlaneVisual(const StaticCollision& ground)
{
  StaticVisual visual;
  visual.name = ground.name.substr(0, ground.name.rfind("::")) + "::visual";
  visual.shape = ground.shape;
  visual.pose = ground.pose;
  visual.colour = {0.7f, 0.7f, 0.7f, 1.0f};
  return visual;
}

void addGroundPlane(const std::string& model_name, const urdf::Pose& pose, WorldDescription& world)
{
  world.collisions.push_back(groundPlane(model_name, pose));
  world.visuals.push_back(groundPlaneVisual(world.collisions.back()));
}

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

std::string directoryOf(const std::string& path)
{
  return std::filesystem::absolute(path).parent_path().string();
}

bool readMesh(const tinyxml2::XMLElement* mesh, const std::string& where, const Source& source, Shape& shape,
              WorldDescription& world, const std::string& left_out)
{
  shape.kind = Shape::Kind::Mesh;
  shape.mesh_uri = xml::childText(mesh, "uri", "");
  std::vector<double> scale = xml::numbers(xml::childText(mesh, "scale", "1 1 1"), 3, where + " <mesh><scale>");
  shape.scale = urdf::Vector3(scale[0], scale[1], scale[2]);
  std::string reason;
  shape.mesh_file = resolveUri(shape.mesh_uri, source.dir, reason);
  if (shape.mesh_file.empty())
    world.warnings.push_back(where + " in " + source.describe() + ": <mesh> " + reason + "; " + left_out);
  return !shape.mesh_file.empty();
}

// The shape of a <geometry>; false (with a warning ending in `left_out`) when the plant leaves it out.
bool readGeometry(const tinyxml2::XMLElement* geometry, const std::string& where, const Source& source, Shape& shape,
                  WorldDescription& world, const std::string& left_out = "collision left out")
{
  if (auto* box = geometry->FirstChildElement("box"))
  {
    shape.kind = Shape::Kind::Box;
    std::vector<double> size = xml::numbers(xml::childText(box, "size", "1 1 1"), 3, where + " <box><size>");
    for (int i = 0; i < 3; ++i)
    {
      if (size[i] <= 0)
        throw DescriptionError(where + ": box sizes must be positive");
      shape.box_size[i] = size[i];
    }
  }
  else if (auto* cylinder = geometry->FirstChildElement("cylinder"))
  {
    shape.kind = Shape::Kind::Cylinder;
    shape.radius = xml::childDouble(cylinder, "radius", 1.0);
    shape.length = xml::childDouble(cylinder, "length", 1.0);
    if (shape.radius <= 0 || shape.length <= 0)
      throw DescriptionError(where + ": cylinder radius and length must be positive");
  }
  else if (auto* sphere = geometry->FirstChildElement("sphere"))
  {
    shape.kind = Shape::Kind::Sphere;
    shape.radius = xml::childDouble(sphere, "radius", 1.0);
    if (shape.radius <= 0)
      throw DescriptionError(where + ": sphere radius must be positive");
  }
  else if (auto* plane = geometry->FirstChildElement("plane"))
  {
    shape.kind = Shape::Kind::Plane;
    std::vector<double> n = xml::numbers(xml::childText(plane, "normal", "0 0 1"), 3, where + " <plane><normal>");
    double norm = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (norm < 1e-9)
      throw DescriptionError(where + ": plane normal must not be zero");
    shape.normal = urdf::Vector3(n[0] / norm, n[1] / norm, n[2] / norm);
  }
  else if (auto* mesh = geometry->FirstChildElement("mesh"))
    return readMesh(mesh, where, source, shape, world, left_out);
  else
  {
    const tinyxml2::XMLElement* first = geometry->FirstChildElement();
    world.warnings.push_back(where + " in " + source.describe() + ": geometry <" +
                             std::string(first ? first->Name() : "") +
                             "> is not supported (box, cylinder, sphere, plane, mesh); " + left_out);
    return false;
  }
  return true;
}

// "r g b" or "r g b a", as SDF colours are written.
std::vector<double> colourNumbers(const std::string& text, const std::string& what)
{
  std::istringstream words(text);
  size_t count = 0;
  for (std::string word; words >> word;)
    ++count;
  return xml::numbers(text, count == 4 ? 4 : 3, what);
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

bool isTrue(const std::string& text) { return text == "true" || text == "1"; }

void readInclude(const tinyxml2::XMLElement* include, const Source& source, const std::string& scope,
                 const urdf::Pose& parent, int depth, WorldDescription& world);

void readLink(const tinyxml2::XMLElement* link, const Source& source, const Placement& model, WorldDescription& world)
{
  std::string link_name = link->Attribute("name") ? link->Attribute("name") : "link";
  urdf::Pose link_pose = compose(model.pose, xml::parseSdfPose(xml::childText(link, "pose", "")));
  for (auto* c = link->FirstChildElement("collision"); c; c = c->NextSiblingElement("collision"))
  {
    StaticCollision collision;
    collision.name = model.name + "::" + link_name + "::" + (c->Attribute("name") ? c->Attribute("name") : "collision");
    const std::string where = "collision '" + collision.name + "'";
    const tinyxml2::XMLElement* geometry = c->FirstChildElement("geometry");
    if (!geometry)
    {
      world.warnings.push_back(where + " in " + source.describe() + " has no <geometry>; left out");
      continue;
    }
    if (!readGeometry(geometry, where, source, collision.shape, world))
      continue;
    collision.pose = compose(link_pose, xml::parseSdfPose(xml::childText(c, "pose", "")));
    collision.mu = xml::childDouble(c, "surface/friction/ode/mu", 1.0);
    if (!(collision.mu >= 0))  // negative or NaN: Bullet would push along the motion
    {
      world.warnings.push_back(where + " in " + source.describe() + ": <mu> " + formatNumber(collision.mu) +
                               " is not a friction coefficient; it is taken as 0");
      collision.mu = 0;
    }
    world.collisions.push_back(collision);
  }
  for (auto* v = link->FirstChildElement("visual"); v; v = v->NextSiblingElement("visual"))
  {
    StaticVisual visual;
    visual.name = model.name + "::" + link_name + "::" + (v->Attribute("name") ? v->Attribute("name") : "visual");
    const tinyxml2::XMLElement* geometry = v->FirstChildElement("geometry");
    if (!geometry ||
        !readGeometry(geometry, "visual '" + visual.name + "'", source, visual.shape, world, "cameras do not see it"))
      continue;
    visual.pose = compose(link_pose, xml::parseSdfPose(xml::childText(v, "pose", "")));
    visual.colour = readColour(v);
    world.visuals.push_back(visual);
  }
}

// A <model>: its links, nested models and includes. `placement` is where the enclosing element
// (the world, a parent model or an <include>) puts it; an include's name and pose replace the model's own.
void readModel(const tinyxml2::XMLElement* model, const Source& source, const Placement& placement, int depth,
               WorldDescription& world)
{
  for (auto* link = model->FirstChildElement("link"); link; link = link->NextSiblingElement("link"))
    readLink(link, source, placement, world);
  for (auto* e = model->FirstChildElement(); e; e = e->NextSiblingElement())
  {
    const std::string tag = e->Name();
    if (tag == "model")
    {
      Placement nested;
      nested.name = placement.name + "::" + (e->Attribute("name") ? e->Attribute("name") : "model");
      nested.pose = compose(placement.pose, xml::parseSdfPose(xml::childText(e, "pose", "")));
      nested.is_static = placement.is_static;
      readModel(e, source, nested, depth + 1, world);
    }
    else if (tag == "include")
      readInclude(e, source, placement.name + "::", placement.pose, depth + 1, world);
  }
}

void warnIfNotStatic(const Placement& model, const Source& source, WorldDescription& world)
{
  if (!model.is_static)
    world.warnings.push_back("model '" + model.name + "' in " + source.describe() +
                             " is not static; the plant keeps world models still");
}

// The model file model.config names: the <sdf> of the newest version; model.sdf without a config.
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

// The directory an <include><uri> names: model://NAME through the model path, or a path.
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

// <include>: the model's files are found, then it is read as if written here, with the include's
// <name>, <pose> and <static> in place of the model's own.
void readInclude(const tinyxml2::XMLElement* include, const Source& source, const std::string& scope,
                 const urdf::Pose& parent, int depth, WorldDescription& world)
{
  const std::string uri = xml::childText(include, "uri", "");
  const urdf::Pose pose = compose(parent, xml::parseSdfPose(xml::childText(include, "pose", "")));
  const std::string name_override = xml::childText(include, "name", "");
  // The plant's own stand-ins, whether or not Gazebo's model database is installed, so a world runs
  // the same everywhere.
  if (uri == "model://ground_plane" || uri == "model://ground_plane/")
  {
    addGroundPlane(scope + (name_override.empty() ? "ground_plane" : name_override), pose, world);
    return;
  }
  if (uri == "model://sun" || uri == "model://sun/")
    return;  // the default light direction is the sun's
  std::string reason;
  const std::string dir = depth > kMaxModelDepth ? "" : includedModelDir(uri, source, reason);
  if (dir.empty())
  {
    world.warnings.push_back("<include> of '" + uri + "' in " + source.describe() + ": " +
                             (depth > kMaxModelDepth ? "models nested too deep (an include loop?)" : reason) +
                             "; skipped");
    return;
  }
  Source model_source{modelFile(dir), dir};
  tinyxml2::XMLDocument doc;
  parseXml(doc, readFile(model_source.file, "model file"), model_source);
  const tinyxml2::XMLElement* sdf = doc.FirstChildElement("sdf");
  const tinyxml2::XMLElement* model = sdf ? sdf->FirstChildElement("model") : nullptr;
  if (!model)
  {
    world.warnings.push_back("<include> of '" + uri + "' in " + source.describe() + ": " + model_source.describe() +
                             " has no <sdf><model>; skipped");
    return;
  }
  Placement placement;
  placement.name = scope + (name_override.empty() ? (model->Attribute("name") ? model->Attribute("name") : "model")
                                                  : name_override);
  placement.pose = include->FirstChildElement("pose") ? pose
                                                      : compose(pose, xml::parseSdfPose(xml::childText(model, "pose", "")));
  placement.is_static = isTrue(xml::childText(include, "static", xml::childText(model, "static", "false")));
  if (scope.empty())
    warnIfNotStatic(placement, source, world);
  readModel(model, model_source, placement, depth, world);
}

// World elements that put things into the scene which the plant does not build.
bool isUnsupportedWorldElement(const std::string& tag)
{
  return tag == "actor" || tag == "population" || tag == "road";
}

WorldDescription parseWorld(const std::string& sdf_xml, const Source& source)
{
  tinyxml2::XMLDocument doc;
  parseXml(doc, sdf_xml, source);
  const tinyxml2::XMLElement* sdf = doc.FirstChildElement("sdf");
  const tinyxml2::XMLElement* w = sdf ? sdf->FirstChildElement("world") : nullptr;
  if (!w)
    throw DescriptionError("SDF " + source.describe() + " has no <sdf><world> element");

  WorldDescription world;
  world.file = source.file;
  world.base_dir = source.dir;
  world.name = w->Attribute("name") ? w->Attribute("name") : "default";
  if (auto* physics = w->FirstChildElement("physics"))
  {
    world.max_step_size = xml::childDouble(physics, "max_step_size", world.max_step_size);
    world.real_time_factor = xml::childDouble(physics, "real_time_factor", world.real_time_factor);
    world.contact_max_correcting_vel =
        xml::childDouble(physics, "ode/constraints/contact_max_correcting_vel", world.contact_max_correcting_vel);
    if (!(world.contact_max_correcting_vel >= 0 && std::isfinite(world.contact_max_correcting_vel)))
    {
      std::ostringstream text;
      text << "<physics><ode><constraints><contact_max_correcting_vel> " << world.contact_max_correcting_vel
           << " must be a finite speed >= 0 m/s (Gazebo's default: 100)";
      throw DescriptionError(text.str());
    }
    if (!(world.max_step_size >= kMinStepSize && world.max_step_size <= kMaxStepSize))
    {
      std::ostringstream text;
      text << "<physics><max_step_size> " << world.max_step_size << " is out of range [" << formatNumber(kMinStepSize) << ", "
           << formatNumber(kMaxStepSize) << "] s";
      throw DescriptionError(text.str());
    }
  }
  std::string gravity = xml::childText(w, "gravity", "");
  if (!gravity.empty())
  {
    std::vector<double> g = xml::numbers(gravity, 3, "<gravity>");
    world.gravity = urdf::Vector3(g[0], g[1], g[2]);
    const double magnitude = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
    if (!(magnitude <= kMaxGravity))
    {
      std::ostringstream text;
      text << "<gravity> " << gravity << " is " << magnitude << " m/s^2; the plant takes at most " << kMaxGravity
           << " m/s^2 (Earth: 9.8)";
      throw DescriptionError(text.str());
    }
  }
  for (auto* light = w->FirstChildElement("light"); light; light = light->NextSiblingElement("light"))
    if (light->Attribute("type") && std::string(light->Attribute("type")) == "directional")
    {
      std::vector<double> d = xml::numbers(xml::childText(light, "direction", "-0.5 0.1 -0.9"), 3, "<light><direction>");
      world.light_direction = urdf::Vector3(d[0], d[1], d[2]);
    }
  if (const tinyxml2::XMLElement* scene = w->FirstChildElement("scene"))
  {
    const std::string background = xml::childText(scene, "background", "");
    if (!background.empty())
    {
      std::vector<double> c = colourNumbers(background, "<scene><background>");
      world.background = {float(c[0]), float(c[1]), float(c[2]), 1.0f};
    }
    const std::string ambient = xml::childText(scene, "ambient", "");
    if (!ambient.empty())
    {
      std::vector<double> c = colourNumbers(ambient, "<scene><ambient>");
      world.ambient = std::max(0.0, std::min(1.0, (c[0] + c[1] + c[2]) / 3.0));
    }
    world.shadows = isTrue(xml::childText(scene, "shadows", "true"));
  }
  for (auto* e = w->FirstChildElement(); e; e = e->NextSiblingElement())
  {
    std::string tag = e->Name();
    if (tag == "model")
    {
      Placement placement;
      placement.name = e->Attribute("name") ? e->Attribute("name") : "model";
      placement.pose = xml::parseSdfPose(xml::childText(e, "pose", ""));
      placement.is_static = isTrue(xml::childText(e, "static", "false"));
      warnIfNotStatic(placement, source, world);
      readModel(e, source, placement, 0, world);
    }
    else if (tag == "include")
      readInclude(e, source, "", urdf::Pose(), 0, world);
    else if (isUnsupportedWorldElement(tag))
      world.warnings.push_back("<" + tag + "> in " + source.describe() + " is not supported; skipped");
  }
  bool has_plane = false;
  for (const StaticCollision& c : world.collisions)
    has_plane = has_plane || c.shape.kind == Shape::Kind::Plane;
  if (!has_plane)
    addGroundPlane("ground_plane", urdf::Pose(), world);
  return world;
}

}  // namespace

WorldDescription emptyWorldDescription()
{
  WorldDescription world;
  addGroundPlane("ground_plane", urdf::Pose(), world);
  return world;
}

WorldDescription parseWorldDescription(const std::string& sdf_xml, const std::string& base_dir)
{
  return parseWorld(sdf_xml, Source{"", base_dir});
}

WorldDescription parseWorldFile(const std::string& name)
{
  std::string reason;
  const std::string path = findWorldFile(name, reason);
  if (path.empty())
    throw DescriptionError(reason);
  return parseWorld(readFile(path, "world file"), Source{path, directoryOf(path)});
}

}  // namespace bullet_plant
