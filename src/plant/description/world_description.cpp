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

// "r g b" or "r g b a", as SDF colours are written.
std::vector<double> colourNumbers(const std::string& text, const std::string& what)
{
  std::istringstream words(text);
  size_t count = 0;
  for (std::string word; words >> word;)
    ++count;
  return xml::numbers(text, count == 4 ? 4 : 3, what);
}

void readLink(const sdf::ElementPtr& link, const Source& source, const Placement& model, WorldDescription& world)
{
  std::string link_name = sdf::attribute(link, "name", "link");
  urdf::Pose link_pose = compose(model.pose, sdf::pose(link));
  addStaticLink(model.model, model.link_scope + link_name, link_pose, world);
  for (sdf::ElementPtr c = sdf::child(link, "collision"); c; c = c->GetNextElement("collision"))
  {
    StaticCollision collision;
    collision.name = model.name + "::" + link_name + "::" + sdf::attribute(c, "name", "collision");
    const std::string where = "collision '" + collision.name + "'";
    const sdf::ElementPtr geometry = sdf::child(c, "geometry");
    if (!geometry)
    {
      world.warnings.push_back(where + " in " + source.describe() + " has no <geometry>; left out");
      continue;
    }
    if (!sdf::readGeometry(geometry, where, source, collision.shape, world.warnings))
      continue;
    collision.pose = compose(link_pose, sdf::pose(c));
    // (a number of at least 0: sdformat enforces SDF's minimum, childDouble refuses NaN)
    collision.mu = sdf::childDouble(c, "surface/friction/ode/mu", 1.0);
    collision.surface = sdf::readSurface(c, where + " in " + source.describe());
    collision.restitution = collision.surface.restitution;
    collision.restitution_threshold = collision.surface.restitution_threshold;
    collision.model = model.model;
    world.collisions.push_back(collision);
  }
  for (sdf::ElementPtr v = sdf::child(link, "visual"); v; v = v->GetNextElement("visual"))
  {
    StaticVisual visual;
    visual.name = model.name + "::" + link_name + "::" + sdf::attribute(v, "name", "visual");
    const sdf::ElementPtr geometry = sdf::child(v, "geometry");
    if (!geometry ||
        !sdf::readGeometry(geometry, "visual '" + visual.name + "'", source, visual.shape, world.warnings,
                           "cameras do not see it"))
      continue;
    visual.pose = compose(link_pose, sdf::pose(v));
    visual.material = sdf::readMaterial(v, "visual '" + visual.name + "' in " + source.describe(), world.warnings);
    visual.model = model.model;
    world.visuals.push_back(visual);
  }
  if (sdf::child(link, "light"))
    world.warnings.push_back("the <light>s of link '" + model.name + "::" + link_name + "' in " + source.describe() +
                             " are not lit: the plant lights cameras with a world's own <light>s and included "
                             "light files (model://sun)");
}

// A static <model>: its links and nested models (an <include>d one is one, sdformat having read it
// in), each read from the file it came from. `placement` is where the enclosing element (the world
// or a parent model) puts it.
void readModel(const sdf::ElementPtr& model, const Source& source, const Placement& placement, WorldDescription& world)
{
  const Source model_source = sdf::sourceOf(model, source);
  for (sdf::ElementPtr link = sdf::child(model, "link"); link; link = link->GetNextElement("link"))
    readLink(link, model_source, placement, world);
  for (sdf::ElementPtr e = sdf::child(model, "model"); e; e = e->GetNextElement("model"))
  {
    const std::string name = sdf::attribute(e, "name", "model");
    Placement nested;
    nested.name = placement.name + "::" + name;
    nested.pose = compose(placement.pose, sdf::pose(e));
    nested.is_static = placement.is_static;
    nested.model = placement.model;
    nested.link_scope = placement.link_scope + name + "::";
    readModel(e, model_source, nested, world);
  }
}

// A static model with a <sensor> or a <plugin> (gazebo_plugins' test worlds hold their cameras so)
// is a model of the world that never moves, not scenery: its sensors and plugins run.
bool hasSensorOrPlugin(const sdf::ElementPtr& model)
{
  if (sdf::child(model, "plugin"))
    return true;
  for (sdf::ElementPtr link = sdf::child(model, "link"); link; link = link->GetNextElement("link"))
    if (sdf::child(link, "sensor"))
      return true;
  for (sdf::ElementPtr nested = sdf::child(model, "model"); nested; nested = nested->GetNextElement("model"))
    if (hasSensorOrPlugin(nested))
      return true;
  return false;
}

