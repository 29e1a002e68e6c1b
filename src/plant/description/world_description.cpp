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
#include "description/sdf_elements.h"
#include "description/xml_util.h"

namespace bullet_plant
{
namespace
{
using sdf::Source;

// Where a model goes: its name (with the enclosing models' names, as Gazebo scopes them) and pose.
struct Placement
{
  std::string name;
  urdf::Pose pose;  // in the world
  bool is_static = false;
  // Of a static model's part: the world's static model it belongs to (WorldDescription::static_models)
  // and the scope its links' names take there ("" for the model's own, "inner::" for a nested one's).
  std::string model, link_scope;
};

// A static model of the world (a top-level <model> or <include>), its links to come.
Placement staticModel(const std::string& name, const urdf::Pose& pose, WorldDescription& world)
{
  world.static_models.push_back({name, pose, {}});
  Placement placement;
  placement.name = placement.model = name;
  placement.pose = pose;
  placement.is_static = true;
  return placement;
}

// The link `name` (scoped in its model) of the static model `model`, at `pose` in the world.
void addStaticLink(const std::string& model, const std::string& name, const urdf::Pose& pose, WorldDescription& world)
{
  for (auto it = world.static_models.rbegin(); it != world.static_models.rend(); ++it)
    if (it->name == model)
    {
      it->links.push_back({name, pose});
      return;
    }
}

// The strongest <gravity> the plant takes, m/s^2 (100 g): beyond it the robots only diverge.
constexpr double kMaxGravity = 1000.0;

StaticCollision groundPlane(const std::string& model_name, const urdf::Pose& pose)
{
  StaticCollision ground;
  ground.name = model_name + "::link::collision";
  ground.model = model_name;
  ground.shape.kind = Shape::Kind::Plane;
  ground.pose = pose;
  return ground;
}

// What cameras see of the ground plane: the plane itself in its model's Gazebo/Grey.
StaticVisual groundPlaneVisual(const StaticCollision& ground)
{
  StaticVisual visual;
  visual.name = ground.name.substr(0, ground.name.rfind("::")) + "::visual";
  visual.model = ground.model;
  visual.shape = ground.shape;
  visual.pose = ground.pose;
  visual.material.has_replace = sdf::gazeboMaterial("Gazebo/Grey", visual.material.replace);
  return visual;
}

// Gazebo's ground_plane model: a static model of one link, or a part of the static model that
// includes it (`within`, with its link scope).
void addGroundPlane(const std::string& model_name, const urdf::Pose& pose, const Placement* within,
                    WorldDescription& world)
{
  const Placement placement = within ? *within : staticModel(model_name, pose, world);
  const std::string link = within ? placement.link_scope + model_name.substr(model_name.rfind("::") + 2) + "::link" : "link";
  addStaticLink(placement.model, link, pose, world);
  world.collisions.push_back(groundPlane(model_name, pose));
  world.collisions.back().model = placement.model;
  world.visuals.push_back(groundPlaneVisual(world.collisions.back()));
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

void readInclude(const tinyxml2::XMLElement* include, const Source& source, const std::string& scope,
                 const urdf::Pose& parent, int depth, WorldDescription& world, const Placement* within = nullptr);
LightDescription readLight(const tinyxml2::XMLElement* light, const urdf::Pose& parent, const Source& source,
                           WorldDescription& world);

void readLink(const tinyxml2::XMLElement* link, const Source& source, const Placement& model, WorldDescription& world)
{
  std::string link_name = link->Attribute("name") ? link->Attribute("name") : "link";
  urdf::Pose link_pose = compose(model.pose, xml::parseSdfPose(xml::childText(link, "pose", "")));
  addStaticLink(model.model, model.link_scope + link_name, link_pose, world);
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
    if (!sdf::readGeometry(geometry, where, source, collision.shape, world.warnings))
      continue;
    collision.pose = compose(link_pose, xml::parseSdfPose(xml::childText(c, "pose", "")));
    collision.mu = xml::childDouble(c, "surface/friction/ode/mu", 1.0);
    if (!(collision.mu >= 0))  // negative or NaN: Bullet would push along the motion
    {
      world.warnings.push_back(where + " in " + source.describe() + ": <mu> " + formatNumber(collision.mu) +
                               " is not a friction coefficient; it is taken as 0");
      collision.mu = 0;
    }
    collision.surface = sdf::readSurface(c, where + " in " + source.describe());
    collision.restitution = collision.surface.restitution;
    collision.restitution_threshold = collision.surface.restitution_threshold;
    collision.model = model.model;
    world.collisions.push_back(collision);
  }
  for (auto* v = link->FirstChildElement("visual"); v; v = v->NextSiblingElement("visual"))
  {
    StaticVisual visual;
    visual.name = model.name + "::" + link_name + "::" + (v->Attribute("name") ? v->Attribute("name") : "visual");
    const tinyxml2::XMLElement* geometry = v->FirstChildElement("geometry");
    if (!geometry ||
        !sdf::readGeometry(geometry, "visual '" + visual.name + "'", source, visual.shape, world.warnings,
                           "cameras do not see it"))
      continue;
    visual.pose = compose(link_pose, xml::parseSdfPose(xml::childText(v, "pose", "")));
    visual.material = sdf::readMaterial(v, "visual '" + visual.name + "' in " + source.describe(), world.warnings);
    visual.model = model.model;
    world.visuals.push_back(visual);
  }
  if (link->FirstChildElement("light"))
    world.warnings.push_back("the <light>s of link '" + model.name + "::" + link_name + "' in " + source.describe() +
                             " are not lit: the plant lights cameras with a world's own <light>s and included "
                             "light files (model://sun)");
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
      nested.model = placement.model;
      nested.link_scope = placement.link_scope + (e->Attribute("name") ? e->Attribute("name") : "model") + "::";
      readModel(e, source, nested, depth + 1, world);
    }
    else if (tag == "include")
      readInclude(e, source, placement.name + "::", placement.pose, depth + 1, world, &placement);
  }
}

