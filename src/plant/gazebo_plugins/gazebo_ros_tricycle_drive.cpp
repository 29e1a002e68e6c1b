// gazebo_plugins' libgazebo_ros_tricycle_drive.so (ROS 1 Noetic): a front wheel both steered and
// driven. A geometry_msgs/Twist on commandTopic gives the wheel's speed (linear.x, m/s) and the
// steering ANGLE (angular.z, rad, held to +-pi/2); at updateRate the actuated wheel is driven by a
// velocity motor of at most wheelTorque (ramped by wheelAcceleration / wheelDeceleration within
// wheelSpeedTolerance) and the steering joint set to the angle (or turned at steeringSpeed within
// steeringAngleTolerance); nav_msgs/Odometry from the model's world pose or the two rear encoder
// wheels, odometryFrame -> robotBaseFrame on /tf, optionally the four joints' TFs and joint_states.
// Parameters, defaults and upstream's quirks are in docs/model_plugins.md.
#include <cmath>

#include "bullet_plant/geometry.h"
#include "bullet_plant/rate_gate.h"
#include "gazebo_plugins/twist_drive_plugin.h"

namespace bullet_plant
{
namespace
{
enum Wheel { kSteering = 0, kActuated = 1, kEncoderLeft = 2, kEncoderRight = 3 };

class GazeboRosTricycleDrive : public TwistDrivePlugin
{
public:
  bool Load(const ModelPluginDescription& d, ModelPluginContext& context, int64_t time_ns) override
  {
    context_ = &context;
    const std::string prefix = context.tfPrefix(d);
    odometry_.frame_id = resolveTfFrame(prefix, d.text("odometryFrame", "odom"));
    odometry_.child_frame_id = resolveTfFrame(prefix, d.text("robotBaseFrame", "base_link"));
    actuated_diameter_ = d.number("actuatedWheelDiameter", 0.15);
    encoder_diameter_ = d.number("encoderWheelDiameter", 0.15);
    encoder_separation_ = d.number("encoderWheelSeparation", 0.5);
    wheel_torque_ = d.number("wheelTorque", 5.0);
    wheel_acceleration_ = d.number("wheelAcceleration", 0.0);
    wheel_deceleration_ = d.number("wheelDeceleration", wheel_acceleration_);
    wheel_speed_tolerance_ = d.number("wheelSpeedTolerance", 0.01);
    steering_speed_ = d.number("steeringSpeed", 0.0);
    steering_angle_tolerance_ = d.number("steeringAngleTolerance", 0.01);
    actuator_gate_.setPeriodNs(periodNsOfRate(d.number("updateRate", 100.0)));
    encoder_odometry_ = d.text("odometrySource", "world") == "encoder";
    publish_wheel_tf_ = d.flag("publishWheelTF", false);
    publish_wheel_joint_state_ = d.flag("publishWheelJointState", false);

    const char* keys[4] = {"steeringJoint", "actuatedWheelJoint", "encoderWheelLeftJoint", "encoderWheelRightJoint"};
    const char* defaults[4] = {"front_steering_joint", "front_wheel_joint", "left_wheel_joint", "right_wheel_joint"};
    const RobotDescription& robot = context.robotDescription();
    for (int w = 0; w < 4; ++w)
    {
      joint_names_[w] = d.text(keys[w], defaults[w]);
      joints_[w] = context.modelJoint(joint_names_[w], pluginLabel(d) + " <" + keys[w] + ">");
      if (!joints_[w])
        return false;
      const urdf::JointConstSharedPtr j = robot.model->getJoint(joint_names_[w]);
      child_links_[w] = j->child_link_name;
      // upstream names each transform after the joint, in its parent link's frame
      tf_children_[w] = resolveTfFrame(prefix, joint_names_[w]);
      tf_parents_[w] = resolveTfFrame(prefix, j->parent_link_name);
    }
    joints_[kActuated]->setMaxForce(wheel_torque_);
    joints_[kSteering]->setMaxForce(wheel_torque_);
    odometry_.pose_covariance_diagonal = planarCovariance(0.00001, 0.00001, 0.001);  // the twist's: zero

    subscribeCommand(d);
    odometry_port_ = &advertise<OdometrySample>(d.text("odometryTopic", "odom"));
    tf_port_ = &advertise<TransformSample>("/tf");
    if (publish_wheel_joint_state_)
      joint_state_port_ = &advertise<JointStateSample>("joint_states");
    actuator_gate_.restart(time_ns);
    return true;
  }

  // Upstream has no Reset: the command, the encoder pose and the update times stay. After a world
  // reset its gate stays shut until simulated time passes the last update again; so does the plant's.
  void Reset(int64_t) override {}