// A model with no links of its own whose nested models are all <static> never moves: Gazebo keeps a
// nested model's own <static>. (AWS RoboMaker's worlds wrap each include of a static model in a
// <model> that only names and places it.)
bool holdsOnlyStaticModels(const sdf::ElementPtr& model)
{
  if (sdf::child(model, "link"))
    return false;
  bool holds_any = false;
  for (sdf::ElementPtr e = sdf::child(model, "model"); e; e = e->GetNextElement("model"))
  {
    holds_any = true;
    if (!sdf::isTrue(sdf::childText(e, "static", "false")) && !holdsOnlyStaticModels(e))
      return false;
  }
  return holds_any;
}

// A model that moves (or a static one with sensors or plugins), read as spawn_model reads one, or
// refused with the reason (the world goes on).
void addMovingModel(const sdf::ElementPtr& model, const Source& source, bool is_static, WorldDescription& world)
{
  const std::string name = sdf::attribute(model, "name", "model");
  const Source model_source = sdf::sourceOf(model, source);
  try
  {
    ModelDescription moving = sdf::readModel(model, model_source);
    moving.robot.is_static = is_static;
    for (const ModelDescription& other : world.models)
      if (other.name == moving.name)
        throw DescriptionError("a model named '" + moving.name + "' is already in the world; model names must be unique");
    world.models.push_back(std::move(moving));
  }
  catch (const DescriptionError& e)
  {
    world.errors.push_back("model '" + name + "' in " + model_source.describe() + " is left out: " + e.what());
  }
}