// A static model with a <sensor> or a <plugin> (gazebo_plugins' test worlds hold their cameras so)
// is a model of the world that never moves, not scenery: its sensors and plugins run.
bool hasSensorOrPlugin(const tinyxml2::XMLElement* model)
{
  if (model->FirstChildElement("plugin"))
    return true;
  for (auto* link = model->FirstChildElement("link"); link; link = link->NextSiblingElement("link"))
    if (link->FirstChildElement("sensor"))
      return true;
  for (auto* nested = model->FirstChildElement("model"); nested; nested = nested->NextSiblingElement("model"))
    if (hasSensorOrPlugin(nested))
      return true;
  return false;
}

// A model with no links of its own whose nested models and includes are all <static> never moves:
// Gazebo keeps a nested model's own <static>. (AWS RoboMaker's worlds wrap each include of a static
// model in a <model> that only names and places it.)
bool holdsOnlyStaticModels(const tinyxml2::XMLElement* model, const Source& source, int depth)
{
  if (model->FirstChildElement("link") || depth > sdf::kMaxModelDepth)
    return false;
  bool holds_any = false;
  for (auto* e = model->FirstChildElement(); e; e = e->NextSiblingElement())
  {
    const std::string tag = e->Name();
    if (tag == "model")
    {
      holds_any = true;
      if (!sdf::isTrue(xml::childText(e, "static", "false")) && !holdsOnlyStaticModels(e, source, depth + 1))
        return false;
    }
    else if (tag == "include")
    {
      holds_any = true;
      const std::string include_static = xml::childText(e, "static", "");
      if (!include_static.empty())
      {
        if (!sdf::isTrue(include_static))
          return false;
        continue;
      }
      tinyxml2::XMLDocument doc;
      Source model_source;
      std::string why;
      const tinyxml2::XMLElement* included =
          sdf::readIncludedModel(xml::childText(e, "uri", ""), source, depth + 1, doc, model_source, why);
      if (included && !sdf::isTrue(xml::childText(included, "static", "false")) &&
          !holdsOnlyStaticModels(included, model_source, depth + 1))
        return false;  // (one that cannot be read is skipped with its warning when the model is read)
    }
  }
  return holds_any;
}

