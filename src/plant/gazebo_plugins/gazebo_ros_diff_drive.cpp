// gazebo_plugins' libgazebo_ros_diff_drive.so (ROS 1 Noetic): a geometry_msgs/Twist on commandTopic
// turns two wheel joints, each by a velocity motor of at most wheelTorque, ramped by
// wheelAcceleration; nav_msgs/Odometry on odometryTopic from the model's world pose or from the
// wheels' encoders, with odometryFrame -> robotBaseFrame on /tf; optionally the wheels' transforms
// and joint_states. Parameters, defaults, the update gate and the odometry are upstream's
// (docs/model_plugins.md).
#include <cmath>

#include "bullet_plant/geometry.h"
#include "bullet_plant/log.h"
#include "bullet_plant/rate_gate.h"
#include "gazebo_plugins/twist_drive_plugin.h"

namespace bullet_plant
{
namespace
{
enum Side { kLeft = 0, kRight = 1 };

class GazeboRosDiffDrive : public TwistDrivePlugin
{
public:
  bool Load(const ModelPluginDescription& d, ModelPluginContext& context, int64_t time_ns) override
  {
    context_ = &context;
    const std::string odometry_topic = d.text("odometryTopic", "odom");
    const std::string prefix = context.tfPrefix(d);
    readOdometryFrames(d, context, odometry_);
    publish_wheel_tf_ = d.flag("publishWheelTF", false);
    publish_odom_tf_ = d.flag("publishOdomTF", true);
    publish_wheel_joint_state_ = d.flag("publishWheelJointState", false);
    wheel_separation_ = d.number("wheelSeparation", 0.34);
    wheel_diameter_ = d.number("wheelDiameter", 0.15);
    wheel_accel_ = d.number("wheelAcceleration", 0.0);
    wheel_torque_ = d.number("wheelTorque", 5.0);
    const double update_rate = d.number("updateRate", 100.0);
    update_gate_.setPeriodNs(periodNsOfRate(update_rate));
    const std::string source = d.text("odometrySource", "world");
    if (source != "world" && source != "encoder")
    {
      context.log().warn(pluginLabel(d) + ": odometrySource '" + source +
                         "' is neither world nor encoder; using world, as gazebo_ros does");
    }
    encoder_odometry_ = source == "encoder";
    publish_tf_ = d.flag("publishTf", true);

    const RobotDescription& robot = context.robotDescription();
    const char* keys[2] = {"leftJoint", "rightJoint"};
    const char* defaults[2] = {"left_joint", "right_joint"};
    for (int side : {kLeft, kRight})
    {
      const std::string joint = d.text(keys[side], defaults[side]);
      motors_[side] = context.modelJoint(joint, pluginLabel(d) + " <" + keys[side] + ">");
      if (!motors_[side])
        return false;
      motors_[side]->setMaxForce(wheel_torque_);
      joint_names_[side] = joint;
      const urdf::JointConstSharedPtr j = robot.model->getJoint(joint);
      wheel_links_[side] = j->child_link_name;
      wheel_frames_[side] = resolveTfFrame(prefix, j->child_link_name);
      wheel_parent_frames_[side] = resolveTfFrame(prefix, j->parent_link_name);
    }
    odometry_.pose_covariance_diagonal = planarCovariance(0.00001, 0.00001, 0.001);

    subscribeCommand(d);
    if (publish_tf_)
      odometry_port_ = &advertise<OdometrySample>(odometry_topic);
    if ((publish_tf_ && publish_odom_tf_) || publish_wheel_tf_)
      tf_port_ = &advertise<TransformSample>("/tf");
    if (publish_wheel_joint_state_)
      joint_state_port_ = &advertise<JointStateSample>("joint_states");
    Reset(time_ns);
    return true;
  }

  void Reset(int64_t time_ns) override
  {
    update_gate_.restart(time_ns);
    last_odometry_ns_ = 0;  // as upstream's, never set before the first encoder update
    encoder_x_ = encoder_y_ = encoder_theta_ = 0.0;
    command_ = TwistCommand();
    wheel_speed_[kLeft] = wheel_speed_[kRight] = 0.0;
    wheel_speed_instr_[kLeft] = wheel_speed_instr_[kRight] = 0.0;
    for (ModelJoint* m : motors_)
    {
      m->setMaxForce(wheel_torque_);
      m->setVelocity(0.0);
    }
  }

