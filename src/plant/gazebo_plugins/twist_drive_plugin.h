// What gazebo_plugins' Twist-driven bases (diff_drive, skid_steer_drive, planar_move) share: the
// last command from commandTopic, their odometry frames, and odometry read from the world (the model
// frame's pose, its world velocity turned into the model's heading with the yaw rounded to float, as
// each of them does).
#pragma once

#include <array>
#include <cmath>
#include <string>

#include <urdf_model/pose.h>

#include "bullet_plant/geometry.h"
#include "bullet_plant/model_plugin.h"
#include "bullet_plant/plugin_names.h"

namespace bullet_plant
{
// The world-frame velocity in the frame turned by yaw about z (x forward, y left; z dropped). The yaw
// is a float as the plugins keep it (yawOf rounded).
inline urdf::Vector3 inHeading(float yaw, const urdf::Vector3& world)
{
  const float c = std::cos(yaw), s = std::sin(yaw);
  return urdf::Vector3(c * world.x + s * world.y, c * world.y - s * world.x, 0.0);
}

// The odometry pose/TF and Odometry covariances the skid steer and planar plugins use: x, y, yaw
// as given, 1e12 (unknown) for z, roll and pitch.
inline std::array<double, 6> planarCovariance(double x, double y, double yaw) { return {{x, y, 1e12, 1e12, 1e12, yaw}}; }

class TwistDrivePlugin : public ModelPlugin
{
protected:
  // commandTopic (default cmd_vel): each geometry_msgs/Twist becomes command_. A non-finite one is
  // refused (a rejected message) where Gazebo would drive the model to NaN: the last one stays.
  void subscribeCommand(const ModelPluginDescription& d)
  {
    subscribe<TwistCommand>(d.text("commandTopic", "cmd_vel"), [this](const TwistCommand& t) {
      if (!std::isfinite(t.linear_x) || !std::isfinite(t.linear_y) || !std::isfinite(t.angular_z))
        return false;
      command_ = t;
      commandArrived();
      return true;
    });
  }

  // odometryFrame (odom) and robotBaseFrame (base_footprint), resolved against the plugin's tf prefix.
  static void readOdometryFrames(const ModelPluginDescription& d, const ModelPluginContext& context, OdometrySample& out)
  {
    const std::string prefix = context.tfPrefix(d);
    out.frame_id = resolveTfFrame(prefix, d.text("odometryFrame", "odom"));
    out.child_frame_id = resolveTfFrame(prefix, d.text("robotBaseFrame", "base_footprint"));
  }

  // Called as each accepted command is stored, for plugins that note when commands come.
  virtual void commandArrived() {}

  // World odometry as diff_drive and tricycle_drive read it: the model frame's pose, its world
  // velocity turned into its heading, the world yaw rate.
  static void readWorldOdometry(const ModelPluginContext& context, OdometrySample& out)
  {
    const LinkMotion model = context.linkMotion(context.rootLink());
    out.pose = model.pose;
    out.linear = inHeading(yawOf(model.pose.rotation), model.velocity);
    out.angular = urdf::Vector3(0, 0, model.angular_velocity.z);
  }

  TwistCommand command_;  // the last command; Reset zeroes it
};

}  // namespace bullet_plant