// A model that moves (or a static one with sensors or plugins), read as spawn_model reads one, or
// refused with the reason (the world goes on). `own_pose`: the model's <pose> places it (a world's
// <model>), else `placement`'s (an <include>'s).
void addMovingModel(const tinyxml2::XMLElement* model, const Source& source, const Placement& placement, int depth,
                    WorldDescription& world, bool own_pose = false)
{
  try
  {
    ModelDescription moving = sdf::readModel(model, source, depth);
    moving.name = placement.name;
    if (!own_pose)
      moving.pose = placement.pose;
    moving.robot.is_static = placement.is_static;
    for (const ModelDescription& other : world.models)
      if (other.name == moving.name)
        throw DescriptionError("a model named '" + moving.name + "' is already in the world; model names must be unique");
    world.models.push_back(std::move(moving));
  }
  catch (const DescriptionError& e)
  {
    world.errors.push_back("model '" + placement.name + "' in " + source.describe() + " is left out: " + e.what());
  }
}

// <include>: the model's files are found, then it is read as if written here, with the include's
// <name>, <pose> and <static> in place of the model's own.
void readInclude(const tinyxml2::XMLElement* include, const Source& source, const std::string& scope,
                 const urdf::Pose& parent, int depth, WorldDescription& world, const Placement* within)
{
  const std::string uri = xml::childText(include, "uri", "");
  const urdf::Pose pose = compose(parent, xml::parseSdfPose(xml::childText(include, "pose", "")));
  const std::string name_override = xml::childText(include, "name", "");
  // The plant's own stand-ins, whether or not Gazebo's model database is installed, so a world runs
  // the same everywhere.
  if (uri == "model://ground_plane" || uri == "model://ground_plane/")
  {
    addGroundPlane(scope + (name_override.empty() ? "ground_plane" : name_override), pose, within, world);
    return;
  }
  if (uri == "model://sun" || uri == "model://sun/")
  {
    // Gazebo's sun model is a light file, its light in the world (the include's pose moves it).
    LightDescription sun = LightDescription::sun();
    if (!name_override.empty())
      sun.name = name_override;
    sun.position = compose(pose, poseFromXyzRpy(0, 0, 10, 0, 0, 0)).position;
    sun.direction = rotate(pose.rotation, sun.direction);
    world.lights.push_back(sun);
    return;
  }
  tinyxml2::XMLDocument doc;
  Source model_source;
  std::string why;
  const tinyxml2::XMLElement* model = sdf::readIncludedModel(uri, source, depth, doc, model_source, why);
  const tinyxml2::XMLElement* root = doc.FirstChildElement("sdf");
  if (!model && root && root->FirstChildElement("light"))
  {
    // a light file (as model://sun is): its lights, where the include puts them
    for (auto* light = root->FirstChildElement("light"); light; light = light->NextSiblingElement("light"))
      world.lights.push_back(readLight(light, pose, model_source, world));
    return;
  }
  if (!model)
  {
    world.warnings.push_back("<include> of '" + uri + "' in " + source.describe() + ": " + why + "; skipped");
    return;
  }
  Placement placement;
  placement.name = scope + (name_override.empty() ? (model->Attribute("name") ? model->Attribute("name") : "model")
                                                  : name_override);
  placement.pose = include->FirstChildElement("pose") ? pose
                                                      : compose(pose, xml::parseSdfPose(xml::childText(model, "pose", "")));
  placement.is_static = sdf::isTrue(xml::childText(include, "static", xml::childText(model, "static", "false")));
  if (scope.empty() && (!placement.is_static || hasSensorOrPlugin(model)))
    addMovingModel(model, model_source, placement, depth, world);
  else if (!within)
    readModel(model, model_source, staticModel(placement.name, placement.pose, world), depth, world);
  else
  {
    placement.model = within->model;
    placement.link_scope = within->link_scope + placement.name.substr(scope.size()) + "::";
    readModel(model, model_source, placement, depth, world);
  }
}