  void OnUpdate(int64_t time_ns) override
  {
    if (encoder_odometry_)
      updateOdometryEncoder(time_ns);
    const double since_last_update = (time_ns - update_gate_.lastNs()) * 1e-9;
    if (!update_gate_.due(time_ns))
      return;
    if (publish_tf_)
      publishOdometry(time_ns);
    if (publish_wheel_tf_)
      publishWheelTf(time_ns);
    if (publish_wheel_joint_state_)
      publishWheelJointState(time_ns);

    wheel_speed_[kLeft] = command_.linear_x - command_.angular_z * wheel_separation_ / 2.0;
    wheel_speed_[kRight] = command_.linear_x + command_.angular_z * wheel_separation_ / 2.0;
    const double radius = wheel_diameter_ / 2.0;
    const double current[2] = {motors_[kLeft]->velocity() * radius, motors_[kRight]->velocity() * radius};
    if (wheel_accel_ == 0 || std::fabs(wheel_speed_[kLeft] - current[kLeft]) < 0.01 ||
        std::fabs(wheel_speed_[kRight] - current[kRight]) < 0.01)
    {
      // No ramp, or a wheel at its speed: both set at once.
      motors_[kLeft]->setVelocity(wheel_speed_[kLeft] / radius);
      motors_[kRight]->setVelocity(wheel_speed_[kRight] / radius);
    }
    else
    {
      // Upstream's ramp: the instructed speed moves by at most wheelAcceleration * dt toward the
      // target from where the wheel is (its left test is >=, its right one >; kept).
      const double step = wheel_accel_ * since_last_update;
      wheel_speed_instr_[kLeft] += wheel_speed_[kLeft] >= current[kLeft]
                                       ? std::fmin(wheel_speed_[kLeft] - current[kLeft], step)
                                       : std::fmax(wheel_speed_[kLeft] - current[kLeft], -step);
      wheel_speed_instr_[kRight] += wheel_speed_[kRight] > current[kRight]
                                        ? std::fmin(wheel_speed_[kRight] - current[kRight], step)
                                        : std::fmax(wheel_speed_[kRight] - current[kRight], -step);
      motors_[kLeft]->setVelocity(wheel_speed_instr_[kLeft] / radius);
      motors_[kRight]->setVelocity(wheel_speed_instr_[kRight] / radius);
    }
  }

private:
  // Siegwart's differential odometry from the wheels' rates, every step.
  void updateOdometryEncoder(int64_t time_ns)
  {
    const double dt = (time_ns - last_odometry_ns_) * 1e-9;
    last_odometry_ns_ = time_ns;
    if (dt <= 0)
      return;  // upstream divides by it (NaN rates at time 0); the plant keeps the last odometry
    const double b = wheel_separation_, radius = wheel_diameter_ / 2.0;
    const double sl = motors_[kLeft]->velocity() * radius * dt, sr = motors_[kRight]->velocity() * radius * dt;
    const double ssum = sl + sr, sdiff = sr - sl;
    const double dx = ssum / 2.0 * std::cos(encoder_theta_ + sdiff / (2.0 * b));
    const double dy = ssum / 2.0 * std::sin(encoder_theta_ + sdiff / (2.0 * b));
    const double dtheta = sdiff / b;
    encoder_x_ += dx;
    encoder_y_ += dy;
    encoder_theta_ += dtheta;
    const double v = std::sqrt(dx * dx + dy * dy) / dt;
    odometry_.pose = planarPose(encoder_x_, encoder_y_, encoder_theta_);
    odometry_.angular = urdf::Vector3(0, 0, dtheta / dt);
    odometry_.linear = urdf::Vector3(ssum < 0 ? -v : v, 0, 0);
  }

  void publishOdometry(int64_t time_ns)
  {
    if (!encoder_odometry_)
      readWorldOdometry(*context_, odometry_);
    odometry_.stamp_ns = time_ns;
    if (publish_odom_tf_)
      tf_port_->publish(TransformSample{time_ns, odometry_.frame_id, odometry_.child_frame_id, odometry_.pose});
    odometry_port_->publish(odometry_);
  }

  // Each wheel link's pose in the model frame, stamped as if in its joint's parent link (upstream's).
  void publishWheelTf(int64_t time_ns)
  {
    const urdf::Pose model = context_->linkMotion(context_->rootLink()).pose;
    for (int side : {kLeft, kRight})
    {
      const urdf::Pose wheel = compose(inverse(model), context_->linkMotion(wheel_links_[side]).pose);
      tf_port_->publish(TransformSample{time_ns, wheel_parent_frames_[side], wheel_frames_[side], wheel});
    }
  }

  // Names and positions only, the right wheel first, as upstream's (its joints_[RIGHT] is index 0).
  void publishWheelJointState(int64_t time_ns)
  {
    JointStateSample s;
    s.stamp_ns = time_ns;
    for (int side : {kRight, kLeft})
    {
      s.name.push_back(joint_names_[side]);
      s.position.push_back(motors_[side]->position());
    }
    joint_state_port_->publish(s);
  }

  ModelPluginContext* context_ = nullptr;
  ModelJoint* motors_[2] = {nullptr, nullptr};
  std::string joint_names_[2], wheel_links_[2], wheel_frames_[2], wheel_parent_frames_[2];
  double wheel_separation_ = 0.34, wheel_diameter_ = 0.15, wheel_accel_ = 0.0, wheel_torque_ = 5.0;
  CatchUpRateGate update_gate_;  // updateRate
  int64_t last_odometry_ns_ = 0;
  bool encoder_odometry_ = false, publish_tf_ = true, publish_odom_tf_ = true;
  bool publish_wheel_tf_ = false, publish_wheel_joint_state_ = false;
  double wheel_speed_[2] = {0, 0}, wheel_speed_instr_[2] = {0, 0};
  double encoder_x_ = 0.0, encoder_y_ = 0.0, encoder_theta_ = 0.0;
  OdometrySample odometry_;
  OutputPort<OdometrySample>* odometry_port_ = nullptr;
  OutputPort<TransformSample>* tf_port_ = nullptr;
  OutputPort<JointStateSample>* joint_state_port_ = nullptr;
};
}  // namespace

GAZEBO_ROS_MODEL_PLUGIN(GazeboRosDiffDrive, modelPluginFile(PluginNaming::GazeboRos), "libgazebo_ros_diff_drive.so");

}  // namespace bullet_plant
