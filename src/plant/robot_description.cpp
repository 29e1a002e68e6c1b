#include "bullet_plant/robot_description.h"

#include <mutex>

#include <console_bridge/console.h>
#include <tinyxml2.h>
#include <urdf_parser/urdf_parser.h>

#include "xml_util.h"

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

PluginKind pluginKind(const std::string& filename)
{
  static const std::map<std::string, PluginKind> kinds = {
      {"libgazebo_ros_laser.so", PluginKind::Laser},          {"libgazebo_ros_gpu_laser.so", PluginKind::Laser},
      {"libgazebo_ros_camera.so", PluginKind::Camera},        {"libgazebo_ros_openni_kinect.so", PluginKind::OpenniKinect},
      {"libgazebo_ros_imu_sensor.so", PluginKind::ImuSensor}, {"libgazebo_ros_imu.so", PluginKind::ImuModel},
      {"libgazebo_ros_p3d.so", PluginKind::P3d}};
  auto it = kinds.find(filename);
  return it == kinds.end() ? PluginKind::Unknown : it->second;
}

namespace
{
// urdfdom reports why it refused a document through console_bridge; collect those lines so the
// error we raise carries the parser's own message.
class CollectingOutputHandler : public console_bridge::OutputHandler
{
public:
  void log(const std::string& text, console_bridge::LogLevel level, const char*, int) override
  {
    if (level >= console_bridge::CONSOLE_BRIDGE_LOG_WARN)
      lines.push_back(text);
  }
  std::vector<std::string> lines;
};

urdf::ModelInterfaceSharedPtr parseWithUrdfdom(const std::string& urdf_xml)
{
  static std::mutex console_mutex;  // console_bridge's output handler is process-wide
  std::lock_guard<std::mutex> lock(console_mutex);
  CollectingOutputHandler handler;
  console_bridge::useOutputHandler(&handler);
  urdf::ModelInterfaceSharedPtr model = urdf::parseURDF(urdf_xml);
  console_bridge::restorePreviousOutputHandler();
  if (!model)
  {
    std::string reason = handler.lines.empty() ? "no reason given" : handler.lines.front();
    for (size_t i = 1; i < handler.lines.size(); ++i)
      reason += "; " + handler.lines[i];
    throw DescriptionError("URDF parser: " + reason);
  }
  return model;
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

void readControlPlugin(const tinyxml2::XMLElement* plugin, RobotDescription& out)
{
  ControlPluginDescription& c = out.control;
  c.present = true;
  c.robot_namespace = xml::childText(plugin, "robotNamespace", "");
  c.robot_param = xml::childText(plugin, "robotParam", "robot_description");
  c.control_period = xml::childDouble(plugin, "controlPeriod", 0.0);
  c.e_stop_topic = xml::childText(plugin, "eStopTopic", "");
  c.legacy_mode_ns_given = plugin->FirstChildElement("legacyModeNS") != nullptr;
  const std::string legacy = xml::childText(plugin, "legacyModeNS", "true");
  c.legacy_mode_ns = legacy == "true" || legacy == "1";
  c.sim_type = xml::childText(plugin, "robotSimType", c.sim_type);
  if (c.sim_type != ControlPluginDescription().sim_type)
  {
    // gazebo_ros_control cannot load such a class and leaves the robot without a controller manager.
    out.errors.push_back("gazebo_ros_control: robotSimType '" + c.sim_type + "' is not available (the plant has "
                         "only gazebo_ros_control/DefaultRobotHWSim); the robot gets no controller manager. Remove "
                         "<robotSimType> or set it to gazebo_ros_control/DefaultRobotHWSim");
    c.present = false;
  }
}

void readPluginBlock(const tinyxml2::XMLElement* plugin, SensorDescription& d)
{
  d.plugin_name = plugin->Attribute("name") ? plugin->Attribute("name") : "";
  d.plugin_filename = plugin->Attribute("filename") ? plugin->Attribute("filename") : "";
  d.plugin_kind = pluginKind(d.plugin_filename);
  for (auto* p = plugin->FirstChildElement(); p; p = p->NextSiblingElement())
    d.plugin[p->Name()] = p->GetText() ? xml::trimmed(p->GetText()) : "";
}

std::string unknownPluginWarning(const std::string& name, const std::string& filename, const std::string& where)
{
  return "plugin '" + name + "' (" + filename + ")" + where +
         " is not simulated by the plant and is ignored (simulated: gazebo_ros_control, gazebo_ros_laser, "
         "gazebo_ros_gpu_laser, gazebo_ros_camera, gazebo_ros_openni_kinect, gazebo_ros_imu_sensor, gazebo_ros_imu, "
         "gazebo_ros_p3d)";
}

// gazebo_ros_imu and gazebo_ros_p3d: model plugins that follow one link (bodyName).
void readModelPlugin(const tinyxml2::XMLElement* plugin, RobotDescription& out)
{
  SensorDescription d;
  readPluginBlock(plugin, d);
  d.model_plugin = true;
  d.name = d.plugin_name.empty() ? d.plugin_filename : d.plugin_name;
  d.type = d.plugin_kind == PluginKind::P3d ? "p3d" : "imu";
  d.link = d.pluginParam("bodyName");
  if (d.link.empty() || !out.model->getLink(d.link))
  {
    out.errors.push_back("plugin '" + d.name + "' (" + d.plugin_filename + ") " +
                         (d.link.empty() ? "has no <bodyName>" : "names bodyName '" + d.link + "', which is no link of the robot") +
                         "; it publishes nothing. Set <bodyName> to a link of the URDF");
    return;
  }
  const std::string frame = d.pluginParam("frameName", "world");
  if (d.plugin_kind == PluginKind::P3d && frame != "world" && frame != "/world" && frame != "map" && frame != "/map" &&
      !out.model->getLink(frame))
  {
    out.errors.push_back("gazebo_ros_p3d plugin: frameName: " + frame + " does not exist, will not publish pose");
    return;
  }
  if (d.plugin_kind == PluginKind::P3d && d.pluginParam("topicName").empty())
  {
    out.errors.push_back("plugin '" + d.name + "' (libgazebo_ros_p3d.so) has no <topicName>; it publishes nothing");
    return;
  }
  out.sensors.push_back(d);
}

void readNoise(const tinyxml2::XMLElement* parent, Noise& noise)
{
  auto* n = parent ? parent->FirstChildElement("noise") : nullptr;
  if (!n)
    return;
  noise.gaussian = xml::childText(n, "type", "gaussian") == "gaussian";
  noise.mean = xml::childDouble(n, "mean", 0.0);
  noise.stddev = xml::childDouble(n, "stddev", 0.0);
}

SensorDescription readSensor(const tinyxml2::XMLElement* s, const std::string& link)
{
  SensorDescription d;
  d.link = link;
  d.name = s->Attribute("name") ? s->Attribute("name") : "";
  d.type = s->Attribute("type") ? s->Attribute("type") : "";
  d.update_rate = xml::childDouble(s, "update_rate", 0.0);
  d.pose = xml::parseSdfPose(xml::childText(s, "pose", ""));
  if (auto* ray = s->FirstChildElement("ray"))
  {
    if (auto* h = xml::child(ray, "scan/horizontal"))
    {
      d.horizontal_samples = static_cast<int>(xml::childDouble(h, "samples", 1));
      d.horizontal_min_angle = xml::childDouble(h, "min_angle", 0.0);
      d.horizontal_max_angle = xml::childDouble(h, "max_angle", 0.0);
    }
    if (auto* v = xml::child(ray, "scan/vertical"))
    {
      d.vertical_samples = static_cast<int>(xml::childDouble(v, "samples", 1));
      d.vertical_min_angle = xml::childDouble(v, "min_angle", 0.0);
      d.vertical_max_angle = xml::childDouble(v, "max_angle", 0.0);
    }
    if (auto* r = ray->FirstChildElement("range"))
    {
      d.range_min = xml::childDouble(r, "min", 0.0);
      d.range_max = xml::childDouble(r, "max", 0.0);
      d.range_resolution = xml::childDouble(r, "resolution", 0.0);
    }
    readNoise(ray, d.noise);
  }
  if (auto* cam = s->FirstChildElement("camera"))
  {
    d.horizontal_fov = xml::childDouble(cam, "horizontal_fov", 1.047);
    if (auto* image = cam->FirstChildElement("image"))
    {
      d.image_width = static_cast<int>(xml::childDouble(image, "width", 320));
      d.image_height = static_cast<int>(xml::childDouble(image, "height", 240));
      d.image_format = xml::childText(image, "format", "R8G8B8");
    }
    if (auto* clip = cam->FirstChildElement("clip"))
    {
      d.clip_near = xml::childDouble(clip, "near", 0.1);
      d.clip_far = xml::childDouble(clip, "far", 100.0);
    }
    readNoise(cam, d.noise);
  }
  if (auto* plugin = s->FirstChildElement("plugin"))
    readPluginBlock(plugin, d);
  return d;
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
      for (auto* p = g->FirstChildElement("plugin"); p; p = p->NextSiblingElement("plugin"))
      {
        const std::string filename = p->Attribute("filename") ? p->Attribute("filename") : "";
        const PluginKind kind = pluginKind(filename);
        if (filename == "libgazebo_ros_control.so")
          readControlPlugin(p, out);
        else if (kind == PluginKind::ImuModel || kind == PluginKind::P3d)
          readModelPlugin(p, out);
        else
          out.warnings.push_back(unknownPluginWarning(p->Attribute("name") ? p->Attribute("name") : "", filename, ""));
      }
      continue;
    }
    std::string link = reference;
    if (!out.model->getLink(link))
    {
      if (!out.model->getJoint(link))  // joint references carry joint tags we do not use
        out.warnings.push_back("<gazebo reference=\"" + link + "\"> names no link of the robot; ignored");
      continue;
    }
    SurfaceDescription& surface = out.surfaces[link];
    for (const char* tag : {"mu1", "mu2", "kp", "kd"})
      if (g->FirstChildElement(tag))
        surface.given = true;
    surface.mu1 = xml::childDouble(g, "mu1", surface.mu1);
    surface.mu2 = xml::childDouble(g, "mu2", surface.mu2);
    surface.kp = xml::childDouble(g, "kp", surface.kp);
    surface.kd = xml::childDouble(g, "kd", surface.kd);
    for (auto* s = g->FirstChildElement("sensor"); s; s = s->NextSiblingElement("sensor"))
    {
      out.sensors.push_back(readSensor(s, link));
      SensorDescription& d = out.sensors.back();
      if (d.plugin_kind == PluginKind::Unknown || d.plugin_kind == PluginKind::ImuModel || d.plugin_kind == PluginKind::P3d)
        out.warnings.push_back(unknownPluginWarning(d.plugin_name, d.plugin_filename, " of sensor '" + d.name + "'"));
      if (d.type == "imu" && d.plugin_kind == PluginKind::ImuSensor && !d.hasPluginParam("frameName"))
      {
        out.errors.push_back("sensor '" + d.name + "': gazebo_ros_imu_sensor needs <frameName> (\"missing <frameName>, "
                             "cannot proceed\"); it publishes nothing");
        d.plugin_kind = PluginKind::None;
      }
    }
  }
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
  out.model = parseWithUrdfdom(urdf_xml);
  readTransmissions(robot, out);
  readGazeboExtensions(robot, out);
  return out;
}

}  // namespace bullet_plant
