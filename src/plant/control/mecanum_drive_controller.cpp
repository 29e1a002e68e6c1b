// mecanum_drive_controller/MecanumDriveController as Clearpath's Ridgeback ships it (ridgeback_control:
// ros_controllers never released one for ROS 1, so the type name resolves to that copy): a
// geometry_msgs/Twist on cmd_vel (linear x, y and angular z) to the speeds of four mecanum wheels
// (VelocityJointInterface, every wheel's axis +y), odometry from the wheels' speeds on odom and /tf
// (docs/interfaces.md section 12).
#include "control/drive_odometry.h"

#include <array>
#include <cmath>

namespace bullet_plant
{
namespace
{
enum Wheel { kFrontLeft, kBackLeft, kBackRight, kFrontRight, kWheels };

class MecanumDriveController : public Controller
{
public:
  MecanumDriveController()
  {
    subscribe<TwistCommand>("cmd_vel", [this](const TwistCommand& t) { return setTwist(t); });
  }

  bool init(ControllerContext& c) override
  {
    log_ = &c.log;
    ns_ = c.ns;
    static const char* const kWheelParams[kWheels] = {"front_left_wheel_joint", "back_left_wheel_joint",
                                                      "back_right_wheel_joint", "front_right_wheel_joint"};
    ClaimedResources claimed{interfaceName(JointInterface::Velocity), {}};
    for (int w = 0; w < kWheels; ++w)
    {
      names_[w] = paramText(c, kWheelParams[w], "");
      JointHandle* h = c.joints.handle(names_[w]);
      if (!h || h->interface() != JointInterface::Velocity)
      {
        c.log.error("Exception thrown while initializing controller '" + c.ns.substr(c.ns.rfind('/') + 1) +
                    "'.\nCould not find resource '" + names_[w] + "' (" + kWheelParams[w] + ") in '" +
                    interfaceName(JointInterface::Velocity) + "'.");
        return false;
      }
      wheels_[w] = h;
      claimed.resources.push_back(names_[w]);
    }
    claimed_.assign(1, claimed);
    publish_gate_.setPeriodNs(periodNsOfRate(paramNumber(c, "publish_rate", 50.0)));
    open_loop_ = paramFlag(c, "open_loop", false);
    cmd_vel_timeout_ = paramNumber(c, "cmd_vel_timeout", 0.5);
    limiters_[0].read(c, "linear/x");
    limiters_[1].read(c, "linear/y");
    limiters_[2].read(c, "angular/z");
    if (!readOdometryParams(c, message_, enable_odom_tf_))
      return false;
    message_.frame_id = "odom";  // upstream's is fixed; odom_frame_id is not read
    if (!readGeometry(c))
      return false;
    odometry_port_ = &advertise<OdometrySample>("odom");
    if (enable_odom_tf_)
      tf_port_ = &advertise<TransformSample>("/tf");
    return true;
  }

  void starting(int64_t time_ns) override
  {
    brake();
    running_ = true;
    publish_gate_.restart(time_ns);
    last_update_ns_ = odometry_ns_ = time_ns;
    command_ = last_ = Command{};
    command_.stamp_ns = time_ns;
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
    if (publish_gate_.periodNs() > 0 && publish_gate_.due(time_ns))  // a publish_rate of 0: never
      publishOdometry(time_ns);
    Command command = command_;
    if ((time_ns - command.stamp_ns) * 1e-9 > cmd_vel_timeout_)
      command.v = {0.0, 0.0, 0.0};  // brake: the command is too old (and still within the limits)
    for (int k = 0; k < 3; ++k)
      limit(limiters_[k], command.v[k], last_.v[k], period);
    last_ = command;
    // Inverse kinematics: each wheel's rollers at 45 degrees (x-pattern seen from above).
    const double vx = command.v[0], vy = command.v[1], wz = command.v[2];
    const double speeds[kWheels] = {(vx - vy - k_ * wz) / radius_, (vx + vy - k_ * wz) / radius_,
                                    (vx - vy + k_ * wz) / radius_, (vx + vy + k_ * wz) / radius_};
    for (int w = 0; w < kWheels; ++w)
      wheels_[w]->setCommand(speeds[w]);
  }

private:
  struct Command
  {
    std::array<double, 3> v{};  // linear x, linear y, angular z
    int64_t stamp_ns = 0;
  };

  bool setTwist(const TwistCommand& t)
  {
    if (!running_)
    {
      log_->error("Can't accept new commands. Controller is not running.");
      return false;
    }
    if (!std::isfinite(t.linear_x + t.linear_y + t.angular_z))
    {
      log_->warn("Received NaN in velocity command. Ignoring. (" + ns_ + "/cmd_vel)");
      return false;
    }
    command_ = Command{{t.linear_x, t.linear_y, t.angular_z}, last_update_ns_};
    return true;
  }

  // Ridgeback's SpeedLimiter: the velocity clamped first, then its change (no jerk limits).
  static void limit(const SpeedLimiter& l, double& v, double v0, double dt)
  {
    if (l.has_velocity_limits)
      v = std::max(l.min_velocity, std::min(v, l.max_velocity));
    if (l.has_acceleration_limits)
      v = v0 + std::max(l.min_acceleration * dt, std::min(v - v0, l.max_acceleration * dt));
  }

  void brake()
  {
    for (JointHandle* h : wheels_)
      if (h)
        h->setCommand(0.0);
  }

