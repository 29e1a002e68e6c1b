// ackermann_steering_controller/AckermannSteeringController: a geometry_msgs/Twist on cmd_vel to the
// rear wheel speed and the steering angle, its odometry on odom and /tf (docs/interfaces.md section 12).
#include "control/controller_support.h"

#include <algorithm>
#include <cmath>
#include <tuple>

#include <urdf_parser/urdf_parser.h>

namespace bullet_plant
{
namespace
{
// ros_controllers' SpeedLimiter: velocity, acceleration and jerk limits on one command, each only
// when enabled (docs/interfaces.md section 12).
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

// ackermann_steering_controller/AckermannSteeringController: a bicycle model of one rear wheel
// (VelocityJointInterface) and one front steering joint (PositionJointInterface). cmd_vel's
// linear.x is the speed and angular.z the steering angle; odometry integrates the rear wheel's
// travel and the steering joint's angle.
class AckermannSteeringController : public Controller
{
public:
  bool init(ControllerContext& c) override
  {
    log_ = &c.log;
    ns_ = c.ns;
    auto text = [&](const char* key, std::string fallback) {
      const Param* p = param(c, key);
      return p && p->type() == Param::Type::String ? p->asString() : fallback;
    };
    auto number = [&](const char* key, double fallback) {
      const Param* p = param(c, key);
      return p && p->isNumber() ? p->asDouble() : fallback;
    };
    auto flag = [&](const char* key, bool fallback) {
      const Param* p = param(c, key);
      return p && p->type() == Param::Type::Bool ? p->asBool() : fallback;
    };
    const std::string rear_wheel = text("rear_wheel", "rear_wheel_joint");
    const std::string front_steer = text("front_steer", "front_steer_joint");
    const double publish_rate = number("publish_rate", 50.0);
    publish_period_ns_ = periodNsOfRate(publish_rate);
    open_loop_ = flag("open_loop", false);
    const double separation_multiplier = number("wheel_separation_h_multiplier", 1.0);
    const double radius_multiplier = number("wheel_radius_multiplier", 1.0);
    steer_pos_multiplier_ = number("steer_pos_multiplier", 1.0);
    window_size_ = size_t(std::max(1.0, number("velocity_rolling_window_size", 10.0)));
    cmd_vel_timeout_ = number("cmd_vel_timeout", 0.5);
    odometry_.child_frame_id = text("base_frame_id", "base_link");
    odometry_.frame_id = text("odom_frame_id", "odom");
    const bool enable_odom_tf = flag("enable_odom_tf", true);
    limiter_linear_.read(c, "linear/x");
    limiter_angular_.read(c, "angular/z");

    const Param* separation = param(c, "wheel_separation_h");
    const Param* radius = param(c, "wheel_radius");
    separation_ = separation && separation->isNumber() ? separation->asDouble() : 0.0;
    wheel_radius_ = radius && radius->isNumber() ? radius->asDouble() : 0.0;
    if (!(separation && separation->isNumber() && radius && radius->isNumber()) &&
        !geometryFromUrdf(c, rear_wheel, front_steer, !(separation && separation->isNumber()),
                          !(radius && radius->isNumber())))
      return false;
    odometry_separation_ = separation_multiplier * separation_;
    odometry_radius_ = radius_multiplier * wheel_radius_;

    for (auto& [key, out] : {std::pair<const char*, double*>{"pose_covariance_diagonal", odometry_.pose_covariance_diagonal.data()},
                             std::pair<const char*, double*>{"twist_covariance_diagonal", odometry_.twist_covariance_diagonal.data()}})
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

    rear_wheel_ = c.joints.handle(rear_wheel);
    front_steer_ = c.joints.handle(front_steer);
    for (auto [handle, name, iface] : {std::make_tuple(rear_wheel_, rear_wheel, JointInterface::Velocity),
                                       std::make_tuple(front_steer_, front_steer, JointInterface::Position)})
      if (!handle || handle->interface() != iface)
      {
        c.log.error("Exception thrown while initializing controller '" + c.ns.substr(c.ns.rfind('/') + 1) +
                    "'.\nCould not find resource '" + name + "' in '" + interfaceName(iface) + "'.");
        return false;
      }
    claimed_ = {ClaimedResources{interfaceName(JointInterface::Position), {front_steer}},
                ClaimedResources{interfaceName(JointInterface::Velocity), {rear_wheel}}};
    subscribe<TwistCommand>("cmd_vel", [this](const TwistCommand& t) { return setTwist(t.linear_x, t.angular_z); });
    odometry_port_ = &advertise<OdometrySample>("odom");
    if (enable_odom_tf)
      tf_port_ = &advertise<TransformSample>("/tf");
    return true;
  }

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

  void starting(int64_t time_ns) override
  {
    brake();
    running_ = true;
    last_publish_ns_ = time_ns;
    odometry_stamp_ns_ = time_ns;
    has_wheel_position_ = false;
    linear_window_.clear();
    angular_window_.clear();
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
    updateOdometry(time_ns);
    if (publish_period_ns_ > 0 && last_publish_ns_ + publish_period_ns_ < time_ns)
    {
      last_publish_ns_ += publish_period_ns_;
      publishOdometry(time_ns);
    }

    Command command = command_;
    if ((time_ns - command.stamp_ns) * 1e-9 > cmd_vel_timeout_)
      command.linear = command.angular = 0.0;  // brake: the commands are too old
    limiter_linear_.limit(command.linear, last0_.linear, last1_.linear, period);
    limiter_angular_.limit(command.angular, last0_.angular, last1_.angular, period);
    last1_ = last0_;
    last0_ = command;
    rear_wheel_->setCommand(command.linear / wheel_radius_);
    front_steer_->setCommand(command.angular);
  }

private:
  struct Command { double linear = 0, angular = 0; int64_t stamp_ns = 0; };

