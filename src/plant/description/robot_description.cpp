#include "bullet_plant/robot_description.h"

#include "bullet_plant/params.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <mutex>
#include <sstream>

#include <sys/stat.h>

#include <console_bridge/console.h>
#include <tinyxml2.h>
#include <urdf_parser/urdf_parser.h>

#include "bullet_plant/geometry.h"
#include "bullet_plant/registry.h"
#include "description/gazebo_elements.h"
#include "description/sdf_elements.h"
#include "description/xml_util.h"

namespace bullet_plant
{
std::string SensorDescription::pluginParam(const std::string& key, const std::string& fallback) const
{
  auto it = plugin.find(key);
  return it == plugin.end() || it->second.empty() ? fallback : it->second;
}

double SensorDescription::pluginNumber(const std::string& key, double fallback) const
{
  auto it = plugin.find(key);
  if (it == plugin.end())
    return fallback;
  return xml::numbers(it->second, 1, "<" + key + "> of plugin '" + plugin_name + "' of sensor '" + name + "'")[0];
}

const PluginFile* findPluginFile(const std::string& filename) { return Registry<PluginFile>::instance().find(filename); }

std::string findGazeboPluginLibrary(const std::string& filename)
{
  struct stat found;
  if (filename.empty())
    return "";
  if (filename.front() == '/')
    return stat(filename.c_str(), &found) == 0 ? filename : "";
  for (const char* variable : {"GAZEBO_PLUGIN_PATH", "LD_LIBRARY_PATH"})
  {
    const char* value = std::getenv(variable);
    std::stringstream folders(value ? value : "");
    std::string folder;
    while (std::getline(folders, folder, ':'))
    {
      const std::string path = folder + "/" + filename;
      if (!folder.empty() && stat(path.c_str(), &found) == 0 && S_ISREG(found.st_mode))
        return path;
    }
  }
  return "";
}

std::string simulatedPluginNames()
{
  std::string names = "gazebo_ros_control";
  for (const std::string& file : Registry<PluginFile>::instance().names())  // "libgazebo_ros_x.so" -> "gazebo_ros_x"
    names += ", " + file.substr(3, file.size() - 6);
  return names;
}

std::string ModelPluginDescription::text(const std::string& key, const std::string& fallback) const
{
  auto it = params.find(key);
  return it == params.end() ? fallback : it->second;
}

double ModelPluginDescription::number(const std::string& key, double fallback) const
{
  auto it = params.find(key);
  if (it == params.end())
    return fallback;
  return xml::numbers(it->second, 1, "<" + key + "> of plugin '" + name + "' (" + filename + ")")[0];
}

urdf::Vector3 ModelPluginDescription::vector(const std::string& key, const urdf::Vector3& fallback) const
{
  auto it = params.find(key);
  if (it == params.end())
    return fallback;
  const std::string what = "<" + key + "> of plugin '" + name + "' (" + filename + ")";
  std::istringstream words(it->second);
  size_t count = 0;
  for (std::string word; words >> word;)
    ++count;
  const std::vector<double> v = xml::numbers(it->second, count == 1 ? 1 : 3, what);
  return v.size() == 1 ? urdf::Vector3(v[0], v[0], v[0]) : urdf::Vector3(v[0], v[1], v[2]);
}

bool ModelPluginDescription::flag(const std::string& key, bool fallback) const
{
  auto it = params.find(key);
  if (it == params.end())
    return fallback;
  if (it->second == "true" || it->second == "1")
    return true;
  if (it->second == "false" || it->second == "0")
    return false;
  throw DescriptionError("<" + key + "> of plugin '" + name + "' (" + filename + ") is '" + it->second +
                         "': give true or false");
}

std::string ControlPluginDescription::controlNamespace(const std::string& spawn_namespace) const
{
  return normaliseNamespace(givenControlNamespace(spawn_namespace));
}

namespace
{
// urdfdom reports why it refused a document, or what it left out of one it still accepted (an
// <inertial> with a mass of nan: the link then has none), through console_bridge; collect those
// lines so that our errors and warnings carry the parser's own message.
class CollectingOutputHandler : public console_bridge::OutputHandler
{
public:
  void log(const std::string& text, console_bridge::LogLevel level, const char*, int) override
  {
    if (level >= console_bridge::CONSOLE_BRIDGE_LOG_ERROR)
      errors.push_back(text);
    else if (level >= console_bridge::CONSOLE_BRIDGE_LOG_WARN)
      warnings.push_back(text);
  }
  std::vector<std::string> errors, warnings;
};

std::string joined(const std::vector<std::string>& lines)
{
  std::string out;
  for (const std::string& line : lines)
    out += (out.empty() ? "" : "; ") + line;
  return out;
}

// Refuses a URDF urdfdom could not read in full: what it skipped (an <inertial>, a <collision>)
// would silently change the robot.
urdf::ModelInterfaceSharedPtr parseWithUrdfdom(const std::string& urdf_xml, std::vector<std::string>& warnings)
{
  static std::mutex console_mutex;  // console_bridge's output handler is process-wide
  std::lock_guard<std::mutex> lock(console_mutex);
  CollectingOutputHandler handler;
  console_bridge::useOutputHandler(&handler);
  urdf::ModelInterfaceSharedPtr model = urdf::parseURDF(urdf_xml);
  console_bridge::restorePreviousOutputHandler();
  if (!model)
    throw DescriptionError("URDF parser: " +
                           (handler.errors.empty() && handler.warnings.empty() ? std::string("no reason given")
                                                                               : joined(handler.errors.empty() ? handler.warnings : handler.errors)));
  if (!handler.errors.empty())
    throw DescriptionError("URDF parser: " + joined(handler.errors) +
                           " (urdfdom went on without what it could not read; fix the URDF)");
  for (const std::string& line : handler.warnings)
    warnings.push_back("URDF parser: " + line);
  return model;
}

// What urdfdom accepts but no physics can use: a negative mass or moment of inertia, and a mass
// so large that single-precision contacts lose it (1/m below Bullet's epsilon: it falls through
// the floor).
void checkInertials(const urdf::ModelInterface& model)
{
  for (const auto& kv : model.links_)
  {
    const urdf::InertialSharedPtr& inertial = kv.second->inertial;
    if (!inertial)
      continue;
    std::ostringstream text;
    text << "link '" << kv.first << "': ";
    if (inertial->mass < 0)
      text << "<mass value=\"" << inertial->mass << "\"/> is negative";
    else if (inertial->mass > kMaxLinkMass)
      text << "<mass value=\"" << inertial->mass << "\"/> is more than the plant can hold on its contacts ("
           << kMaxLinkMass << " kg)";
    else if (inertial->ixx < 0 || inertial->iyy < 0 || inertial->izz < 0)
      text << "<inertia ixx=\"" << inertial->ixx << "\" iyy=\"" << inertial->iyy << "\" izz=\"" << inertial->izz
           << "\"/> has a negative moment";
    else if (std::max({inertial->ixx, inertial->iyy, inertial->izz, std::abs(inertial->ixy), std::abs(inertial->ixz),
                       std::abs(inertial->iyz)}) > kMaxLinkMass * kMaxLength * kMaxLength)
      text << "<inertia> has a component beyond " << kMaxLinkMass * kMaxLength * kMaxLength << " kg m^2";
    else
      continue;
    throw DescriptionError(text.str());
  }
}

// Lengths beyond kMaxLength overflow the plant's single-precision arithmetic (1e308 is infinite
// there, 1e30 squared too): the robot would start non-finite.
void checkLength(const urdf::Vector3& v, const std::string& what)
{
  if (std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)}) <= kMaxLength)
    return;
  std::ostringstream text;
  text << what << " " << v.x << " " << v.y << " " << v.z << " is beyond " << kMaxLength << " m";
  throw DescriptionError(text.str());
}