  void OnUpdate(int64_t time_ns) override
  {
    if (encoder_odometry_)
      updateOdometryEncoder(time_ns);
    const double since_last_update = (time_ns - actuator_gate_.lastNs()) * 1e-9;
    if (!actuator_gate_.due(time_ns))
      return;
    publishOdometry(time_ns);
    if (publish_wheel_tf_)
      publishWheelTf(time_ns);
    if (publish_wheel_joint_state_)
      publishWheelJointState(time_ns);
    motorController(command_.linear_x / (actuated_diameter_ / 2.0), command_.angular_z, since_last_update);
  }

private:
  void motorController(double target_speed, double target_angle, double dt)
  {
    double applied_speed = target_speed;
    const double current_speed = joints_[kActuated]->velocity();
    if (wheel_acceleration_ > 0)
    {
      // upstream's: slowing uses wheelAcceleration, speeding up wheelDeceleration (sic)
      const double diff_speed = current_speed - target_speed;
      if (std::fabs(diff_speed) < wheel_speed_tolerance_)
        applied_speed = current_speed;
      else if (std::fabs(diff_speed) > wheel_acceleration_ * dt)
        applied_speed = diff_speed > 0 ? current_speed - wheel_acceleration_ * dt : current_speed + wheel_deceleration_ * dt;
    }
    joints_[kActuated]->setVelocity(applied_speed);

    target_angle = std::fmax(-M_PI / 2.0, std::fmin(M_PI / 2.0, target_angle));
    const double diff_angle = joints_[kSteering]->position() - target_angle;
    if (steering_speed_ > 0)
    {
      // upstream compares the angle error with the wheel's target speed (sic): kept, as robots tuned
      // in Gazebo steer this way
      double applied_steering_speed = 0.0;
      if (std::fabs(diff_angle) >= steering_angle_tolerance_)
        applied_steering_speed = diff_angle < target_speed ? steering_speed_ : -steering_speed_;
      joints_[kSteering]->setVelocity(applied_steering_speed);
    }
    else
      joints_[kSteering]->setPosition(target_angle, 0.0);
  }

  // Siegwart's odometry from the rear wheels' rates, every step, with upstream's left-minus-right
  // heading (a left turn integrates as a right one) and its twist in the odometry frame.
  void updateOdometryEncoder(int64_t time_ns)
  {
    const double dt = (time_ns - last_odometry_ns_) * 1e-9;
    last_odometry_ns_ = time_ns;
    if (dt <= 0)
      return;  // upstream divides by it
    const double radius = encoder_diameter_ / 2.0, b = encoder_separation_;
    const double sl = joints_[kEncoderLeft]->velocity() * radius * dt;
    const double sr = joints_[kEncoderRight]->velocity() * radius * dt;
    const double theta = encoder_theta_;
    const double dx = (sl + sr) / 2.0 * std::cos(theta + (sl - sr) / (2.0 * b));
    const double dy = (sl + sr) / 2.0 * std::sin(theta + (sl - sr) / (2.0 * b));
    const double dtheta = (sl - sr) / b;
    encoder_x_ += dx;
    encoder_y_ += dy;
    encoder_theta_ += dtheta;
    odometry_.pose = planarPose(encoder_x_, encoder_y_, encoder_theta_);
    odometry_.linear = urdf::Vector3(dx / dt, dy / dt, 0.0);
    odometry_.angular = urdf::Vector3(0, 0, dtheta / dt);
  }

  void publishOdometry(int64_t time_ns)
  {
    if (!encoder_odometry_)
      readWorldOdometry(*context_, odometry_);
    odometry_.stamp_ns = time_ns;
    tf_port_->publish(TransformSample{time_ns, odometry_.frame_id, odometry_.child_frame_id, odometry_.pose});
    odometry_port_->publish(odometry_);
  }

  void publishWheelTf(int64_t time_ns)
  {
    const urdf::Pose model = context_->linkMotion(context_->rootLink()).pose;
    for (int w = 0; w < 4; ++w)
      tf_port_->publish(TransformSample{time_ns, tf_parents_[w], tf_children_[w],
                                        compose(inverse(model), context_->linkMotion(child_links_[w]).pose)});
  }

  void publishWheelJointState(int64_t time_ns)
  {
    JointStateSample s;
    s.stamp_ns = time_ns;
    for (int w = 0; w < 4; ++w)
    {
      s.name.push_back(joint_names_[w]);
      s.position.push_back(joints_[w]->position());
      s.velocity.push_back(joints_[w]->velocity());
      s.effort.push_back(0.0);  // Joint::GetForce reads the force set by SetForce: none here
    }
    joint_state_port_->publish(s);
  }

  ModelPluginContext* context_ = nullptr;
  ModelJoint* joints_[4] = {nullptr, nullptr, nullptr, nullptr};
  std::string joint_names_[4], child_links_[4], tf_children_[4], tf_parents_[4];
  double actuated_diameter_ = 0.15, encoder_diameter_ = 0.15, encoder_separation_ = 0.5, wheel_torque_ = 5.0;
  double wheel_acceleration_ = 0, wheel_deceleration_ = 0, wheel_speed_tolerance_ = 0.01;
  double steering_speed_ = 0, steering_angle_tolerance_ = 0.01;
  CatchUpRateGate actuator_gate_;  // updateRate
  int64_t last_odometry_ns_ = 0;
  bool encoder_odometry_ = false, publish_wheel_tf_ = false, publish_wheel_joint_state_ = false;
  double encoder_x_ = 0, encoder_y_ = 0, encoder_theta_ = 0;
  OdometrySample odometry_;
  OutputPort<OdometrySample>* odometry_port_ = nullptr;
  OutputPort<TransformSample>* tf_port_ = nullptr;
  OutputPort<JointStateSample>* joint_state_port_ = nullptr;
};
}  // namespace

GAZEBO_ROS_MODEL_PLUGIN(GazeboRosTricycleDrive, modelPluginFile(PluginNaming::GazeboRos),
                        "libgazebo_ros_tricycle_drive.so");

}  // namespace bullet_plant
