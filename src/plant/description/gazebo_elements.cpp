#include "description/gazebo_elements.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "bullet_plant/geometry.h"
#include "description/sdf_elements.h"
#include "description/xml_util.h"

namespace bullet_plant
{
namespace
{
void readControlPlugin(const sdf::ElementPtr& plugin, RobotDescription& out)
{
  ControlPluginDescription& c = out.control;
  c.present = true;
  c.robot_namespace = sdf::childText(plugin, "robotNamespace", "");
  c.robot_param = sdf::childText(plugin, "robotParam", "robot_description");
  c.control_period = sdf::childDouble(plugin, "controlPeriod", 0.0);
  c.e_stop_topic = sdf::childText(plugin, "eStopTopic", "");
  c.legacy_mode_ns_given = sdf::child(plugin, "legacyModeNS") != nullptr;
  const std::string legacy = sdf::childText(plugin, "legacyModeNS", "true");
  c.legacy_mode_ns = legacy == "true" || legacy == "1";
  c.sim_type = sdf::childText(plugin, "robotSimType", c.sim_type);
  if (c.sim_type != ControlPluginDescription().sim_type)
  {
    // gazebo_ros_control cannot load such a class and leaves the robot without a controller manager.
    out.errors.push_back("gazebo_ros_control: robotSimType '" + c.sim_type + "' is not available (the plant has "
                         "only gazebo_ros_control/DefaultRobotHWSim); the robot gets no controller manager. Remove "
                         "<robotSimType> or set it to gazebo_ros_control/DefaultRobotHWSim");
    c.present = false;
  }
}

void readPluginBlock(const sdf::ElementPtr& plugin, SensorDescription& d)
{
  d.plugin_name = sdf::attribute(plugin, "name");
  d.plugin_filename = sdf::attribute(plugin, "filename");
  d.plugin_given = true;
  d.plugin_file = findPluginFile(d.plugin_filename);
  for (sdf::ElementPtr p = plugin->GetFirstElement(); p; p = p->GetNextElement())
    d.plugin[p->GetName()] = sdf::text(p);
}

std::string unknownPluginWarning(const std::string& name, const std::string& filename, const std::string& where)
{
  return "plugin '" + name + "' (" + filename + ")" + where + " is not simulated by the plant and is ignored (simulated: " +
         simulatedPluginNames() + ")";
}

// gazebo_ros_imu and gazebo_ros_p3d: model plugins that follow one link (bodyName).
void readLinkSensorPlugin(const sdf::ElementPtr& plugin, RobotDescription& out)
{
  SensorDescription d;
  readPluginBlock(plugin, d);
  d.model_plugin = true;
  d.name = d.plugin_name.empty() ? d.plugin_filename : d.plugin_name;
  d.type = d.plugin_file->sensor_type;
  d.link = d.pluginParam("bodyName");
  if (d.link.empty() || !out.model->getLink(d.link))
  {
    out.errors.push_back("plugin '" + d.name + "' (" + d.plugin_filename + ") " +
                         (d.link.empty() ? "has no <bodyName>" : "names bodyName '" + d.link + "', which is no link of the robot") +
                         "; it publishes nothing. Set <bodyName> to a link of the URDF");
    return;
  }
  const std::string frame = d.pluginParam("frameName", "world");
  if (d.type == "p3d" && frame != "world" && frame != "/world" && frame != "map" && frame != "/map" &&
      !out.model->getLink(frame))
  {
    out.errors.push_back("gazebo_ros_p3d plugin: frameName: " + frame + " does not exist, will not publish pose");
    return;
  }
  if (d.type == "p3d" && d.pluginParam("topicName").empty())
  {
    out.errors.push_back("plugin '" + d.name + "' (libgazebo_ros_p3d.so) has no <topicName>; it publishes nothing");
    return;
  }
  out.sensors.push_back(d);
}

void readNoise(const sdf::ElementPtr& parent, Noise& noise)
{
  sdf::ElementPtr n = sdf::child(parent, "noise");
  if (!n)
    return;
  noise.gaussian = sdf::childText(n, "type", "gaussian") == "gaussian";
  noise.mean = sdf::childDouble(n, "mean", 0.0);
  noise.stddev = sdf::childDouble(n, "stddev", 0.0);
}

// A count (samples, pixels) as written, in an int: beyond its range the nearest int (converting
// would be undefined), not a number -1, for the checks at spawn to refuse.
int countOf(double written)
{
  if (std::isnan(written))
    return -1;
  return int(std::max(double(std::numeric_limits<int>::min()), std::min(written, double(std::numeric_limits<int>::max()))));
}

// A <camera>'s <distortion>. A coefficient or centre that is not a finite number is 0 (0.5 for
// the centre), named in `problems`: Gazebo would warp the frame into nothing.
void readDistortion(const sdf::ElementPtr& cam, CameraDistortion& out, std::vector<std::string>& problems)
{
  sdf::ElementPtr d = sdf::child(cam, "distortion");
  if (!d)
    return;
  out.given = true;
  const char* names[] = {"k1", "k2", "k3", "p1", "p2"};
  double* values[] = {&out.k1, &out.k2, &out.k3, &out.p1, &out.p2};
  for (int i = 0; i < 5; ++i)
  {
    *values[i] = sdf::childDouble(d, names[i], 0.0);
    if (!std::isfinite(*values[i]))
    {
      problems.push_back(std::string("<distortion><") + names[i] + "> is not a finite number; it is taken as 0");
      *values[i] = 0.0;
    }
  }
  std::istringstream center(sdf::childText(d, "center", "0.5 0.5"));
  double x = 0.5, y = 0.5;
  if (!(center >> x >> y) || !std::isfinite(x) || !std::isfinite(y))
  {
    problems.push_back("<distortion><center> is not two finite numbers; it is taken as 0.5 0.5");
    x = y = 0.5;
  }
  out.center_x = x;
  out.center_y = y;
}

// A <camera>: its field of view, image, clip, noise and distortion.
void readCamera(const sdf::ElementPtr& cam, SensorDescription& d)
{
  d.horizontal_fov = sdf::childDouble(cam, "horizontal_fov", 1.047);
  if (sdf::ElementPtr image = sdf::child(cam, "image"))
  {
    d.image_width = countOf(sdf::childDouble(image, "width", 320));
    d.image_height = countOf(sdf::childDouble(image, "height", 240));
    d.image_format = sdf::childText(image, "format", "R8G8B8");
  }
  if (sdf::ElementPtr clip = sdf::child(cam, "clip"))
  {
    d.clip_near = sdf::childDouble(clip, "near", 0.1);
    d.clip_far = sdf::childDouble(clip, "far", 100.0);
  }
  readNoise(cam, d.noise);
  readDistortion(cam, d.distortion, d.description_problems);
}

SensorDescription readSensor(const sdf::ElementPtr& s, const std::string& link)
{
  SensorDescription d;
  d.link = link;
  d.name = sdf::attribute(s, "name");
  d.type = sdf::attribute(s, "type");
  d.update_rate = sdf::childDouble(s, "update_rate", 0.0);
  d.pose = sdf::pose(s);
  if (sdf::ElementPtr ray = sdf::child(s, "ray"))
  {
    if (sdf::ElementPtr h = sdf::child(ray, "scan/horizontal"))
    {
      d.horizontal_samples = countOf(sdf::childDouble(h, "samples", 1));
      d.horizontal_min_angle = sdf::childDouble(h, "min_angle", 0.0);
      d.horizontal_max_angle = sdf::childDouble(h, "max_angle", 0.0);
    }
    if (sdf::ElementPtr v = sdf::child(ray, "scan/vertical"))
    {
      d.vertical_samples = countOf(sdf::childDouble(v, "samples", 1));
      d.vertical_min_angle = sdf::childDouble(v, "min_angle", 0.0);
      d.vertical_max_angle = sdf::childDouble(v, "max_angle", 0.0);
    }
    if (sdf::ElementPtr r = sdf::child(ray, "range"))
    {
      d.range_min = sdf::childDouble(r, "min", 0.0);
      d.range_max = sdf::childDouble(r, "max", 0.0);
      d.range_resolution = sdf::childDouble(r, "resolution", 0.0);
    }
    readNoise(ray, d.noise);
  }
  if (sdf::ElementPtr sonar = sdf::child(s, "sonar"))
  {
    d.range_min = sdf::childDouble(sonar, "min", 0.0);  // sonar.sdf's defaults
    d.range_max = sdf::childDouble(sonar, "max", 1.0);
    d.sonar_radius = sdf::childDouble(sonar, "radius", 0.5);
    d.sonar_geometry = sdf::childText(sonar, "geometry", "cone");
  }
  if (sdf::ElementPtr cam = sdf::child(s, "camera"))
    readCamera(cam, d);
  if (sdf::ElementPtr contact = sdf::child(s, "contact"))
    for (sdf::ElementPtr c = sdf::child(contact, "collision"); c; c = c->GetNextElement("collision"))
      d.contact_collisions.push_back(sdf::text(c));
  if (sdf::ElementPtr plugin = sdf::child(s, "plugin"))
  {
    readPluginBlock(plugin, d);
    // A file found on the plugin paths is loaded as Gazebo would, even where the plant has its own
    // plugin of that name (readModelPlugin's rule).
    d.library = findGazeboPluginLibrary(d.plugin_filename);
    if (!d.library.empty())
    {
      d.plugin_file = nullptr;
      d.element = s;
      d.plugin_element = plugin;
      d.document = sdf::root(s);
    }
  }
  return d;
}

// A <sensor type="multicamera">: one camera per <camera>, sharing the sensor's rate and plugin.
std::vector<SensorDescription> readMulticamera(const sdf::ElementPtr& s, const std::string& link)
{
  std::vector<SensorDescription> cameras;
  for (sdf::ElementPtr cam = sdf::child(s, "camera"); cam; cam = cam->GetNextElement("camera"))
  {
    SensorDescription d = readSensor(s, link);
    const SensorDescription defaults;
    d.type = "camera";
    d.image_width = defaults.image_width;
    d.image_height = defaults.image_height;
    d.image_format = defaults.image_format;
    d.clip_near = defaults.clip_near;
    d.clip_far = defaults.clip_far;
    d.noise = defaults.noise;
    d.distortion = defaults.distortion;
    d.description_problems = defaults.description_problems;
    readCamera(cam, d);
    d.multicamera_camera = sdf::attribute(cam, "name");
    d.name += "::" + d.multicamera_camera;
    d.pose = compose(d.pose, sdf::pose(cam));
    cameras.push_back(std::move(d));
  }
  return cameras;
}

}  // namespace

void readSensors(const sdf::ElementPtr& parent, const std::string& link, RobotDescription& out,
                 const std::string& joint)
{
  std::vector<SensorDescription> sensors;
  for (sdf::ElementPtr s = sdf::child(parent, "sensor"); s; s = s->GetNextElement("sensor"))
  {
    if (sdf::attribute(s, "type") != "multicamera")
      sensors.push_back(readSensor(s, link));
    else
      for (SensorDescription& camera : readMulticamera(s, link))
        sensors.push_back(std::move(camera));
  }
  for (SensorDescription& sensor : sensors)
  {
    out.sensors.push_back(std::move(sensor));
    SensorDescription& d = out.sensors.back();
    d.joint = joint;
    for (const std::string& problem : d.description_problems)
      out.warnings.push_back("sensor '" + d.name + "': " + problem);
    if (d.plugin_given && d.library.empty() && (!d.plugin_file || d.plugin_file->role != PluginRole::Sensor))
    {
      out.warnings.push_back(unknownPluginWarning(d.plugin_name, d.plugin_filename, " of sensor '" + d.name + "'"));
      d.plugin_file = nullptr;  // a model plugin's file in a <sensor> is no sensor plugin
    }
    const std::string refusal = d.plugin_file && d.plugin_file->refusal ? d.plugin_file->refusal(d) : "";
    if (!refusal.empty())
    {
      out.errors.push_back("sensor '" + d.name + "': " + refusal + "; it publishes nothing");
      d.plugin_file = nullptr;
    }
  }
}

void readModelPlugin(const sdf::ElementPtr& p, RobotDescription& out)
{
  const std::string filename = sdf::attribute(p, "filename");
  const PluginFile* file = findPluginFile(filename);
  // A library found on the plugin paths is loaded as Gazebo would, even where the plant has its own
  // plugin of that name: whoever built upstream's runs upstream's (gazebo_ros_control stays the
  // plant's, its hardware layer being the plant's own).
  const std::string library = filename == "libgazebo_ros_control.so" ? "" : findGazeboPluginLibrary(filename);
  if (library.empty() && filename == "libgazebo_ros_control.so")
    readControlPlugin(p, out);
  else if (library.empty() && file && file->role == PluginRole::LinkSensor)
    readLinkSensorPlugin(p, out);
  else if (!library.empty() || (file && file->role == PluginRole::Model))
  {
    ModelPluginDescription d;
    d.name = sdf::attribute(p, "name");
    d.filename = filename;
    for (sdf::ElementPtr e = p->GetFirstElement(); e; e = e->GetNextElement())
      d.params[e->GetName()] = sdf::text(e);
    if (!library.empty())
    {
      d.library = library;
      d.element = p;
      d.document = sdf::root(p);
    }
    out.model_plugins.push_back(std::move(d));
  }
  else
    out.warnings.push_back(unknownPluginWarning(sdf::attribute(p, "name"), filename, ""));
}

}  // namespace bullet_plant
