// What ros_controllers' drive controllers share (private to control/), as ackermann_steering_controller
// reuses diff_drive_controller's speed_limiter.h and odometry.h upstream: the speed limiter, the
// odometry integrator, the odometry message's parameters and the robot model the wheel geometry is
// read from (docs/interfaces.md section 12).
#pragma once

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <urdf_parser/urdf_parser.h>

#include "bullet_plant/geometry.h"
#include "control/controller_support.h"

namespace bullet_plant
{
// ros_controllers' SpeedLimiter: velocity, acceleration and jerk limits on one command, each only
// when enabled.
struct SpeedLimiter
{
  bool has_velocity_limits = false, has_acceleration_limits = false, has_jerk_limits = false;
  double min_velocity = 0, max_velocity = 0, min_acceleration = 0, max_acceleration = 0, min_jerk = 0, max_jerk = 0;

  // Reads <prefix>/has_velocity_limits, max_velocity, min_velocity (default -max_velocity), ...
  void read(const ControllerContext& c, const std::string& prefix)
  {
    auto flag = [&](const char* key, bool& out) {
      if (const Param* p = param(c, prefix + "/" + key))
        if (p->type() == Param::Type::Bool)
          out = p->asBool();
    };
    auto number = [&](const char* key, double fallback) {
      const Param* p = param(c, prefix + "/" + key);
      return p && p->isNumber() ? p->asDouble() : fallback;
    };
    flag("has_velocity_limits", has_velocity_limits);
    flag("has_acceleration_limits", has_acceleration_limits);
    flag("has_jerk_limits", has_jerk_limits);
    max_velocity = number("max_velocity", max_velocity);
    min_velocity = number("min_velocity", -max_velocity);
    max_acceleration = number("max_acceleration", max_acceleration);
    min_acceleration = number("min_acceleration", -max_acceleration);
    max_jerk = number("max_jerk", max_jerk);
    min_jerk = number("min_jerk", -max_jerk);
  }

  // v: the new command, v0 and v1 the two before it; jerk, then acceleration, then velocity.
  void limit(double& v, double v0, double v1, double dt) const
  {
    if (has_jerk_limits)
    {
      const double dv = v - v0, dv0 = v0 - v1, dt2 = 2.0 * dt * dt;
      v = v0 + dv0 + std::max(min_jerk * dt2, std::min(dv - dv0, max_jerk * dt2));
    }
    if (has_acceleration_limits)
      v = v0 + std::max(min_acceleration * dt, std::min(v - v0, max_acceleration * dt));
    if (has_velocity_limits)
      v = std::max(min_velocity, std::min(v, max_velocity));
  }
};

// diff_drive_controller's Odometry: increments of travel and heading integrated exactly on the arc
// (second-order Runge-Kutta when almost straight); the rates are rolling means of the last
// velocity_rolling_window_size updates.
class DriveOdometry
{
public:
  // At a controller's start: the rates forgotten, the pose kept (upstream's init).
  void init(int64_t time_ns, size_t window_size)
  {
    timestamp_ns_ = time_ns;
    window_size_ = std::max<size_t>(1, window_size);
    linear_window_.clear();
    angular_window_.clear();
  }

  // Travel (m) and heading change (rad) since the last update, measured at time_ns.
  void update(double linear, double angular, int64_t time_ns)
  {
    const double dt = (time_ns - timestamp_ns_) * 1e-9;
    integrate(linear, angular);
    if (dt < 0.0001)
      return;  // too short an interval to estimate a speed
    timestamp_ns_ = time_ns;
    linear_ = rollingMean(linear_window_, linear / dt);
    angular_ = rollingMean(angular_window_, angular / dt);
  }

  // Open loop: the commanded rates over the time since the last update.
  void updateOpenLoop(double linear, double angular, int64_t time_ns)
  {
    const double dt = (time_ns - timestamp_ns_) * 1e-9;
    integrate(linear * dt, angular * dt);
    linear_ = linear;
    angular_ = angular;
    timestamp_ns_ = time_ns;
  }