  void publishOdometry(int64_t time_ns)
  {
    odometry_.stamp_ns = time_ns;
    odometry_.pose = planarPose(x_, y_, heading_);
    odometry_.linear = urdf::Vector3(linear_, 0, 0);
    odometry_.angular = urdf::Vector3(0, 0, angular_);
    odometry_port_->publish(odometry_);
    if (tf_port_)
      tf_port_->publish(TransformSample{time_ns, odometry_.frame_id, odometry_.child_frame_id, odometry_.pose});
  }

  void brake()
  {
    rear_wheel_->setCommand(0.0);
    front_steer_->setCommand(0.0);
  }

  // ros_controllers' ackermann odometry: the rear wheel's travel since the last update and the
  // steering angle give the increment, integrated exactly on the arc; velocities are rolling means.
  void updateOdometry(int64_t time_ns)
  {
    double linear, angular;
    const double dt = (time_ns - odometry_stamp_ns_) * 1e-9;
    if (open_loop_)
    {
      linear = last0_.linear * dt;
      angular = last0_.angular * dt;
    }
    else
    {
      const double wheel = rear_wheel_->position() * odometry_radius_;
      // The first update after a start takes the wheel where it is (upstream would count the
      // wheel's whole travel since the robot was made as one jump).
      linear = has_wheel_position_ ? wheel - wheel_position_ : 0.0;
      wheel_position_ = wheel;
      has_wheel_position_ = true;
      angular = std::tan(front_steer_->position() * steer_pos_multiplier_) * linear / odometry_separation_;
    }
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
    if (open_loop_)
    {
      linear_ = last0_.linear;
      angular_ = last0_.angular;
      odometry_stamp_ns_ = time_ns;
      return;
    }
    if (dt < 0.0001)
      return;  // too short an interval to estimate a speed
    odometry_stamp_ns_ = time_ns;
    linear_ = rollingMean(linear_window_, linear / dt);
    angular_ = rollingMean(angular_window_, angular / dt);
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

  // wheel_separation_h: the x distance between the two joints' origins in their parents; the
  // wheel radius: the rear wheel link's collision cylinder. Read from <manager ns>/robot_description.
  bool geometryFromUrdf(ControllerContext& c, const std::string& rear_wheel, const std::string& front_steer,
                        bool need_separation, bool need_radius)
  {
    const Param* description = c.params.find(joinPath(c.ns.substr(0, c.ns.rfind('/')), "robot_description"));
    urdf::ModelInterfaceSharedPtr model;
    if (description && description->type() == Param::Type::String)
      model = urdf::parseURDF(description->asString());
    if (!model)
    {
      c.log.error("Robot descripion couldn't be retrieved from param server.");
      return false;
    }
    urdf::JointConstSharedPtr wheel = model->getJoint(rear_wheel), steer = model->getJoint(front_steer);
    if (!wheel || (need_separation && !steer))
    {
      c.log.error((!wheel ? rear_wheel : front_steer) + " couldn't be retrieved from model description");
      return false;
    }
    if (need_separation)
      separation_ = std::abs(wheel->parent_to_joint_origin_transform.position.x -
                             steer->parent_to_joint_origin_transform.position.x);
    if (need_radius)
    {
      urdf::LinkConstSharedPtr link = model->getLink(wheel->child_link_name);
      if (!link || !link->collision || !link->collision->geometry ||
          link->collision->geometry->type != urdf::Geometry::CYLINDER)
      {
        c.log.error("Wheel link " + wheel->child_link_name + " is NOT modeled as a cylinder!");
        c.log.error("Couldn't retrieve " + rear_wheel + " wheel radius");
        return false;
      }
      wheel_radius_ = static_cast<const urdf::Cylinder&>(*link->collision->geometry).radius;
    }
    return true;
  }

  Log* log_ = nullptr;
  std::string ns_;
  JointHandle *rear_wheel_ = nullptr, *front_steer_ = nullptr;
  OdometrySample odometry_;  // frames and covariances from the parameters; the rest per message
  OutputPort<OdometrySample>* odometry_port_ = nullptr;
  OutputPort<TransformSample>* tf_port_ = nullptr;  // null unless enable_odom_tf
  SpeedLimiter limiter_linear_, limiter_angular_;
  double separation_ = 0, wheel_radius_ = 0, odometry_separation_ = 0, odometry_radius_ = 0;
  double steer_pos_multiplier_ = 1, cmd_vel_timeout_ = 0.5;
  bool open_loop_ = false, running_ = false;
  size_t window_size_ = 10;
  int64_t publish_period_ns_ = 0, last_publish_ns_ = 0, last_update_ns_ = 0, odometry_stamp_ns_ = 0;
  Command command_, last0_, last1_;
  double x_ = 0, y_ = 0, heading_ = 0, linear_ = 0, angular_ = 0;
  double wheel_position_ = 0;
  bool has_wheel_position_ = false;
  std::vector<double> linear_window_, angular_window_;
};
}  // namespace

std::unique_ptr<Controller> makeAckermannSteeringController()
{
  return std::unique_ptr<Controller>(new AckermannSteeringController());
}

}  // namespace bullet_plant