void checkGeometry(const urdf::GeometrySharedPtr& geometry, const std::string& what)
{
  if (!geometry)
    return;
  if (auto box = std::dynamic_pointer_cast<urdf::Box>(geometry))
    checkLength(box->dim, what + " <box size>");
  else if (auto cylinder = std::dynamic_pointer_cast<urdf::Cylinder>(geometry))
    checkLength(urdf::Vector3(cylinder->radius, cylinder->length, 0), what + " <cylinder radius length>");
  else if (auto sphere = std::dynamic_pointer_cast<urdf::Sphere>(geometry))
    checkLength(urdf::Vector3(sphere->radius, 0, 0), what + " <sphere radius>");
  else if (auto mesh = std::dynamic_pointer_cast<urdf::Mesh>(geometry))
    checkLength(mesh->scale, what + " <mesh scale>");
}

void checkLengths(const urdf::ModelInterface& model)
{
  for (const auto& kv : model.joints_)
    checkLength(kv.second->parent_to_joint_origin_transform.position, "joint '" + kv.first + "': <origin xyz>");
  for (const auto& kv : model.links_)
  {
    const std::string where = "link '" + kv.first + "': ";
    if (kv.second->inertial)
      checkLength(kv.second->inertial->origin.position, where + "<inertial><origin xyz>");
    for (const urdf::CollisionSharedPtr& c : kv.second->collision_array)
    {
      checkLength(c->origin.position, where + "<collision><origin xyz>");
      checkGeometry(c->geometry, where + "<collision>");
    }
  }
}

