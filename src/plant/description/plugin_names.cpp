// The gazebo_ros plugins' naming rules, by plugin (docs/interfaces.md section 11).
#include "bullet_plant/plugin_names.h"

#include "bullet_plant/params.h"

namespace bullet_plant
{
namespace
{
// Its registered file's naming rules; the default ones for a sensor without a simulated plugin.
PluginNaming namingOf(const SensorDescription& d) { return d.plugin_file ? d.plugin_file->naming : PluginNaming::Default; }

PluginNaming namingOf(const ModelPluginDescription& d)
{
  const PluginFile* file = findPluginFile(d.filename);
  return file ? file->naming : PluginNaming::Default;
}

std::string withoutLeadingSlash(const std::string& name) { return !name.empty() && name[0] == '/' ? name.substr(1) : name; }

std::string withoutTrailingSlashes(std::string name)
{
  while (!name.empty() && name.back() == '/')
    name.pop_back();
  return name;
}

// gazebo_ros_camera and gazebo_ros_openni_kinect put relative topics under <cameraName>;
// gazebo_ros_multicamera under <cameraName>/left or /right (an empty <cameraName>: left, right).
std::string underCameraName(const SensorDescription& d, const std::string& topic)
{
  std::string camera = d.pluginParam("cameraName");
  if (namingOf(d) == PluginNaming::MultiCamera)
    camera = camera.empty() ? multicameraSide(d) : camera + "/" + multicameraSide(d);
  if (!topic.empty() && topic[0] == '/')
    return topic;
  return camera.empty() ? topic : camera + "/" + topic;
}

// Whose rules name a sensor: its type's plugin family, as the plant builds its sensor class from
// the type (a <plugin> of another family is refused at load by the node).
enum class Family { Laser, Range, Velodyne, BlockLaser, HectorSonar, Camera, ImuSensor, ImuModel, P3d, Bumper, Other };

Family familyOf(const SensorDescription& d)
{
  if (d.type == "ray" || d.type == "gpu_ray")
    switch (namingOf(d))
    {
      case PluginNaming::Range:
        return Family::Range;
      case PluginNaming::Velodyne:
        return Family::Velodyne;
      case PluginNaming::BlockLaser:
        return Family::BlockLaser;
      case PluginNaming::HectorSonar:
        return Family::HectorSonar;
      default:
        return Family::Laser;
    }
  if (d.type == "camera" || d.type == "depth")
    return Family::Camera;
  if (d.type == "imu")
    return d.model_plugin ? Family::ImuModel : Family::ImuSensor;
  if (d.type == "p3d")
    return Family::P3d;
  if (d.type == "contact")
    return Family::Bumper;
  return Family::Other;
}

// Model plugins (and gazebo_ros_imu_sensor) take "<robotNamespace>/" as their namespace, so an
// empty element means the root, not the model's name as for the laser and camera plugins.
std::string namespaceOfModelPlugin(const SensorDescription& d, const std::string& spawn_namespace,
                                   const std::string& fallback)
{
  if (d.hasPluginParam("robotNamespace"))
    return d.plugin.at("robotNamespace").empty() ? "/" : d.plugin.at("robotNamespace");
  return spawn_namespace.empty() ? fallback : spawn_namespace;
}
}  // namespace

std::string resolveTfFrame(const std::string& prefix, const std::string& frame)
{
  if (!frame.empty() && frame[0] == '/')
    return frame.substr(1);
  if (prefix.empty())
    return frame;
  return (prefix[0] == '/' ? prefix.substr(1) : prefix) + "/" + frame;
}

std::string pluginNamespace(const SensorDescription& d, const std::string& spawn_namespace, const std::string& model_name)
{
  switch (familyOf(d))
  {
    case Family::ImuSensor:  // without any namespace: "/<model name>/"
      return namespaceOfModelPlugin(d, spawn_namespace, "/" + model_name);
    case Family::ImuModel:
    case Family::P3d:
    case Family::Range:
    case Family::Velodyne:
    case Family::BlockLaser:
    case Family::HectorSonar:
    case Family::Bumper:
      return namespaceOfModelPlugin(d, spawn_namespace, "");
    default:
      if (d.hasPluginParam("robotNamespace"))  // GetRobotNamespace: an empty element means the model's name
        return d.plugin.at("robotNamespace").empty() ? model_name : d.plugin.at("robotNamespace");
      return spawn_namespace;
  }
}

std::string pluginFrameId(const SensorDescription& d, const std::string& tf_prefix)
{
  switch (familyOf(d))
  {
    case Family::Laser:  // no <frameName> means "/world"
    case Family::Range:
    case Family::Velodyne:
    case Family::BlockLaser:
      return resolveTfFrame(tf_prefix, d.pluginParam("frameName", "/world"));
    case Family::HectorSonar:  // as given, a leading '/' kept (tf2 consumers refuse one: give <frameId>)
      return d.pluginParam("frameId", "/sonar_link");
    case Family::ImuSensor:  // frameName as given, without a leading '/' (tf2 refuses it)
      return withoutLeadingSlash(d.pluginParam("frameName", ""));
    case Family::ImuModel:  // default bodyName
      return withoutLeadingSlash(d.pluginParam("frameName", d.link));
    case Family::P3d:
    case Family::Bumper:
      return resolveTfFrame(tf_prefix, d.pluginParam("frameName", "world"));
    default:
      // Cameras: tf::resolve(tf_prefix, frameName). A camera without <frameName> would get
      // "tf_prefix/" from gazebo_ros_camera, which no tf consumer accepts: its link instead.
      return resolveTfFrame(tf_prefix, d.pluginParam("frameName", d.link));
  }
}

std::string modelPluginNamespace(const ModelPluginDescription& d, const std::string& spawn_namespace,
                                 const std::string& model_name)
{
  const std::string ns = d.has("robotNamespace") ? d.text("robotNamespace", "") : spawn_namespace;
  switch (namingOf(d))
  {
    case PluginNaming::GazeboRos:  // diff_drive, tricycle_drive
    case PluginNaming::ModelNamespace:  // joint_state_publisher
      return ns.empty() ? model_name : ns;
    default:  // skid_steer_drive, planar_move, the mimic joint plugin: "" is the global namespace
      return ns;
  }
}

namespace
{
// NS/tf_prefix, then each parent's, then /tf_prefix: where ROS's searchParam looks from NS.
std::vector<std::string> tfPrefixSearchKeys(const std::string& plugin_namespace)
{
  std::vector<std::string> keys;
  std::string ns = withoutTrailingSlashes(plugin_namespace);
  ns.erase(0, ns.find_first_not_of('/'));
  if (!ns.empty())
    ns = "/" + ns;
  while (true)
  {
    keys.push_back(ns + "/tf_prefix");
    if (ns.empty())
      break;
    ns = ns.substr(0, ns.rfind('/'));
  }
  return keys;
}
}  // namespace

std::vector<std::string> tfPrefixParamKeys(const ModelPluginDescription& d, const std::string& plugin_namespace)
{
  if (!d.library.empty() || namingOf(d) != PluginNaming::GazeboRos)
    return {};
  return tfPrefixSearchKeys(plugin_namespace);
}

std::string searchedTfPrefix(const std::string& plugin_namespace, const Param& params)
{
  for (const std::string& key : tfPrefixSearchKeys(plugin_namespace))
    if (const Param* found = params.find(key.substr(1)))  // the tree's paths are relative
      return found->type() == Param::Type::String ? found->asString() : "";
  return "";
}

std::string modelPluginTfPrefix(const ModelPluginDescription& d, const std::string& plugin_namespace,
                                const Param& params)
{
  return tfPrefixParamKeys(d, plugin_namespace).empty() ? "" : searchedTfPrefix(plugin_namespace, params);
}

std::string multicameraSide(const SensorDescription& d)
{
  if (d.multicamera_camera.find("left") != std::string::npos)
    return "left";
  return d.multicamera_camera.find("right") != std::string::npos ? "right" : "";
}

std::string pluginTopic(const SensorDescription& d, PluginTopic which)
{
  switch (familyOf(d))
  {
    case Family::Laser:  // no <topicName> means "/world" (sic)
      return d.pluginParam("topicName", "/world");
    case Family::Range:
      return d.pluginParam("topicName", "/range");
    case Family::Velodyne:
      return d.pluginParam("topicName", "/points");
    case Family::BlockLaser:  // no <topicName> means "/world" (sic), as the laser's
      return d.pluginParam("topicName", "/world");
    case Family::HectorSonar:
      return d.pluginParam("topicName", "sonar");
    case Family::Bumper:
      return d.pluginParam("bumperTopicName", "bumper_states");
    case Family::ImuModel:
      return d.pluginParam("topicName", "/default_imu");
    case Family::ImuSensor:  // appended to "<namespace>/": never absolute on its own
      return withoutLeadingSlash(d.pluginParam("topicName", "imu_data"));
    case Family::P3d:
      return d.pluginParam("topicName");
    default:
      break;
  }
  // The depth plugins set their image's defaults to the infrared one's ("ir/image_raw",
  // "ir/camera_info") and then call GazeboRosCameraUtils::Load, which sets the camera's again: as
  // published, the depth plugins' image defaults are every camera's.
  switch (which)
  {
    case PluginTopic::CameraInfo:
      return underCameraName(d, d.pluginParam("cameraInfoTopicName", "camera_info"));
    case PluginTopic::DepthImage:
      return underCameraName(d, d.pluginParam("depthImageTopicName", "depth/image_raw"));
    case PluginTopic::DepthCameraInfo:
      return underCameraName(d, d.pluginParam("depthImageCameraInfoTopicName", "depth/camera_info"));
    case PluginTopic::Points:
      return underCameraName(d, d.pluginParam("pointCloudTopicName", "points"));
    default:
      return underCameraName(d, d.pluginParam("imageTopicName", "image_raw"));
  }
}

}  // namespace bullet_plant
