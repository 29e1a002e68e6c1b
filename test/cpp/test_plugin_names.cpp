// plugin_names.cpp: the namespaces, topics and frame ids the gazebo_ros plugins give themselves.
#include <gtest/gtest.h>

#include <map>
#include <string>

#include "bullet_plant/params.h"
#include "bullet_plant/plugin_names.h"

using namespace bullet_plant;

namespace
{
SensorDescription sensor(const std::string& type, const std::string& link, std::map<std::string, std::string> plugin,
                         bool model_plugin = false)
{
  SensorDescription d;
  d.name = type;
  d.type = type;
  d.link = link;
  d.model_plugin = model_plugin;
  d.plugin = std::move(plugin);
  return d;
}
}  // namespace

TEST(ResolveTfFrame, AsTfResolve)
{
  EXPECT_EQ(resolveTfFrame("", "camera"), "camera");
  EXPECT_EQ(resolveTfFrame("tianracer_01", "camera"), "tianracer_01/camera");
  EXPECT_EQ(resolveTfFrame("/tianracer_01", "camera"), "tianracer_01/camera");
  EXPECT_EQ(resolveTfFrame("tianracer_01", "/tianracer_01/base_footprint"), "tianracer_01/base_footprint");
  EXPECT_EQ(resolveTfFrame("", "/world"), "world");
}

TEST(PluginNames, ImuNamespacesAsTheirPluginsTakeThem)
{
  const SensorDescription sensor_plugin = sensor("imu", "imu_link", {{"frameName", "f"}, {"topicName", "/imu"}});
  EXPECT_EQ(pluginNamespace(sensor_plugin, "", "tianracer"), "/tianracer")
      << "gazebo_ros_imu_sensor without a namespace: the model's";
  EXPECT_EQ(pluginTopic(sensor_plugin), "imu") << "appended to the namespace";
  EXPECT_EQ(pluginNamespace(sensor_plugin, "/car1", "tianracer"), "/car1");
  const SensorDescription model_plugin = sensor("imu", "imu_link", {{"bodyName", "imu_link"}}, true);
  EXPECT_EQ(pluginNamespace(model_plugin, "", "tianracer"), "");
  EXPECT_EQ(pluginTopic(model_plugin), "/default_imu");
}

TEST(PluginNames, ImuFramesAsGivenButForTheLeadingSlash)
{
  const SensorDescription sensor_plugin = sensor("imu", "imu_link", {{"frameName", "/car1/imu_link"}});
  EXPECT_EQ(pluginFrameId(sensor_plugin, ""), "car1/imu_link")
      << "frameName verbatim but for the leading '/'";
  const SensorDescription model_plugin = sensor("imu", "imu_link", {{"bodyName", "imu_link"}}, true);
  EXPECT_EQ(pluginFrameId(model_plugin, ""), "imu_link")
      << "frameName defaults to bodyName";
}

TEST(PluginNames, P3dFrameResolvesOnlyAgainstATfPrefixParameter)
{
  const SensorDescription p3d = sensor("p3d", "base_footprint",
                                       {{"bodyName", "base_footprint"}, {"topicName", "ground_truth"}}, true);
  EXPECT_EQ(pluginNamespace(p3d, "/car1", "car1"), "/car1");
  EXPECT_EQ(pluginTopic(p3d), "ground_truth");
  EXPECT_EQ(pluginFrameId(p3d, ""), "world") << "no tf_prefix parameter: the frame as given";
  EXPECT_EQ(pluginFrameId(p3d, "car1"), "car1/world");
  EXPECT_EQ(pluginChildFrameId(p3d), "base_footprint");
}