// A <light> in the world (`parent`: where the element that holds it puts it), SDF's defaults where
// absent. A value that is not a number stops the load (xml::numbers); a point or spot light that
// lights nothing (a range or factors that cannot light) is warned about and left dark. Gazebo's
// Light::SetAttenuation clamps the constant and linear factors to [0, 1]: so are they here.
LightDescription readLight(const tinyxml2::XMLElement* light, const urdf::Pose& parent, const Source& source,
                           WorldDescription& world)
{
  LightDescription out;
  out.name = light->Attribute("name") ? light->Attribute("name") : "";
  const std::string type = light->Attribute("type") ? light->Attribute("type") : "point";
  out.kind = type == "directional" ? LightDescription::Kind::Directional
             : type == "spot"      ? LightDescription::Kind::Spot
                                   : LightDescription::Kind::Point;
  const std::string where = "light '" + out.name + "'";
  const urdf::Pose pose = compose(parent, xml::parseSdfPose(xml::childText(light, "pose", "")));
  out.position = pose.position;
  const std::vector<double> d = xml::numbers(xml::childText(light, "direction", "0 0 -1"), 3, where + " <direction>");
  const urdf::Vector3 direction = rotate(pose.rotation, urdf::Vector3(d[0], d[1], d[2]));
  const double norm = std::sqrt(direction.x * direction.x + direction.y * direction.y + direction.z * direction.z);
  if (norm > 0 && std::isfinite(norm))
    out.direction = scaled(direction, 1.0 / norm);
  else
    world.warnings.push_back(where + " in " + source.describe() + ": <direction> " +
                             xml::trimmed(xml::childText(light, "direction", "")) +
                             " is not a direction (zero or not finite); it shines straight down");
  for (const auto& c : {std::make_pair("diffuse", &out.diffuse), std::make_pair("specular", &out.specular)})
  {
    const std::string text = xml::childText(light, c.first, "");
    if (text.empty())
      continue;
    const std::vector<double> v = colourNumbers(text, where + " <" + c.first + ">");
    *c.second = {float(v[0]), float(v[1]), float(v[2]), 1.0f};
  }
  out.cast_shadows = sdf::readFlag(light, "cast_shadows", false, where);
  out.range = xml::childDouble(light, "attenuation/range", out.range);
  out.constant = xml::childDouble(light, "attenuation/constant", out.constant);
  out.linear = xml::childDouble(light, "attenuation/linear", out.linear);
  out.quadratic = xml::childDouble(light, "attenuation/quadratic", out.quadratic);
  out.inner_angle = xml::childDouble(light, "spot/inner_angle", out.inner_angle);
  out.outer_angle = xml::childDouble(light, "spot/outer_angle", out.outer_angle);
  out.falloff = xml::childDouble(light, "spot/falloff", out.falloff);
  for (double v : {out.position.x, out.position.y, out.position.z, out.range, out.constant, out.linear, out.quadratic,
                   out.inner_angle, out.outer_angle, out.falloff})
    if (!std::isfinite(v))
      throw DescriptionError(where + ": its pose, <attenuation> and <spot> must be finite numbers");
  if (out.kind == LightDescription::Kind::Directional)
    return out;
  out.constant = std::min(1.0, out.constant);
  out.linear = std::min(1.0, out.linear);
  if (out.range <= 0 || out.constant < 0 || out.linear < 0 || out.quadratic < 0 ||
      out.constant + out.linear + out.quadratic <= 0)
  {
    world.warnings.push_back(where + ": <attenuation> range " + formatNumber(out.range) + ", constant " +
                             formatNumber(out.constant) + ", linear " + formatNumber(out.linear) + ", quadratic " +
                             formatNumber(out.quadratic) + " lights nothing (give a positive range and factors >= 0, "
                             "not all 0); left dark");
    out.range = 0;  // cameras leave it out
  }
  return out;
}

// A world's <plugin>: a Gazebo WorldPlugin library, loaded where its file is found on the plugin
// paths, as Gazebo's World::LoadPlugin looks for it. Gazebo reports a file it cannot open and runs
// the world without it; so does the plant (gazebo_ros's own world plugins are the node itself).
void addWorldPlugin(const tinyxml2::XMLElement* e, const Source& source, WorldDescription& world)
{
  WorldPluginDescription plugin;
  plugin.name = e->Attribute("name") ? e->Attribute("name") : "";
  plugin.filename = e->Attribute("filename") ? e->Attribute("filename") : "";
  plugin.library = findGazeboPluginLibrary(plugin.filename);
  if (plugin.library.empty())
  {
    world.warnings.push_back("world plugin '" + plugin.name + "' (" +
                             (plugin.filename.empty() ? "no filename" : plugin.filename) + ") in " + source.describe() +
                             " is not run: no such file on GAZEBO_PLUGIN_PATH or LD_LIBRARY_PATH; skipped");
    return;
  }
  plugin.xml = xml::printed(e);
  world.plugins.push_back(std::move(plugin));
}