  double x() const { return x_; }
  double y() const { return y_; }
  double heading() const { return heading_; }
  double linear() const { return linear_; }
  double angular() const { return angular_; }

private:
  void integrate(double linear, double angular)
  {
    if (std::abs(angular) < 1e-6)
    {
      const double direction = heading_ + angular * 0.5;
      x_ += linear * std::cos(direction);
      y_ += linear * std::sin(direction);
      heading_ += angular;
    }
    else
    {
      const double heading_old = heading_, r = linear / angular;
      heading_ += angular;
      x_ += r * (std::sin(heading_) - std::sin(heading_old));
      y_ += -r * (std::cos(heading_) - std::cos(heading_old));
    }
  }

  double rollingMean(std::vector<double>& window, double value) const
  {
    window.push_back(value);
    if (window.size() > window_size_)
      window.erase(window.begin());
    double sum = 0.0;
    for (double v : window)
      sum += v;
    return sum / double(window.size());
  }

  int64_t timestamp_ns_ = 0;
  size_t window_size_ = 10;
  double x_ = 0, y_ = 0, heading_ = 0, linear_ = 0, angular_ = 0;
  std::vector<double> linear_window_, angular_window_;
};

// base_frame_id, odom_frame_id, enable_odom_tf and the two covariance diagonals into the message a
// drive controller publishes; false, with upstream's kind of error, for a diagonal that is not 6 numbers.
inline bool readOdometryParams(const ControllerContext& c, OdometrySample& odometry, bool& enable_odom_tf)
{
  odometry.child_frame_id = paramText(c, "base_frame_id", "base_link");
  odometry.frame_id = paramText(c, "odom_frame_id", "odom");
  enable_odom_tf = paramFlag(c, "enable_odom_tf", true);
  for (auto& [key, out] : {std::pair<const char*, double*>{"pose_covariance_diagonal", odometry.pose_covariance_diagonal.data()},
                           std::pair<const char*, double*>{"twist_covariance_diagonal", odometry.twist_covariance_diagonal.data()}})
  {
    const Param* list = param(c, key);
    bool ok = list && list->type() == Param::Type::List && list->asList().size() == 6;
    for (size_t k = 0; ok && k < 6; ++k)
      ok = list->asList()[k].isNumber() && ((out[k] = list->asList()[k].asDouble()), true);
    if (!ok)
    {
      c.log.error(std::string("Parameter '") + key + "' of " + c.ns + " must be a list of 6 numbers (the "
                  "odometry's covariance diagonal, e.g. [0.001, 0.001, 1000000.0, 1000000.0, 1000000.0, 1000.0])");
      return false;
    }
  }
  return true;
}

// The URDF on the parameter server in the controller manager's namespace, as the drive controllers
// read robot_description from their root node handle; null (logged) when there is none.
inline urdf::ModelInterfaceSharedPtr robotModel(const ControllerContext& c)
{
  const Param* description = c.params.find(joinPath(c.ns.substr(0, c.ns.rfind('/')), "robot_description"));
  urdf::ModelInterfaceSharedPtr model;
  if (description && description->type() == Param::Type::String)
    model = urdf::parseURDF(description->asString());
  if (!model)
    c.log.error("Robot descripion couldn't be retrieved from param server.");
  return model;
}

// What ros_controllers' two drive controllers (diff_drive, ackermann_steering) share: a Twist on
// <controller>/cmd_vel (refused, logged, while stopped or non-finite), zeroed after cmd_vel_timeout,
// limited, then turned into joint commands by the subclass; odometry measured every update and
// published with its transform at publish_rate (strictly later than the period).
class TwistDriveController : public Controller
{
public:
  void starting(int64_t time_ns) override
  {
    brake();
    running_ = true;
    publish_gate_.restart(time_ns);
    odometry_.init(time_ns, window_size_);
    restartMeasurement();
    last0_ = last1_ = Command();
    command_ = Command{0.0, 0.0, time_ns};
  }

  void stopping(int64_t) override
  {
    brake();
    running_ = false;
  }