std::string normaliseInterface(const std::string& text, std::vector<std::string>& warnings)
{
  static const char* prefix = "hardware_interface/";
  if (text.rfind(prefix, 0) == 0)
    return text;
  if (text == "EffortJointInterface" || text == "VelocityJointInterface" || text == "PositionJointInterface")
  {
    warnings.push_back("Deprecated syntax, please prepend 'hardware_interface/' to '" + text +
                       "' within the <hardwareInterface> tag in joint transmissions.");
    return prefix + text;
  }
  return text;
}

void readTransmissions(const tinyxml2::XMLElement* robot, RobotDescription& out)
{
  for (auto* t = robot->FirstChildElement("transmission"); t; t = t->NextSiblingElement("transmission"))
  {
    const char* name = t->Attribute("name");
    auto* joint = t->FirstChildElement("joint");
    if (!joint || !joint->Attribute("name"))
    {
      out.warnings.push_back(std::string("transmission '") + (name ? name : "?") + "' has no <joint name=...>; ignored");
      continue;
    }
    // gazebo_ros_control reads the joint's interface; older files put it only on the actuator.
    const tinyxml2::XMLElement* iface = joint->FirstChildElement("hardwareInterface");
    if (!iface)
      if (auto* actuator = t->FirstChildElement("actuator"))
        iface = actuator->FirstChildElement("hardwareInterface");
    if (!iface || !iface->GetText())
    {
      out.warnings.push_back("transmission '" + std::string(name ? name : "?") + "' for joint '" +
                             joint->Attribute("name") + "' names no hardwareInterface; ignored");
      continue;
    }
    out.transmissions.push_back({name ? name : "", joint->Attribute("name"),
                                 normaliseInterface(xml::trimmed(iface->GetText()), out.warnings)});
  }
}

// One <sensor> of a <gazebo reference="LINK"> or <gazebo reference="JOINT"> block, or one <plugin>
// of a block without a reference.
struct GazeboBlockItem
{
  std::string link;  // the sensor's link (a joint's sensor: the joint's child); "" for a model plugin
  std::string xml;   // as written
  std::string what;  // "sensor 'NAME' of link 'LINK'", "plugin 'NAME' (FILE)"
  urdf::JointConstSharedPtr joint;  // a joint's sensor: that joint
};

// SDF's name of a URDF joint's type, as sdformat's URDF converter writes it.
const char* sdfJointType(const urdf::Joint& joint)
{
  switch (joint.type)
  {
    case urdf::Joint::REVOLUTE:
      return "revolute";
    case urdf::Joint::CONTINUOUS:
      return "continuous";
    case urdf::Joint::PRISMATIC:
      return "prismatic";
    default:
      return "fixed";
  }
}