// A <light> in the world (`parent`: where the element that holds it puts it), SDF's defaults where
// absent. A value that is not a number stops the load (xml::numbers); a point or spot light that
// lights nothing (a range or factors that cannot light) is warned about and left dark. Gazebo's
// Light::SetAttenuation clamps the constant and linear factors to [0, 1]: so are they here.
LightDescription readLight(const sdf::ElementPtr& light, const urdf::Pose& parent, const Source& source,
                           WorldDescription& world)
{
  LightDescription out;
  out.name = sdf::attribute(light, "name", "");
  const std::string type = sdf::attribute(light, "type", "point");
  out.kind = type == "directional" ? LightDescription::Kind::Directional
             : type == "spot"      ? LightDescription::Kind::Spot
                                   : LightDescription::Kind::Point;
  const std::string where = "light '" + out.name + "'";
  const urdf::Pose pose = compose(parent, sdf::pose(light));
  out.position = pose.position;
  const std::vector<double> d = xml::numbers(sdf::childText(light, "direction", "0 0 -1"), 3, where + " <direction>");
  const urdf::Vector3 direction = rotate(pose.rotation, urdf::Vector3(d[0], d[1], d[2]));
  const double norm = std::sqrt(direction.x * direction.x + direction.y * direction.y + direction.z * direction.z);
  if (norm > 0 && std::isfinite(norm))
    out.direction = scaled(direction, 1.0 / norm);
  else
    world.warnings.push_back(where + " in " + source.describe() + ": <direction> " +
                             xml::trimmed(sdf::childText(light, "direction", "")) +
                             " is not a direction (zero or not finite); it shines straight down");
  for (const auto& c : {std::make_pair("diffuse", &out.diffuse), std::make_pair("specular", &out.specular)})
  {
    const std::string text = sdf::childText(light, c.first, "");
    if (text.empty())
      continue;
    const std::vector<double> v = colourNumbers(text, where + " <" + c.first + ">");
    *c.second = {float(v[0]), float(v[1]), float(v[2]), 1.0f};
  }
  out.cast_shadows = sdf::flag(light, "cast_shadows", false);
  out.range = sdf::childDouble(light, "attenuation/range", out.range);
  out.constant = sdf::childDouble(light, "attenuation/constant", out.constant);
  out.linear = sdf::childDouble(light, "attenuation/linear", out.linear);
  out.quadratic = sdf::childDouble(light, "attenuation/quadratic", out.quadratic);
  out.inner_angle = sdf::childDouble(light, "spot/inner_angle", out.inner_angle);
  out.outer_angle = sdf::childDouble(light, "spot/outer_angle", out.outer_angle);
  out.falloff = sdf::childDouble(light, "spot/falloff", out.falloff);
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
void addWorldPlugin(const sdf::ElementPtr& e, const Source& source, WorldDescription& world)
{
  WorldPluginDescription plugin;
  plugin.name = sdf::attribute(e, "name", "");
  plugin.filename = sdf::attribute(e, "filename", "");
  plugin.library = findGazeboPluginLibrary(plugin.filename);
  if (plugin.library.empty())
  {
    world.warnings.push_back("world plugin '" + plugin.name + "' (" +
                             (plugin.filename.empty() ? "no filename" : plugin.filename) + ") in " + source.describe() +
                             " is not run: no such file on GAZEBO_PLUGIN_PATH or LD_LIBRARY_PATH; skipped");
    return;
  }
  plugin.element = e;
  plugin.document = sdf::root(e);
  world.plugins.push_back(std::move(plugin));
}

// A saved world's <state> (gzclient's "Save World" writes one): each model it names that the world
// simulates starts at the state's <pose>, as Gazebo's World::SetState puts it. What the plant does
// not take from it is said once: link poses (joint positions), scenery moved, insertions, deletions.
void applyState(const sdf::ElementPtr& state, const Source& source, WorldDescription& world)
{
  std::vector<std::string> left_out;
  for (sdf::ElementPtr m = sdf::child(state, "model"); m; m = m->GetNextElement("model"))
  {
    const std::string name = sdf::attribute(m, "name", "");
    auto model = std::find_if(world.models.begin(), world.models.end(),
                              [&](const ModelDescription& d) { return d.name == name; });
    if (model == world.models.end())
      continue;  // scenery (static) or not in the world: where the file put it
    if (sdf::child(m, "pose"))
      model->pose = sdf::pose(m);
    // A model without movable joints has its links where its pose puts them.
    bool movable = false;
    for (const auto& joint : model->robot.model->joints_)
      movable = movable || joint.second->type != urdf::Joint::FIXED;
    if (sdf::child(m, "link") && movable)
      left_out.push_back("the link poses of '" + name + "'");
  }
  for (const char* tag : {"insertions", "deletions"})
    if (sdf::child(state, tag))
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
void readSolverSettings(const sdf::ElementPtr& physics, const Source& source, WorldDescription& world)
{
  const sdf::ElementPtr ode = sdf::child(physics, "ode");
  if (!ode)
    return;
  auto number = [&](const char* path, const std::string& element) {
    return xml::numbers(sdf::childText(ode, path, ""), 1, "<physics><ode>" + element)[0];
  };
  auto fail = [](const std::string& element, double value, const std::string& range) {
    std::ostringstream text;
    text << "<physics><ode>" << element << " " << value << " " << range;
    throw DescriptionError(text.str());
  };
  if (sdf::child(ode, "solver/iters"))
  {
    const double iters = number("solver/iters", "<solver><iters>");
    if (!(iters >= 1 && iters <= kMaxSolverIterations && iters == std::floor(iters)))
      fail("<solver><iters>", iters, "must be a whole number of passes from 1 to " +
                                         std::to_string(kMaxSolverIterations) + " (Gazebo's default: 50)");
    world.solver_iterations = int(iters);
  }
  if (sdf::child(ode, "solver/sor"))
  {
    world.sor = number("solver/sor", "<solver><sor>");
    if (!(world.sor > 0 && world.sor < 2))
      fail("<solver><sor>", world.sor, "must lie between 0 and 2, where over-relaxation converges (Gazebo's "
                                       "default: 1.3)");
  }
  if (sdf::child(ode, "constraints/contact_surface_layer"))
  {
    world.contact_surface_layer = number("constraints/contact_surface_layer", "<constraints><contact_surface_layer>");
    if (!(world.contact_surface_layer >= 0 && world.contact_surface_layer <= 1))
      fail("<constraints><contact_surface_layer>", world.contact_surface_layer,
           "must be a depth from 0 to 1 m (Gazebo's default: 0.001)");
  }
  std::string not_applied;
  if (sdf::childText(ode, "solver/type", "quick") == "world")
    not_applied = "<type>world (dWorldStep's direct solve; the plant iterates)";
  for (const char* path : {"solver/min_step_size", "solver/precon_iters", "solver/use_dynamic_moi_rescaling",
                           "solver/friction_model", "solver/island_threads", "solver/thread_position_correction",
                           "constraints/erp", "constraints/cfm"})
  {
    const std::string text(path);
    const size_t slash = text.find('/');
    if (sdf::child(ode, text))
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

// The world's <model> or <include> (counted among the world's element children) holding the
// element `name` at `line` of `doc`; -1 where that is the world's own element, or none.
int topLevelIndex(const tinyxml2::XMLDocument& doc, const std::string& name, int line)
{
  const tinyxml2::XMLElement* root = doc.RootElement();
  const tinyxml2::XMLElement* w = std::string(root->Name()) == "world" ? root : root->FirstChildElement("world");
  int index = 0;
  for (const tinyxml2::XMLElement* e = w ? w->FirstChildElement() : nullptr; e; e = e->NextSiblingElement(), ++index)
    if ((std::string(e->Name()) == "model" || std::string(e->Name()) == "include") &&
        ((e->GetLineNum() == line && name == e->Name()) || sdf::elementAt(e, name, line)))
      return index;
  return -1;
}

// The world document as sdformat reads it. sdformat refuses a whole document for one value it
// cannot read (Gazebo then loads no world); the plant keeps the world's other models: the
// <model> or <include> holding what sdformat refused is left out, named in `errors` with
// sdformat's reason, and the rest read again, until sdformat reads it. A world whose own elements
// sdformat refuses is refused.
sdf::Document readWorldDocument(const std::string& text, const Source& source, std::vector<std::string>& errors)
{
  tinyxml2::XMLDocument original;  // the elements left out go from it, their lines as written
  std::string current = text;
  for (;;)
  {
    try
    {
      return sdf::readDocument(current, source);
    }
    catch (const sdf::Refusal& refused)
    {
      tinyxml2::XMLDocument shown;
      if (refused.element.empty() || shown.Parse(current.c_str(), current.size()) != tinyxml2::XML_SUCCESS)
        throw;
      const int index = topLevelIndex(shown, refused.element, refused.line);
      if (current == text)
        original.Parse(text.c_str(), text.size());
      tinyxml2::XMLElement* root = original.RootElement();
      tinyxml2::XMLElement* w = std::string(root->Name()) == "world" ? root : root->FirstChildElement("world");
      tinyxml2::XMLElement* culprit = w && index >= 0 ? w->FirstChildElement() : nullptr;
      for (int i = 0; culprit && i < index; ++i)
        culprit = culprit->NextSiblingElement();
      if (!culprit)
        throw;
      // (its elements' lines are those of the text sdformat read, the world printed again after the
      // first left out: the element left out is named by its own line as written)
      const char* name = culprit->Attribute("name");
      errors.push_back("<" + std::string(culprit->Name()) + "> " +
                       (name ? "'" + std::string(name) + "'" : "of '" + xml::childText(culprit, "uri", "") + "'") +
                       " in " + source.describe() + " (line " + std::to_string(culprit->GetLineNum()) +
                       ") is left out: " + sdf::reasonLeftOut(refused));
      w->DeleteChild(culprit);
      tinyxml2::XMLPrinter printer;
      original.Print(&printer);
      current = printer.CStr();
    }
  }
}

WorldDescription parseWorld(const std::string& sdf_xml, const Source& source)
{
  std::vector<std::string> left_out;
  const sdf::Document doc = readWorldDocument(sdf_xml, source, left_out);
  const sdf::ElementPtr w = sdf::child(doc.root(), "world");
  if (!w)
    throw DescriptionError("SDF " + source.describe() + " has no <sdf><world> element");

  WorldDescription world;
  world.file = source.file;
  world.base_dir = source.dir;
  world.warnings = doc.warnings;
  world.errors = left_out;
  world.name = sdf::attribute(w, "name", "default");
  if (sdf::ElementPtr physics = sdf::child(w, "physics"))
  {
    world.max_step_size = sdf::childDouble(physics, "max_step_size", world.max_step_size);
    world.real_time_factor = sdf::childDouble(physics, "real_time_factor", world.real_time_factor);
    world.real_time_update_rate = sdf::childDouble(physics, "real_time_update_rate", world.real_time_update_rate);
    if (!(world.real_time_update_rate >= 0 && std::isfinite(world.real_time_update_rate)))
      throw DescriptionError("<physics><real_time_update_rate> " + formatNumber(world.real_time_update_rate) +
                             " must be a finite rate >= 0 Hz (0: as fast as possible; Gazebo's default: 1000)");
    world.contact_max_correcting_vel =
        sdf::childDouble(physics, "ode/constraints/contact_max_correcting_vel", world.contact_max_correcting_vel);
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
  std::string gravity = sdf::childText(w, "gravity", "");
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
  const std::string magnetic_field = sdf::childText(w, "magnetic_field", "");
  if (!magnetic_field.empty())
  {
    std::vector<double> b = xml::numbers(magnetic_field, 3, "<magnetic_field>");
    for (double v : b)
      if (!std::isfinite(v))
        throw DescriptionError("<magnetic_field> " + xml::trimmed(magnetic_field) + " must be three finite numbers "
                               "(tesla, world frame)");
    world.magnetic_field = urdf::Vector3(b[0], b[1], b[2]);
  }
  if (const sdf::ElementPtr spherical = sdf::child(w, "spherical_coordinates"))
  {
    WorldDescription::SphericalCoordinates& s = world.spherical_coordinates;
    s.latitude_deg = sdf::childDouble(spherical, "latitude_deg", 0.0);
    s.longitude_deg = sdf::childDouble(spherical, "longitude_deg", 0.0);
    s.elevation = sdf::childDouble(spherical, "elevation", 0.0);
    s.heading_deg = sdf::childDouble(spherical, "heading_deg", 0.0);
    const std::string surface = sdf::childText(spherical, "surface_model", "EARTH_WGS84");
    if (surface != "EARTH_WGS84")
      world.warnings.push_back("<spherical_coordinates><surface_model> " + surface +
                               ": the plant knows EARTH_WGS84 only, as Gazebo 11; taken as that");
  }
  // The lights in file order, the world's own and its includes' (model://sun) as they come.
  auto addLight = [&](const sdf::ElementPtr& light) {
    const std::string type = sdf::attribute(light, "type", "point");
    const Source light_source = sdf::sourceOf(light, source);
    if (type == "directional" || type == "point" || type == "spot")
      world.lights.push_back(readLight(light, urdf::Pose(), light_source, world));
    else
      world.warnings.push_back("light '" + sdf::attribute(light, "name", "") + "' in " + light_source.describe() +
                               " is of type '" + type + "' (point, spot, directional are); left out");
  };
  if (const sdf::ElementPtr scene = sdf::child(w, "scene"))
  {
    const std::string background = sdf::childText(scene, "background", "");
    if (!background.empty())
    {
      std::vector<double> c = colourNumbers(background, "<scene><background>");
      world.background = {float(c[0]), float(c[1]), float(c[2]), 1.0f};
    }
    const std::string ambient = sdf::childText(scene, "ambient", "");
    if (!ambient.empty())
    {
      std::vector<double> c = colourNumbers(ambient, "<scene><ambient>");
      world.ambient = {float(c[0]), float(c[1]), float(c[2]), 1.0f};
    }
    world.shadows = sdf::isTrue(sdf::childText(scene, "shadows", "true"));
  }
  for (sdf::ElementPtr e = w->GetFirstElement(); e; e = e->GetNextElement())
  {
    const std::string tag = e->GetName();
    if (tag == "model")
    {
      // (an <include>d model among them, sdformat having read it in with the include's name, pose
      // and <static>)
      const bool is_static = sdf::isTrue(sdf::childText(e, "static", "false")) || holdsOnlyStaticModels(e);
      if (is_static && !hasSensorOrPlugin(e))
        readModel(e, source, staticModel(sdf::attribute(e, "name", "model"), sdf::pose(e), world), world);
      else
        addMovingModel(e, source, is_static, world);
    }
    else if (tag == "light")
      addLight(e);
    else if (tag == "plugin")
      addWorldPlugin(e, source, world);
    else if (isUnsupportedWorldElement(tag))
      world.warnings.push_back("<" + tag + "> in " + source.describe() + " is not supported; skipped");
  }
  if (const sdf::ElementPtr state = sdf::child(w, "state"))
    applyState(state, source, world);
  // A world gets the ground its file gives it and no other, as in Gazebo: a house whose floor is a
  // mesh has no plane under it, a world of objects in the void has nothing to fall on.
  return world;
}

}  // namespace

WorldDescription emptyWorldDescription()
{
  // Gazebo's worlds/empty.world: the sun and the ground plane, read once.
  static const WorldDescription empty = parseWorld(R"(<sdf version="1.6"><world name="default">
    <include><uri>model://sun</uri></include><include><uri>model://ground_plane</uri></include></world></sdf>)",
                                                   Source{"", ""});
  return empty;
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