// A saved world's <state> (gzclient's "Save World" writes one): each model it names that the world
// simulates starts at the state's <pose>, as Gazebo's World::SetState puts it. What the plant does
// not take from it is said once: link poses (joint positions), scenery moved, insertions, deletions.
void applyState(const tinyxml2::XMLElement* state, const Source& source, WorldDescription& world)
{
  std::vector<std::string> left_out;
  for (auto* m = state->FirstChildElement("model"); m; m = m->NextSiblingElement("model"))
  {
    const std::string name = m->Attribute("name") ? m->Attribute("name") : "";
    auto model = std::find_if(world.models.begin(), world.models.end(),
                              [&](const ModelDescription& d) { return d.name == name; });
    if (model == world.models.end())
      continue;  // scenery (static) or not in the world: where the file put it
    if (m->FirstChildElement("pose"))
      model->pose = xml::parseSdfPose(xml::childText(m, "pose", ""));
    // A model without movable joints has its links where its pose puts them.
    bool movable = false;
    for (const auto& joint : model->robot.model->joints_)
      movable = movable || joint.second->type != urdf::Joint::FIXED;
    if (m->FirstChildElement("link") && movable)
      left_out.push_back("the link poses of '" + name + "'");
  }
  for (const char* tag : {"insertions", "deletions"})
    if (state->FirstChildElement(tag))
      left_out.push_back(std::string("<") + tag + ">");
  std::string text;
  for (const std::string& what : left_out)
    text += (text.empty() ? "" : ", ") + what;
  if (!text.empty())
    world.warnings.push_back("<state> in " + source.describe() + ": the models start at its poses; " + text +
                             " are not applied (the models' joints start at their files' positions)");
}

// <physics><ode>'s solver settings: those the plant's solver has an equivalent of, checked; the
// others said once as not applied.
void readSolverSettings(const tinyxml2::XMLElement* physics, const Source& source, WorldDescription& world)
{
  const tinyxml2::XMLElement* ode = physics->FirstChildElement("ode");
  if (!ode)
    return;
  auto number = [&](const char* path, const std::string& element) {
    return xml::numbers(xml::childText(ode, path, ""), 1, "<physics><ode>" + element)[0];
  };
  auto fail = [](const std::string& element, double value, const std::string& range) {
    std::ostringstream text;
    text << "<physics><ode>" << element << " " << value << " " << range;
    throw DescriptionError(text.str());
  };
  if (ode->FirstChildElement("solver") && ode->FirstChildElement("solver")->FirstChildElement("iters"))
  {
    const double iters = number("solver/iters", "<solver><iters>");
    if (!(iters >= 1 && iters <= kMaxSolverIterations && iters == std::floor(iters)))
      fail("<solver><iters>", iters, "must be a whole number of passes from 1 to " +
                                         std::to_string(kMaxSolverIterations) + " (Gazebo's default: 50)");
    world.solver_iterations = int(iters);
  }
  if (ode->FirstChildElement("solver") && ode->FirstChildElement("solver")->FirstChildElement("sor"))
  {
    world.sor = number("solver/sor", "<solver><sor>");
    if (!(world.sor > 0 && world.sor < 2))
      fail("<solver><sor>", world.sor, "must lie between 0 and 2, where over-relaxation converges (Gazebo's "
                                       "default: 1.3)");
  }
  if (ode->FirstChildElement("constraints") &&
      ode->FirstChildElement("constraints")->FirstChildElement("contact_surface_layer"))
  {
    world.contact_surface_layer = number("constraints/contact_surface_layer", "<constraints><contact_surface_layer>");
    if (!(world.contact_surface_layer >= 0 && world.contact_surface_layer <= 1))
      fail("<constraints><contact_surface_layer>", world.contact_surface_layer,
           "must be a depth from 0 to 1 m (Gazebo's default: 0.001)");
  }
  std::string not_applied;
  if (xml::childText(ode, "solver/type", "quick") == "world")
    not_applied = "<type>world (dWorldStep's direct solve; the plant iterates)";
  for (const char* path : {"solver/min_step_size", "solver/precon_iters", "solver/use_dynamic_moi_rescaling",
                           "solver/friction_model", "solver/island_threads", "solver/thread_position_correction",
                           "constraints/erp", "constraints/cfm"})
  {
    const std::string text(path);
    const size_t slash = text.find('/');
    const tinyxml2::XMLElement* group = ode->FirstChildElement(text.substr(0, slash).c_str());
    if (group && group->FirstChildElement(text.substr(slash + 1).c_str()))
      not_applied += (not_applied.empty() ? "<" : ", <") + text.substr(slash + 1) + ">";
  }
  if (!not_applied.empty())
    world.warnings.push_back("<physics><ode> in " + source.describe() + ": " + not_applied + " not applied: the "
                             "plant's solver is Bullet's multibody one, iterated as ODE's quick step; its joints are "
                             "reduced coordinates that need no error reduction, and its contacts take none of the "
                             "world's erp and cfm, as Gazebo's take theirs from each <surface>'s kp and kd");
}