// The items as one SDF model named as the robot (which a plugin's GetParent() finds): the model's
// plugins, and a link per sensor named as its URDF link (a joint per joint's sensor, named as its
// URDF joint, between its links), in the blocks' order.
std::string gazeboItemsAsSdf(const std::string& robot, const std::vector<const GazeboBlockItem*>& items)
{
  tinyxml2::XMLDocument doc;
  tinyxml2::XMLElement* sdf = doc.NewElement("sdf");
  sdf->SetAttribute("version", "1.6");
  doc.InsertEndChild(sdf);
  tinyxml2::XMLElement* model = sdf->InsertNewChildElement("model");
  model->SetAttribute("name", robot.c_str());
  std::string text;
  for (const GazeboBlockItem* item : items)
  {
    tinyxml2::XMLDocument piece;
    piece.Parse(item->xml.c_str());
    tinyxml2::XMLNode* parent = model;
    if (item->joint)
    {
      tinyxml2::XMLElement* joint = model->InsertNewChildElement("joint");
      joint->SetAttribute("name", item->joint->name.c_str());
      joint->SetAttribute("type", sdfJointType(*item->joint));
      joint->InsertNewChildElement("parent")->SetText(item->joint->parent_link_name.c_str());
      joint->InsertNewChildElement("child")->SetText(item->joint->child_link_name.c_str());
      parent = joint;
    }
    else if (!item->link.empty())
    {
      parent = model->InsertNewChildElement("link");
      parent->ToElement()->SetAttribute("name", item->link.c_str());
    }
    parent->InsertEndChild(piece.RootElement()->DeepClone(&doc));
  }
  tinyxml2::XMLPrinter printer;  // an element a line: sdformat's line numbers tell them apart
  doc.Print(&printer);
  return printer.CStr();
}

// The sensors and plugins of the robot's <gazebo> blocks, read by sdformat as Gazebo reads them (its
// URDF converter puts a block's <sensor>s in the link it references and the others' <plugin>s in the
// model). One that sdformat cannot read (a camera's <horizontal_fov> of 0, below the spec's 0.1) is
// left out with an error naming it, the robot going on without it.
void readGazeboSensorsAndPlugins(const tinyxml2::XMLElement* robot, RobotDescription& out)
{
  std::vector<GazeboBlockItem> items;
  for (auto* g = robot->FirstChildElement("gazebo"); g; g = g->NextSiblingElement("gazebo"))
  {
    const char* reference = g->Attribute("reference");
    // a joint's sensors are Gazebo's where it names no link (a link's name wins, as sdformat's)
    const urdf::JointConstSharedPtr joint =
        reference && !out.model->getLink(reference) ? out.model->getJoint(reference) : nullptr;
    if (reference && !out.model->getLink(reference) && !joint)
      continue;
    const char* tag = reference ? "sensor" : "plugin";
    for (auto* e = g->FirstChildElement(tag); e; e = e->NextSiblingElement(tag))
    {
      const std::string name = e->Attribute("name") ? e->Attribute("name") : "";
      const std::string what =
          !reference ? "plugin '" + name + "' (" + (e->Attribute("filename") ? e->Attribute("filename") : "") + ")"
                     : "sensor '" + name + "' of " + (joint ? "joint '" : "link '") + reference + "'";
      items.push_back({joint ? joint->child_link_name : reference ? reference : "", xml::printed(e), what, joint});
    }
  }
  if (items.empty())
    return;
  const sdf::Source source{"", out.base_dir};
  std::vector<const GazeboBlockItem*> read;
  for (const GazeboBlockItem& item : items)
    read.push_back(&item);
  sdf::Document doc;
  try
  {
    doc = sdf::readDocument(gazeboItemsAsSdf(out.model->getName(), read), source);
  }
  catch (const DescriptionError&)
  {
    read.clear();
    for (const GazeboBlockItem& item : items)
      try
      {
        sdf::readDocument(gazeboItemsAsSdf(out.model->getName(), {&item}), source);
        read.push_back(&item);
      }
      catch (const DescriptionError& e)
      {
        // (the lines are those of the item read alone: left out)
        out.errors.push_back(item.what + " in the URDF's <gazebo>: " + sdf::reasonLeftOut(e) +
                             (item.link.empty() ? "; it is not loaded" : "; it publishes nothing"));
      }
    if (read.empty())
      return;
    doc = sdf::readDocument(gazeboItemsAsSdf(out.model->getName(), read), source);
  }
  const sdf::ElementPtr model = sdf::child(doc.root(), "model");
  for (sdf::ElementPtr e = model->GetFirstElement(); e; e = e->GetNextElement())
    if (e->GetName() == "plugin")
      readModelPlugin(e, out);
    else if (e->GetName() == "link")
      readSensors(e, sdf::attribute(e, "name"), out);
    else if (e->GetName() == "joint")
      readSensors(e, sdf::childText(e, "child", ""), out, sdf::attribute(e, "name"));
}

