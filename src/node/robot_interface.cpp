#include "robot_interface.h"

#include <std_msgs/Bool.h>

#include "bullet_plant/model_plugin.h"
#include "bullet_plant/plugin_names.h"
#include "bullet_plant/robot.h"
#include "ros_names.h"
#include "ros_plant.h"

namespace bullet_plant
{
RobotInterface::RobotInterface(RosPlant& plant, Robot& robot)
  : nh_(robot.controlNamespace().empty()
            ? "/"
            : requireValidRosName(robot.controlNamespace(), "robot '" + robot.name() + "' robotNamespace")),
    robot_(robot)
{
  for (ModelPlugin* plugin : robot.modelPlugins())
  {
    const ModelPluginDescription& d = plugin->description();
    const std::string ns = modelPluginNamespace(d, robot.spawnNamespace(), robot.name());
    ros::NodeHandle plugin_nh(requireValidRosName(ns, "plugin '" + d.name + "' robotNamespace"));
    model_plugin_topics_.emplace_back(new PortTopics(plant, plugin_nh, [plugin](const std::string&) { return plugin; }));
    model_plugin_topics_.back()->refresh({{"", plugin}});
    // A Gazebo plugin file of the user's own (upstream's diff drive built against the API ...) may
    // publish odometry and tf the plant does not see: its robot publishes what its plugins do, as in
    // Gazebo.
    plugin_odometry_ = plugin_odometry_ || plugin->output<OdometrySample>() || plugin->output<TransformSample>() ||
                       !d.library.empty();
  }
  // The plant's ground truth is for URDF robots; an SDF model publishes only what its plugins
  // publish, as in Gazebo: odom -> "link" of every box would fight on /tf.
  if (!plugin_odometry_ && robot.description().format == RobotDescription::Format::Urdf)
    odometry_.reset(new OdometryPublisher(robot, nh_, plant.outbox()));
  for (Sensor* sensor : robot.sensors())
    if (std::unique_ptr<SensorPlugin> plugin = SensorPlugin::create(*sensor, robot, plant.world().timeStep(), plant.outbox()))
      sensor_plugins_.push_back({sensor, std::move(plugin)});
  const std::string& estop = robot.description().control.e_stop_topic;
  if (!estop.empty())
    estop_sub_ = nh_.subscribe<std_msgs::Bool>(requireValidRosName(estop, "robot '" + robot.name() + "' eStopTopic"), 1, [&plant, &robot](const std_msgs::BoolConstPtr& m) {
      bool on = m->data;
      plant.post([&robot, on] { robot.setEStop(on); });
    });
  if (ControllerManager* manager = robot.controllerManager())
  {
    controller_topics_.reset(new ControllerTopics(plant, *manager, nh_));
    manager_services_.reset(new ControllerManagerServices(plant, *manager, *controller_topics_, nh_));
  }
}

void RobotInterface::OnUpdate(int64_t time_ns)
{
  if (controller_topics_)
    controller_topics_->publish();
  for (std::unique_ptr<PortTopics>& topics : model_plugin_topics_)
    topics->publish();
  if (odometry_)
    odometry_->publish(time_ns, !(controller_topics_ && controller_topics_->publishesOdometryTransform()));
  for (LoadedPlugin& loaded : sensor_plugins_)
    loaded.plugin->update(time_ns);
}

void RobotInterface::updateSubscriptions()
{
  for (LoadedPlugin& loaded : sensor_plugins_)
  {
    const bool active = loaded.plugin->subscribed();
    if (loaded.sensor->active() != active)
      ROS_INFO("%s sensor '%s': %s", robot_.name().c_str(), loaded.sensor->name().c_str(),
               active ? "subscribed, computing" : "no subscribers, idle");
    loaded.sensor->setActive(active);
  }
}

}  // namespace bullet_plant