// World elements that put things into the scene which the plant does not build.
bool isUnsupportedWorldElement(const std::string& tag)
{
  return tag == "actor" || tag == "population" || tag == "road";
}

WorldDescription parseWorld(const std::string& sdf_xml, const Source& source)
{
  tinyxml2::XMLDocument doc;
  sdf::parseXml(doc, sdf_xml, source);
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
    world.real_time_update_rate = xml::childDouble(physics, "real_time_update_rate", world.real_time_update_rate);
    if (!(world.real_time_update_rate >= 0 && std::isfinite(world.real_time_update_rate)))
      throw DescriptionError("<physics><real_time_update_rate> " + formatNumber(world.real_time_update_rate) +
                             " must be a finite rate >= 0 Hz (0: as fast as possible; Gazebo's default: 1000)");
    world.contact_max_correcting_vel =
        xml::childDouble(physics, "ode/constraints/contact_max_correcting_vel", world.contact_max_correcting_vel);
    if (!(world.contact_max_correcting_vel >= 0 && std::isfinite(world.contact_max_correcting_vel)))
    {
      std::ostringstream text;
      text << "<physics><ode><constraints><contact_max_correcting_vel> " << world.contact_max_correcting_vel
           << " must be a finite speed >= 0 m/s (Gazebo's default: 100)";
      throw DescriptionError(text.str());
    }
    readSolverSettings(physics, source, world);
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
  const std::string magnetic_field = xml::childText(w, "magnetic_field", "");
  if (!magnetic_field.empty())
  {
    std::vector<double> b = xml::numbers(magnetic_field, 3, "<magnetic_field>");
    for (double v : b)
      if (!std::isfinite(v))
        throw DescriptionError("<magnetic_field> " + xml::trimmed(magnetic_field) + " must be three finite numbers "
                               "(tesla, world frame)");
    world.magnetic_field = urdf::Vector3(b[0], b[1], b[2]);
  }
  // The lights in file order, the world's own and its includes' (model://sun) as they come.
  auto addLight = [&](const tinyxml2::XMLElement* light) {
    const std::string type = light->Attribute("type") ? light->Attribute("type") : "point";
    if (type == "directional" || type == "point" || type == "spot")
      world.lights.push_back(readLight(light, urdf::Pose(), source, world));
    else
      world.warnings.push_back("light '" + std::string(light->Attribute("name") ? light->Attribute("name") : "") +
                               "' in " + source.describe() + " is of type '" + type +
                               "' (point, spot, directional are); left out");
  };
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
      world.ambient = {float(c[0]), float(c[1]), float(c[2]), 1.0f};
    }
    world.shadows = sdf::isTrue(xml::childText(scene, "shadows", "true"));
  }
  for (auto* e = w->FirstChildElement(); e; e = e->NextSiblingElement())
  {
    std::string tag = e->Name();
    if (tag == "model")
    {
      Placement placement;
      placement.name = e->Attribute("name") ? e->Attribute("name") : "model";
      placement.is_static = sdf::isTrue(xml::childText(e, "static", "false")) || holdsOnlyStaticModels(e, source, 0);
      if (placement.is_static && !hasSensorOrPlugin(e))
        readModel(e, source, staticModel(placement.name, xml::parseSdfPose(xml::childText(e, "pose", "")), world), 0,
                  world);
      else
        addMovingModel(e, source, placement, 0, world, true);
    }
    else if (tag == "include")
      readInclude(e, source, "", urdf::Pose(), 0, world);
    else if (tag == "light")
      addLight(e);
    else if (tag == "plugin")
      addWorldPlugin(e, source, world);
    else if (isUnsupportedWorldElement(tag))
      world.warnings.push_back("<" + tag + "> in " + source.describe() + " is not supported; skipped");
  }
  if (const tinyxml2::XMLElement* state = w->FirstChildElement("state"))
    applyState(state, source, world);
  // A world gets the ground its file gives it and no other, as in Gazebo: a house whose floor is a
  // mesh has no plane under it, a world of objects in the void has nothing to fall on.
  return world;
}

}  // namespace