  // wheel_separation_x and wheel_separation_y (both or neither: k = (x + y) / 2) and wheel_radius
  // override the URDF, where k is the mean of |x| + |y| of the four wheel joints' origins in their
  // parents (which must be the base) and the radius that of the wheel links' collision cylinders or
  // spheres (use_realigned_roller_joints: the links below the wheels, a realigned roller's).
  bool readGeometry(ControllerContext& c)
  {
    const Param* separation_x = param(c, "wheel_separation_x");
    const Param* separation_y = param(c, "wheel_separation_y");
    const Param* radius = param(c, "wheel_radius");
    const bool has_x = separation_x && separation_x->isNumber(), has_y = separation_y && separation_y->isNumber();
    if (has_x != has_y)
    {
      c.log.error("Only one wheel separation overrided (" + c.ns + "/wheel_separation_" + (has_x ? "x" : "y") +
                  "): set both wheel_separation_x and wheel_separation_y, or neither to read them from the URDF.");
      return false;
    }
    const bool has_radius = radius && radius->isNumber();
    if (has_x)
      k_ = (separation_x->asDouble() + separation_y->asDouble()) / 2.0;
    if (has_radius)
      radius_ = radius->asDouble();
    if (has_x && has_radius)
      return true;
    urdf::ModelInterfaceSharedPtr model = robotModel(c);
    if (!model)
      return false;
    urdf::Vector3 origin[kWheels];
    double radii[kWheels];
    const bool realigned = paramFlag(c, "use_realigned_roller_joints", false);
    for (int w = 0; w < kWheels; ++w)
    {
      urdf::JointConstSharedPtr joint = model->getJoint(names_[w]);
      if (!joint)
      {
        c.log.error(names_[w] + " couldn't be retrieved from model description");
        return false;
      }
      origin[w] = joint->parent_to_joint_origin_transform.position;
      urdf::LinkConstSharedPtr link = model->getLink(joint->child_link_name);
      if (realigned && link && !link->child_joints.empty())
        link = model->getLink(link->child_joints[0]->child_link_name);
      const urdf::Geometry* g = link && link->collision ? link->collision->geometry.get() : nullptr;
      if (g && g->type == urdf::Geometry::CYLINDER)
        radii[w] = static_cast<const urdf::Cylinder*>(g)->radius;
      else if (g && g->type == urdf::Geometry::SPHERE)
        radii[w] = static_cast<const urdf::Sphere*>(g)->radius;
      else if (!has_radius)
      {
        c.log.error("Wheel link " + (link ? link->name : joint->child_link_name) +
                    " is NOT modeled as a cylinder or sphere! Couldn't retrieve " + names_[w] + " wheel radius");
        return false;
      }
    }
    if (!has_x)
      k_ = (-(-origin[0].x - origin[0].y) - (origin[1].x - origin[1].y) + (-origin[2].x - origin[2].y) +
            (origin[3].x - origin[3].y)) / 4.0;
    if (!has_radius)
    {
      for (int w = 1; w < kWheels; ++w)
        if (std::fabs(radii[w] - radii[0]) > 1e-3)
        {
          c.log.error("Wheels radius are not egual: " + names_[0] + " and " + names_[w] + " differ; give wheel_radius.");
          return false;
        }
      radius_ = radii[0];
    }
    return true;
  }

  // Forward kinematics of the wheels' speeds (or, open loop, the last command), integrated with
  // the heading after the turn, as Ridgeback's Odometry::integrateXY.
  void updateOdometry(int64_t time_ns)
  {
    const double dt = (time_ns - odometry_ns_) * 1e-9;
    if (dt < 0.0001)
      return;  // too short an interval
    odometry_ns_ = time_ns;
    if (open_loop_)
      twist_ = last_.v;
    else
    {
      double w[kWheels];
      for (int i = 0; i < kWheels; ++i)
        w[i] = wheels_[i]->velocity();
      twist_ = {0.25 * radius_ * (w[0] + w[1] + w[2] + w[3]), 0.25 * radius_ * (-w[0] + w[1] - w[2] + w[3]),
                0.25 * radius_ / k_ * (-w[0] - w[1] + w[2] + w[3])};
    }
    heading_ += twist_[2] * dt;
    x_ += (twist_[0] * std::cos(heading_) - twist_[1] * std::sin(heading_)) * dt;
    y_ += (twist_[0] * std::sin(heading_) + twist_[1] * std::cos(heading_)) * dt;
  }

  void publishOdometry(int64_t time_ns)
  {
    message_.stamp_ns = time_ns;
    message_.pose = planarPose(x_, y_, heading_);
    message_.linear = urdf::Vector3(twist_[0], twist_[1], 0);
    message_.angular = urdf::Vector3(0, 0, twist_[2]);
    odometry_port_->publish(message_);
    if (tf_port_)
      tf_port_->publish(TransformSample{time_ns, message_.frame_id, message_.child_frame_id, message_.pose});
  }

  Log* log_ = nullptr;
  std::string ns_;
  std::string names_[kWheels];
  JointHandle* wheels_[kWheels] = {};
  double k_ = 0, radius_ = 0;  // half separations x + y, wheel radius
  SpeedLimiter limiters_[3];   // linear/x, linear/y, angular/z (their velocity and acceleration limits)
  double cmd_vel_timeout_ = 0.5;
  bool open_loop_ = false, running_ = false, enable_odom_tf_ = true;
  CatchUpRateGate publish_gate_;  // publish_rate
  int64_t last_update_ns_ = 0, odometry_ns_ = 0;
  Command command_, last_;
  std::array<double, 3> twist_{};
  double x_ = 0, y_ = 0, heading_ = 0;  // kept over restarts, as upstream's Odometry::init
  OdometrySample message_;
  OutputPort<OdometrySample>* odometry_port_ = nullptr;
  OutputPort<TransformSample>* tf_port_ = nullptr;
};
}  // namespace

ROS_CONTROLLER_TYPE(mecanum_drive, "mecanum_drive_controller/MecanumDriveController",
                    controllerFactory<MecanumDriveController>());

}  // namespace bullet_plant
