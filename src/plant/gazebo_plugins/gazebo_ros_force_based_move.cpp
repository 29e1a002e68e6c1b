// hector_gazebo_plugins' libgazebo_ros_force_based_move.so (ROS 1), for omnidirectional bases
// driven by a Twist without wheels: every step a force on <robotBaseFrame>, in its frame,
// proportional to the commanded minus the model's planar velocity (x and y gains), and a world yaw
// torque from the yaw rate error; at odometryRate nav_msgs/Odometry integrated from the model's own
// forward speed and yaw rate, with odometryFrame -> robotBaseFrame on /tf. Parameters, defaults and
// formulas are upstream's (docs/model_plugins.md).
#include <cmath>

#include "bullet_plant/geometry.h"
#include "bullet_plant/log.h"
#include "gazebo_plugins/twist_drive_plugin.h"

namespace bullet_plant
{
namespace
{
class GazeboRosForceBasedMove : public TwistDrivePlugin
{
public:
  bool Load(const ModelPluginDescription& d, ModelPluginContext& context, int64_t time_ns) override
  {
    context_ = &context;
    readOdometryFrames(d, context, odometry_);
    base_link_ = d.text("robotBaseFrame", "base_footprint");
    if (!requireLink(d, context, "robotBaseFrame", base_link_, "the forces act on it"))
      return false;
    yaw_gain_ = d.number("yaw_velocity_p_gain", 100.0);
    x_gain_ = d.number("x_velocity_p_gain", 10000.0);
    y_gain_ = d.number("y_velocity_p_gain", 10000.0);
    odometry_rate_ = d.number("odometryRate", 20.0);
    publish_tf_ = d.flag("publishOdometryTf", true);
    subscribeCommand(d);
    odometry_port_ = &advertise<OdometrySample>(d.text("odometryTopic", "odom"));
    if (publish_tf_)
      tf_port_ = &advertise<TransformSample>("/tf");
    Reset(time_ns);
    return true;
  }

  void Reset(int64_t time_ns) override
  {
    command_ = TwistCommand();
    last_odometry_ns_ = time_ns;
    odometry_.pose = urdf::Pose();
  }

  void OnUpdate(int64_t time_ns) override
  {
    const LinkMotion model = context_->linkMotion(context_->rootLink());
    const urdf::Rotation to_model = model.pose.rotation.GetInverse();
    const urdf::Vector3 relative = rotate(to_model, model.velocity);
    const urdf::Vector3 force_in_base((command_.linear_x - relative.x) * x_gain_,
                                      (command_.linear_y - relative.y) * y_gain_, 0.0);
    const urdf::Rotation base = context_->linkMotion(base_link_).pose.rotation;
    context_->addLinkWrench(base_link_, rotate(base, force_in_base),
                            urdf::Vector3(0, 0, -(model.angular_velocity.z - command_.angular_z) * yaw_gain_));
    if (odometry_rate_ > 0.0 && (time_ns - last_odometry_ns_) * 1e-9 > 1.0 / odometry_rate_)
    {
      publishOdometry(time_ns, (time_ns - last_odometry_ns_) * 1e-9, relative.x,
                      rotate(to_model, model.angular_velocity).z);
      last_odometry_ns_ = time_ns;
    }
  }

private:
  // Dead reckoning from the model's forward speed and yaw rate over dt, on an arc (sideways speed
  // is not integrated, as upstream).
  void publishOdometry(int64_t time_ns, double dt, double v, double w)
  {
    urdf::Pose step;
    if (std::fabs(w) < 0.0001)
      step.position = urdf::Vector3(v * dt, 0, 0);
    else
    {
      const double r = v / w;
      step.position = urdf::Vector3(std::sin(w * dt) * r, r - std::cos(w * dt) * r, 0);
      step.rotation.setFromRPY(0, 0, w * dt);
    }
    odometry_.pose = compose(odometry_.pose, step);
    odometry_.stamp_ns = time_ns;
    odometry_.linear = urdf::Vector3(v, 0, 0);
    odometry_.angular = urdf::Vector3(0, 0, w);
    const double yaw_covariance = std::fabs(w) < 0.0001 ? 0.01 : 100.0;
    odometry_.pose_covariance_diagonal = {{0.001, 0.001, 1e12, 1e12, 1e12, yaw_covariance}};
    odometry_.twist_covariance_diagonal = {{0.001, 0.001, 0.001, 1e12, 1e12, yaw_covariance}};
    if (publish_tf_)
      tf_port_->publish(TransformSample{time_ns, odometry_.frame_id, odometry_.child_frame_id, odometry_.pose});
    odometry_port_->publish(odometry_);
  }

  ModelPluginContext* context_ = nullptr;
  std::string base_link_;
  double yaw_gain_ = 100.0, x_gain_ = 10000.0, y_gain_ = 10000.0, odometry_rate_ = 20.0;
  bool publish_tf_ = true;
  int64_t last_odometry_ns_ = 0;
  OdometrySample odometry_;
  OutputPort<OdometrySample>* odometry_port_ = nullptr;
  OutputPort<TransformSample>* tf_port_ = nullptr;
};
}  // namespace

GAZEBO_ROS_MODEL_PLUGIN(GazeboRosForceBasedMove, modelPluginFile(), "libgazebo_ros_force_based_move.so");

}  // namespace bullet_plant
