// How the gazebo_ros plugins name their ROS side, from their <plugin> block alone: the namespace of
// the plugin's node handle, its topics and the frame ids it stamps (docs/interfaces.md section 11).
// The plant's sensors know none of it. ROS-free, so the node's plugins and the Python module share
// one copy of these rules.
#pragma once

#include <string>
#include <vector>

#include "bullet_plant/robot_description.h"

namespace bullet_plant
{
class Param;
// tf::resolve(prefix, frame) of tf 1.13, as gazebo_ros's plugins use it for their frame ids: a
// frame starting with '/' loses the '/', otherwise "prefix/frame" (the prefix without its leading
// '/'), or the frame alone for an empty prefix.
std::string resolveTfFrame(const std::string& prefix, const std::string& frame);

// The namespace of the plugin's node handle: its <robotNamespace>, else the spawn namespace
// (gazebo_ros writes it into every plugin), else the plugin's own default.
std::string pluginNamespace(const SensorDescription& d, const std::string& spawn_namespace, const std::string& model_name);

// The frame id of what it publishes, each plugin with its own rule.
std::string pluginFrameId(const SensorDescription& d, const std::string& tf_prefix);

// p3d's child frame: <bodyName> as given.
inline std::string pluginChildFrameId(const SensorDescription& d) { return d.link; }

// Its topics, relative to its namespace. Camera plugins have five, under <cameraName>.
enum class PluginTopic { Main, CameraInfo, DepthImage, DepthCameraInfo, Points };
std::string pluginTopic(const SensorDescription& d, PluginTopic which = PluginTopic::Main);

// Which camera of a multicamera sensor gazebo_ros_multicamera publishes it as: "left" when the
// <camera>'s name contains "left", else "right" when it contains "right", else "" (upstream loads
// no publisher for it).
std::string multicameraSide(const SensorDescription& d);

// A model plugin's namespace: its <robotNamespace>, which spawn_model writes into every plugin
// without one (the spawner's namespace). Where that is empty, the plugins built on gazebo_ros's
// GazeboRos helper (diff_drive) and joint_state_publisher take the model's name; skid_steer_drive,
// planar_move and the mimic joint plugin stay in the global namespace.
std::string modelPluginNamespace(const ModelPluginDescription& d, const std::string& spawn_namespace,
                                 const std::string& model_name);
// Its tf prefix, for the GazeboRos helper's plugins (diff_drive, tricycle_drive): the tf_prefix
// parameter tf::getPrefixParam finds from the plugin's namespace up (`params`, where the node copies
// them at spawn), as gazebo_ros_pkgs' noetic gazebo_ros_utils reads it; none where there is none, and
// none for the others.
std::string modelPluginTfPrefix(const ModelPluginDescription& d, const std::string& plugin_namespace,
                                const Param& params);
// The keys tf::getPrefixParam would try for plugin `d` in `plugin_namespace`: NS/tf_prefix, then each
// parent's, then /tf_prefix; none but for the plant's own GazeboRos helper plugins (a Gazebo plugin
// library of the user's asks the parameter server itself).
std::vector<std::string> tfPrefixParamKeys(const ModelPluginDescription& d, const std::string& plugin_namespace);
// The tf_prefix parameter tf::getPrefixParam finds in `params` from `plugin_namespace` up (the
// nearest of NS/tf_prefix, its parents', /tf_prefix); "" where there is none. gazebo_ros_pkgs
// 2.9.2's sensor plugins take no other prefix (its "Leave empty tf_prefix values unset": before it,
// the laser and camera plugins fell back to their namespace).
std::string searchedTfPrefix(const std::string& plugin_namespace, const Param& params);

}  // namespace bullet_plant