  void update(int64_t time_ns, double period) override
  {
    last_update_ns_ = time_ns;
    if (open_loop_)
      odometry_.updateOpenLoop(last0_.linear, last0_.angular, time_ns);
    else
      measureOdometry(time_ns);
    if (publish_gate_.periodNs() > 0 && publish_gate_.due(time_ns))  // a publish_rate of 0: never
      publishOdometry(time_ns);
    Command command = command_;
    if ((time_ns - command.stamp_ns) * 1e-9 > cmd_vel_timeout_)
      command.linear = command.angular = 0.0;  // brake: the commands are too old
    limiter_linear_.limit(command.linear, last0_.linear, last1_.linear, period);
    limiter_angular_.limit(command.angular, last0_.angular, last1_.angular, period);
    last1_ = last0_;
    last0_ = command;
    drive(command.linear, command.angular);
  }

protected:
  // publish_rate (50), open_loop, velocity_rolling_window_size (10), cmd_vel_timeout (0.5) and the
  // linear/x and angular/z limits.
  void readDriveParams(ControllerContext& c)
  {
    log_ = &c.log;
    ns_ = c.ns;
    publish_gate_.setPeriodNs(periodNsOfRate(paramNumber(c, "publish_rate", 50.0)));
    open_loop_ = paramFlag(c, "open_loop", false);
    window_size_ = size_t(std::max(1.0, paramNumber(c, "velocity_rolling_window_size", 10.0)));
    cmd_vel_timeout_ = paramNumber(c, "cmd_vel_timeout", 0.5);
    limiter_linear_.read(c, "linear/x");
    limiter_angular_.read(c, "angular/z");
  }
  // The odometry message's frames and covariances; false (logged) for bad covariances.
  bool readOdometry(ControllerContext& c) { return readOdometryParams(c, message_, enable_odom_tf_); }
  // cmd_vel in, odom and (with enable_odom_tf) /tf out.
  void openPorts()
  {
    subscribe<TwistCommand>("cmd_vel", [this](const TwistCommand& t) { return setTwist(t.linear_x, t.angular_z); });
    odometry_port_ = &advertise<OdometrySample>("odom");
    if (enable_odom_tf_)
      tf_port_ = &advertise<TransformSample>("/tf");
  }

  // Closed loop: odometry_.update with the travel and heading change since the last update.
  virtual void measureOdometry(int64_t time_ns) = 0;
  // At a start: the next measurement takes the joints where they are.
  virtual void restartMeasurement() = 0;
  // The limited command (linear.x, angular.z) into the joints.
  virtual void drive(double linear, double angular) = 0;
  virtual void brake() = 0;

  DriveOdometry odometry_;

private:
  struct Command { double linear = 0, angular = 0; int64_t stamp_ns = 0; };

  bool setTwist(double linear_x, double angular_z)
  {
    if (!running_)
    {
      log_->error("Can't accept new commands. Controller is not running.");
      return false;
    }
    if (!std::isfinite(linear_x) || !std::isfinite(angular_z))
    {
      log_->warn("Received NaN in velocity command. Ignoring. (" + ns_ + "/cmd_vel)");
      return false;
    }
    command_ = {linear_x, angular_z, last_update_ns_};
    return true;
  }

  void publishOdometry(int64_t time_ns)
  {
    message_.stamp_ns = time_ns;
    message_.pose = planarPose(odometry_.x(), odometry_.y(), odometry_.heading());
    message_.linear = urdf::Vector3(odometry_.linear(), 0, 0);
    message_.angular = urdf::Vector3(0, 0, odometry_.angular());
    odometry_port_->publish(message_);
    if (tf_port_)
      tf_port_->publish(TransformSample{time_ns, message_.frame_id, message_.child_frame_id, message_.pose});
  }

  Log* log_ = nullptr;
  std::string ns_;
  OdometrySample message_;  // frames and covariances from the parameters; the rest per message
  bool enable_odom_tf_ = true;
  OutputPort<OdometrySample>* odometry_port_ = nullptr;
  OutputPort<TransformSample>* tf_port_ = nullptr;  // null unless enable_odom_tf
  SpeedLimiter limiter_linear_, limiter_angular_;
  double cmd_vel_timeout_ = 0.5;
  bool open_loop_ = false, running_ = false;
  size_t window_size_ = 10;
  CatchUpRateGate publish_gate_;  // publish_rate
  int64_t last_update_ns_ = 0;
  Command command_, last0_, last1_;
};

}  // namespace bullet_plant