WorldDescription emptyWorldDescription()
{
  WorldDescription world;
  world.lights.push_back(LightDescription::sun());
  addGroundPlane("ground_plane", urdf::Pose(), nullptr, world);
  return world;
}

LightDescription LightDescription::sun()
{
  // gazebo's models/sun/model.sdf
  LightDescription sun;
  sun.name = "sun";
  sun.kind = Kind::Directional;
  sun.position = urdf::Vector3(0, 0, 10);
  const double n = std::sqrt(0.5 * 0.5 + 0.1 * 0.1 + 0.9 * 0.9);
  sun.direction = urdf::Vector3(-0.5 / n, 0.1 / n, -0.9 / n);
  sun.diffuse = {0.8f, 0.8f, 0.8f, 1.0f};
  sun.specular = {0.2f, 0.2f, 0.2f, 1.0f};
  sun.range = 1000;
  sun.constant = 0.9;
  sun.linear = 0.01;
  sun.quadratic = 0.001;
  sun.cast_shadows = true;
  return sun;
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
    throw WorldFileNotFound(reason);
  return parseWorld(sdf::readFile(path, "world file"), Source{path, sdf::directoryOf(path)});
}

namespace
{
// readSpawnedModel and readInsertedModel: an <include> without a <pose> at the identity (gazebo_ros
// then puts the request's pose there), or at the model's own <pose> (Gazebo's factory reads the file).
ModelDescription readModelRequest(const std::string& model_xml, bool include_at_identity)
{
  tinyxml2::XMLDocument doc;
  doc.Parse(model_xml.c_str(), model_xml.size());
  tinyxml2::XMLElement* root = doc.Error() ? nullptr : doc.RootElement();
  tinyxml2::XMLElement* world = root && std::string(root->Name()) == "sdf" && !root->FirstChildElement("model")
                                    ? root->FirstChildElement("world")
                                    : nullptr;
  tinyxml2::XMLElement* include = world && !world->FirstChildElement("model") ? world->FirstChildElement("include") : nullptr;
  if (!include)
    return parseModelXml(model_xml);  // URDF or an SDF model, or the parser's complaint
  // The model database request: the world reader finds and reads the included model.
  std::string uri = include->FirstChildElement("uri") && include->FirstChildElement("uri")->GetText()
                        ? include->FirstChildElement("uri")->GetText()
                        : "";
  uri.erase(0, uri.find_first_not_of(" \t\r\n"));
  uri.erase(uri.find_last_not_of(" \t\r\n") + 1);
  if (include_at_identity && !include->FirstChildElement("pose"))
    include->InsertEndChild(doc.NewElement("pose"))->ToElement()->SetText("0 0 0 0 0 0");
  auto read = [&doc] {
    tinyxml2::XMLPrinter printer;
    doc.Print(&printer);
    WorldDescription world = parseWorldDescription(printer.CStr());
    if (!world.errors.empty())
      throw DescriptionError(world.errors.front());
    return world;
  };
  WorldDescription found = read();
  bool is_static = false;
  if (found.models.empty())
  {
    // Not found: the world reader's warning names the URI and where it looked.
    for (const std::string& warning : found.warnings)
      if (warning.rfind("<include> of '" + uri + "'", 0) == 0)
        throw DescriptionError(warning);
    // Found, but <static>: scenery to a world; spawned, a model fixed where it is put, as Gazebo's.
    tinyxml2::XMLElement* static_element = include->FirstChildElement("static");
    if (!static_element)
      static_element = include->InsertEndChild(doc.NewElement("static"))->ToElement();
    static_element->SetText("false");
    found = read();
    is_static = true;
  }
  if (found.models.empty())
    throw DescriptionError("<include> of '" + uri + "' gives no model to spawn");
  ModelDescription model = std::move(found.models.front());
  model.robot.is_static = model.robot.is_static || is_static;
  return model;
}
}  // namespace

ModelDescription readSpawnedModel(const std::string& model_xml) { return readModelRequest(model_xml, true); }

ModelDescription readInsertedModel(const std::string& model_xml) { return readModelRequest(model_xml, false); }

}  // namespace bullet_plant