TEST(PluginNames, LaserAndCameraResolveOnlyAgainstATfPrefixParameter)
{
  const SensorDescription laser = sensor("ray", "laser_link", {});
  EXPECT_EQ(pluginTopic(laser), "/world") << "gazebo_ros_laser's default, sic";
  EXPECT_EQ(pluginFrameId(laser, ""), "world") << "frameName defaults to /world";
  const SensorDescription camera =
      sensor("depth", "camera_link", {{"cameraName", "front"}, {"frameName", "optical"}, {"robotNamespace", ""}});
  EXPECT_EQ(pluginNamespace(camera, "/car1", "car"), "car") << "an empty robotNamespace: the model's name";
  EXPECT_EQ(pluginFrameId(camera, ""), "optical") << "no tf_prefix parameter: the frame as given (2.9.2)";
  EXPECT_EQ(pluginFrameId(camera, "car1"), "car1/optical");
  EXPECT_EQ(pluginTopic(camera), "front/image_raw");
  EXPECT_EQ(pluginTopic(camera, PluginTopic::Points), "front/points");
  EXPECT_EQ(pluginTopic(camera, PluginTopic::DepthCameraInfo), "front/depth/camera_info");
}

TEST(PluginNames, ModelPluginNamespacesByTheirKindsRules)
{
  auto plugin = [](const char* filename, std::map<std::string, std::string> params) {
    ModelPluginDescription d;
    d.filename = filename;
    d.params = std::move(params);
    return d;
  };
  for (const char* kind : {"libgazebo_ros_diff_drive.so", "libgazebo_ros_joint_state_publisher.so"})
  {
    EXPECT_EQ(modelPluginNamespace(plugin(kind, {}), "", "bot"), "bot") << "empty: the model's name";
    EXPECT_EQ(modelPluginNamespace(plugin(kind, {{"robotNamespace", ""}}), "/", "bot"), "bot");
    EXPECT_EQ(modelPluginNamespace(plugin(kind, {}), "/", "bot"), "/") << "spawn_model's namespace";
    EXPECT_EQ(modelPluginNamespace(plugin(kind, {{"robotNamespace", "/r1"}}), "/", "bot"), "/r1");
  }
  for (const char* kind : {"libgazebo_ros_skid_steer_drive.so", "libgazebo_ros_planar_move.so",
                           "libroboticsgroup_upatras_gazebo_mimic_joint_plugin.so"})
  {
    EXPECT_EQ(modelPluginNamespace(plugin(kind, {}), "", "bot"), "") << "empty: the global namespace";
    EXPECT_EQ(modelPluginNamespace(plugin(kind, {}), "/r2", "bot"), "/r2");
  }
  // The GazeboRos helper's tf prefix: the tf_prefix parameter found from its namespace up, as
  // noetic's gazebo_ros_utils reads it (tf::getPrefixParam); none without one.
  const ModelPluginDescription diff = plugin("libgazebo_ros_diff_drive.so", {});
  Param params;
  EXPECT_EQ(modelPluginTfPrefix(diff, "/r1/", params), "") << "no tf_prefix parameter: no prefix";
  EXPECT_EQ(tfPrefixParamKeys(diff, "/r1/a/"),
            (std::vector<std::string>{"/r1/a/tf_prefix", "/r1/tf_prefix", "/tf_prefix"}));
  EXPECT_EQ(tfPrefixParamKeys(diff, ""), (std::vector<std::string>{"/tf_prefix"}));
  EXPECT_EQ(tfPrefixParamKeys(plugin("libgazebo_ros_skid_steer_drive.so", {}), "/r1"), std::vector<std::string>())
      << "only the GazeboRos helper's plugins read it";
  ModelPluginDescription upstream = diff;
  upstream.library = "/ws/devel/lib/libgazebo_ros_diff_drive.so";
  EXPECT_EQ(tfPrefixParamKeys(upstream, "/r1"), std::vector<std::string>())
      << "a Gazebo plugin library asks the parameter server itself: nothing to copy for it";
  params.set("/tf_prefix", Param::string("everyone"));
  EXPECT_EQ(modelPluginTfPrefix(diff, "/r1", params), "everyone") << "a parent's";
  params.set("/r1/tf_prefix", Param::string("r1"));
  EXPECT_EQ(modelPluginTfPrefix(diff, "/r1", params), "r1") << "its own namespace's first";
  EXPECT_EQ(modelPluginTfPrefix(plugin("libgazebo_ros_skid_steer_drive.so", {}), "/r1", params), "")
      << "skid_steer_drive reads none";
  EXPECT_EQ(resolveTfFrame(modelPluginTfPrefix(diff, "/r1", params), "odom"), "r1/odom");
}