void readGazeboExtensions(const tinyxml2::XMLElement* robot, RobotDescription& out)
{
  for (auto* g = robot->FirstChildElement("gazebo"); g; g = g->NextSiblingElement("gazebo"))
  {
    const char* reference = g->Attribute("reference");
    if (!reference)
    {
      // The robot-level <static>, as Gazebo's URDF converter copies it to the model.
      const std::string is_static = xml::childText(g, "static", "");
      if (!is_static.empty())
        out.is_static = is_static == "true" || is_static == "1";
      continue;
    }
    std::string link = reference;
    if (!out.model->getLink(link))
    {
      if (!out.model->getJoint(link))
        out.warnings.push_back("<gazebo reference=\"" + link + "\"> names no link of the robot; ignored");
      else if (xml::childText(g, "provideFeedback", "") == "true" || xml::childText(g, "provideFeedback", "") == "1")
        out.joint_feedback.insert(link);  // the joint's other tags (ODE's stops, CFM) are not used
      continue;
    }
    SurfaceDescription& surface = out.surfaces[link];
    surface.urdf = true;
    for (const char* tag : {"mu1", "mu2", "kp", "kd"})
      if (g->FirstChildElement(tag))
        surface.given = true;
    surface.mu1 = xml::childDouble(g, "mu1", surface.mu1);
    surface.mu2 = xml::childDouble(g, "mu2", surface.mu2);
    surface.kp = xml::childDouble(g, "kp", surface.kp);
    surface.kd = xml::childDouble(g, "kd", surface.kd);
  }
  readGazeboSensorsAndPlugins(robot, out);
}

}  // namespace

RobotDescription parseRobotDescription(const std::string& urdf_xml, const std::string& base_dir)
{
  tinyxml2::XMLDocument doc;
  if (doc.Parse(urdf_xml.c_str(), urdf_xml.size()) != tinyxml2::XML_SUCCESS)
    throw DescriptionError(std::string("URDF is not well-formed XML: ") + doc.ErrorStr());
  const tinyxml2::XMLElement* robot = doc.FirstChildElement("robot");
  if (!robot)
    throw DescriptionError("URDF has no <robot> root element");

  RobotDescription out;
  out.base_dir = base_dir;
  out.model = parseWithUrdfdom(urdf_xml, out.warnings);
  checkInertials(*out.model);
  checkLengths(*out.model);
  readTransmissions(robot, out);
  readGazeboExtensions(robot, out);
  return out;
}

VisualMaterial visualMaterial(const RobotDescription& robot, const std::string& link, size_t index,
                              const urdf::Visual& visual)
{
  const auto sdf = robot.visual_materials.find(link);
  if (sdf != robot.visual_materials.end() && index < sdf->second.size())
    return sdf->second[index];
  if (visual.material)
    return VisualMaterial::colour({float(visual.material->color.r), float(visual.material->color.g),
                                   float(visual.material->color.b), float(visual.material->color.a)});
  return VisualMaterial();
}

}  // namespace bullet_plant
