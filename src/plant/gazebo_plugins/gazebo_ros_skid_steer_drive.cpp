// gazebo_plugins' libgazebo_ros_skid_steer_drive.so (ROS 1 Noetic): a geometry_msgs/Twist on
// commandTopic turns four wheel joints, the left pair at v - w b/2 and the right pair at v + w b/2
// (b = wheelSeparation), each by a velocity motor of at most <torque>; nav_msgs/Odometry on
// odometryTopic from the model's world pose, with odometryFrame -> robotBaseFrame on /tf only when
// broadcastTF is true. Parameters, defaults, the update gate and the odometry are upstream's
// (docs/model_plugins.md).
#include "bullet_plant/rate_gate.h"
#include "gazebo_plugins/twist_drive_plugin.h"

namespace bullet_plant
{
namespace
{
// Upstream's wheel order.
enum Wheel { kRightFront = 0, kLeftFront = 1, kRightRear = 2, kLeftRear = 3 };

class GazeboRosSkidSteerDrive : public TwistDrivePlugin
{
public:
  bool Load(const ModelPluginDescription& d, ModelPluginContext& context, int64_t time_ns) override
  {
    context_ = &context;
    broadcast_tf_ = d.flag("broadcastTF", false);
    wheel_separation_ = d.number("wheelSeparation", 0.4);
    wheel_diameter_ = d.number("wheelDiameter", 0.15);
    torque_ = d.number("torque", 5.0);
    const std::string odometry_topic = d.text("odometryTopic", "odom");
    readOdometryFrames(d, context, odometry_);
    const double update_rate = d.number("updateRate", 100.0);
    update_gate_.setPeriodNs(periodNsOfRate(update_rate));
    odometry_.pose_covariance_diagonal = odometry_.twist_covariance_diagonal =
        planarCovariance(d.number("covariance_x", 0.0001), d.number("covariance_y", 0.0001),
                         d.number("covariance_yaw", 0.01));

    const char* keys[4] = {"rightFrontJoint", "leftFrontJoint", "rightRearJoint", "leftRearJoint"};
    const char* defaults[4] = {"right_front_joint", "left_front_joint", "right_rear_joint", "left_rear_joint"};
    for (int w = 0; w < 4; ++w)
    {
      joints_[w] = context.modelJoint(d.text(keys[w], defaults[w]),
                                      pluginLabel(d) + " <" + keys[w] + ">");
      if (!joints_[w])
        return false;
      joints_[w]->setMaxForce(torque_);
    }

    subscribeCommand(d);
    odometry_port_ = &advertise<OdometrySample>(odometry_topic);
    if (broadcast_tf_)
      tf_port_ = &advertise<TransformSample>("/tf");
    Reset(time_ns);
    return true;
  }

  // Upstream has no Reset: Gazebo's default leaves the last command and the gate's clock; the
  // plant's reset puts the plugin back to how Load left it, as a reset world expects.
  void Reset(int64_t time_ns) override
  {
    update_gate_.restart(time_ns);
    command_ = TwistCommand();
    for (ModelJoint* j : joints_)
      j->setVelocity(0.0);
  }

  void OnUpdate(int64_t time_ns) override
  {
    if (!update_gate_.due(time_ns))
      return;
    publishOdometry(time_ns);
    const double radius = wheel_diameter_ / 2.0;
    const double v = command_.linear_x, w = command_.angular_z;
    const double left = v - w * wheel_separation_ / 2.0, right = v + w * wheel_separation_ / 2.0;
    joints_[kLeftFront]->setVelocity(left / radius);
    joints_[kRightFront]->setVelocity(right / radius);
    joints_[kLeftRear]->setVelocity(left / radius);
    joints_[kRightRear]->setVelocity(right / radius);
  }

private:
  void publishOdometry(int64_t time_ns)
  {
    const LinkMotion model = context_->linkMotion(context_->rootLink());
    odometry_.stamp_ns = time_ns;
    if (broadcast_tf_)
      tf_port_->publish(TransformSample{time_ns, odometry_.frame_id, odometry_.child_frame_id, model.pose});
    // Upstream fills the message's x and y and leaves z at 0; the transform carries all three.
    odometry_.pose = model.pose;
    odometry_.pose.position.z = 0.0;
    odometry_.linear = inHeading(yawOf(model.pose.rotation), model.velocity);
    odometry_.angular = urdf::Vector3(0, 0, model.angular_velocity.z);
    odometry_port_->publish(odometry_);
  }

  ModelPluginContext* context_ = nullptr;
  ModelJoint* joints_[4] = {nullptr, nullptr, nullptr, nullptr};
  double wheel_separation_ = 0.4, wheel_diameter_ = 0.15, torque_ = 5.0;
  bool broadcast_tf_ = false;
  CatchUpRateGate update_gate_;  // updateRate
  OdometrySample odometry_;
  OutputPort<OdometrySample>* odometry_port_ = nullptr;
  OutputPort<TransformSample>* tf_port_ = nullptr;
};
}  // namespace

GAZEBO_ROS_MODEL_PLUGIN(GazeboRosSkidSteerDrive, modelPluginFile(), "libgazebo_ros_skid_steer_drive.so");

}  // namespace bullet_plant
