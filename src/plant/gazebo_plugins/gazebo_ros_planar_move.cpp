// gazebo_plugins' libgazebo_ros_planar_move.so (ROS 1 Noetic): a holonomic base. Every step the
// model's velocity is set from the last geometry_msgs/Twist on commandTopic (linear x and y turned
// into the world by the model's yaw, z 0; yaw rate angular.z), as Model::SetLinearVel and
// SetAngularVel do; at odometryRate nav_msgs/Odometry on odometryTopic and odometryFrame ->
// robotBaseFrame on /tf, the twist differenced from the last published pose. With cmdTimeout >= 0
// a command older than that many seconds is dropped. Parameters and defaults are upstream's
// (docs/model_plugins.md).
#include <cmath>

#include "gazebo_plugins/twist_drive_plugin.h"

namespace bullet_plant
{
namespace
{
class GazeboRosPlanarMove : public TwistDrivePlugin
{
public:
  bool Load(const ModelPluginDescription& d, ModelPluginContext& context, int64_t time_ns) override
  {
    context_ = &context;
    const std::string odometry_topic = d.text("odometryTopic", "odom");
    readOdometryFrames(d, context, odometry_);
    odometry_rate_ = d.number("odometryRate", 20.0);
    cmd_timeout_ = d.number("cmdTimeout", -1.0);
    odometry_.pose_covariance_diagonal = planarCovariance(0.00001, 0.00001, 0.001);

    subscribeCommand(d);
    odometry_port_ = &advertise<OdometrySample>(odometry_topic);
    tf_port_ = &advertise<TransformSample>("/tf");
    Reset(time_ns);
    return true;
  }

  void Reset(int64_t time_ns) override
  {
    last_odometry_ns_ = last_command_ns_ = time_ns;
    last_odometry_pose_ = modelPose();
    command_ = TwistCommand();
    command_arrived_ = false;
  }

  void OnUpdate(int64_t time_ns) override
  {
    if (command_arrived_)  // upstream stamps a command when its callback runs: the plant's next step
      last_command_ns_ = time_ns;
    command_arrived_ = false;
    if (cmd_timeout_ >= 0 && (time_ns - last_command_ns_) * 1e-9 > cmd_timeout_)
      command_ = TwistCommand();
    const float yaw = yawOf(modelPose().rotation);
    const float c = std::cos(yaw), s = std::sin(yaw);
    const double x = command_.linear_x, y = command_.linear_y;
    context_->setModelVelocity(urdf::Vector3(x * c - y * s, y * c + x * s, 0.0),
                               urdf::Vector3(0, 0, command_.angular_z));
    if (odometry_rate_ > 0.0)
    {
      const double since_last = (time_ns - last_odometry_ns_) * 1e-9;
      if (since_last > 1.0 / odometry_rate_)
      {
        publishOdometry(time_ns, since_last);
        last_odometry_ns_ = time_ns;
      }
    }
  }

private:
  void commandArrived() override { command_arrived_ = true; }

  urdf::Pose modelPose() const { return context_->linkMotion(context_->rootLink()).pose; }

  void publishOdometry(int64_t time_ns, double step_time)
  {
    const urdf::Pose pose = modelPose();
    tf_port_->publish(TransformSample{time_ns, odometry_.frame_id, odometry_.child_frame_id, pose});
    odometry_.stamp_ns = time_ns;
    odometry_.pose = pose;
    odometry_.pose.position.z = 0.0;  // upstream fills x and y of the message
    const urdf::Vector3 world((pose.position.x - last_odometry_pose_.position.x) / step_time,
                              (pose.position.y - last_odometry_pose_.position.y) / step_time, 0.0);
    if (command_.angular_z > M_PI / step_time)
      odometry_.angular = urdf::Vector3(0, 0, command_.angular_z);  // over half a turn per period: not measurable
    else
    {
      const float last_yaw = yawOf(last_odometry_pose_.rotation);
      float current_yaw = yawOf(pose.rotation);
      while (current_yaw < last_yaw - M_PI)
        current_yaw += 2 * M_PI;
      while (current_yaw > last_yaw + M_PI)
        current_yaw -= 2 * M_PI;
      odometry_.angular = urdf::Vector3(0, 0, (current_yaw - last_yaw) / step_time);
    }
    last_odometry_pose_ = pose;
    odometry_.linear = inHeading(yawOf(pose.rotation), world);
    odometry_port_->publish(odometry_);
  }

  ModelPluginContext* context_ = nullptr;
  double odometry_rate_ = 20.0, cmd_timeout_ = -1.0;
  int64_t last_odometry_ns_ = 0, last_command_ns_ = 0;
  bool command_arrived_ = false;  // since the last step
  urdf::Pose last_odometry_pose_;
  OdometrySample odometry_;
  OutputPort<OdometrySample>* odometry_port_ = nullptr;
  OutputPort<TransformSample>* tf_port_ = nullptr;
};
}  // namespace

GAZEBO_ROS_MODEL_PLUGIN(GazeboRosPlanarMove, modelPluginFile(), "libgazebo_ros_planar_move.so");

}  // namespace bullet_plant
