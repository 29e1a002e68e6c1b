// hector_gazebo_plugins' libhector_gazebo_ros_imu.so (ROS 1): sensor_msgs/Imu of <bodyName> on
// topicName, and the current biases on biasTopicName: the acceleration differenced from the body
// frame's world velocity between updates, less gravity, and the rate from the turn between them,
// both in the (rpyOffset-rotated) body frame through hector's error models (accel, rate); the
// orientation in the world tilted by the accelerometer's bias and turned by the yaw model's, as a
// pseudo-AHRS. Parameters, defaults and formulas are upstream's (docs/model_plugins.md).
#include <algorithm>
#include <cmath>

#include "bullet_plant/geometry.h"
#include "bullet_plant/messages.h"
#include "bullet_plant/hector_sensor_model.h"

namespace bullet_plant
{
namespace
{
double norm(const urdf::Vector3& v) { return std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z); }

class HectorGazeboRosImu : public ModelPlugin
{
public:
  bool Load(const ModelPluginDescription& d, ModelPluginContext& context, int64_t time_ns) override
  {
    context_ = &context;
    if (!readHectorBodyName(d, context, link_))
      return false;
    imu_.frame_id = bias_.frame_id = d.text("frameId", link_);
    const std::string topic = d.text("topicName", "imu");
    accel_model_.load(d, "accel");
    rate_model_.load(d, "rate");
    yaw_model_.load(d, "yaw");
    // The legacy <gaussianNoise> sets both vector models' noise on every axis.
    const double legacy_noise = d.number("gaussianNoise", 0.0);
    if (legacy_noise != 0.0)
    {
      accel_model_.setGaussianNoise(urdf::Vector3(legacy_noise, legacy_noise, legacy_noise));
      rate_model_.setGaussianNoise(urdf::Vector3(legacy_noise, legacy_noise, legacy_noise));
    }
    const urdf::Vector3 rpy = d.vector("rpyOffset", urdf::Vector3(0, 0, 0));
    offset_.setFromRPY(rpy.x, rpy.y, rpy.z);
    timer_.load(d, 0.0, context);
    rng_.seed(context.noiseSeed(d));

    // Covariances from the noise at load, as upstream (which never updates them).
    const urdf::Vector3 accel_noise = accel_model_.gaussianNoise(), rate_noise = rate_model_.gaussianNoise();
    const double g = norm(context.gravity());
    imu_.angular_velocity_covariance_diagonal = {
        {rate_noise.x * rate_noise.x, rate_noise.y * rate_noise.y, rate_noise.z * rate_noise.z}};
    imu_.linear_acceleration_covariance_diagonal = {
        {accel_noise.x * accel_noise.x, accel_noise.y * accel_noise.y, accel_noise.z * accel_noise.z}};
    imu_.orientation_covariance_diagonal = {{g > 0 ? accel_noise.x * accel_noise.x / (g * g) : -1.0,
                                             g > 0 ? accel_noise.y * accel_noise.y / (g * g) : -1.0,
                                             yaw_model_.gaussianNoise().x * yaw_model_.gaussianNoise().x}};
    imu_port_ = &advertise<ImuSample>(topic);
    bias_port_ = &advertise<ImuSample>(d.text("biasTopicName", topic + "/bias"));
    // Upstream's services: calibrate draws the rate model's drift anew, the two others set a bias.
    const std::string calibrate = d.has("serviceName") ? d.text("serviceName", "") : topic + "/calibrate";
    if (!calibrate.empty())
      serve<EmptyRequest, EmptyRequest>(calibrate, [this](const EmptyRequest&, EmptyRequest&) {
        rate_model_.reset(rng_);
        return true;
      });
    serve<SetBiasRequest, EmptyRequest>(topic + "/set_accel_bias", [this](const SetBiasRequest& r, EmptyRequest&) {
      accel_model_.setCurrentDrift(r.bias);
      return true;
    });
    serve<SetBiasRequest, EmptyRequest>(topic + "/set_rate_bias", [this](const SetBiasRequest& r, EmptyRequest&) {
      rate_model_.setCurrentDrift(r.bias);
      return true;
    });
    Reset(time_ns);
    return true;
  }

  void Reset(int64_t) override
  {
    timer_.reset();
    accel_model_.reset(rng_);
    rate_model_.reset(rng_);
    yaw_model_.reset(rng_);
    const LinkMotion body = context_->linkMotion(link_);
    last_orientation_ = offset_ * body.pose.rotation;
    last_velocity_ = body.velocity;
    accel_ = rate_ = urdf::Vector3(0, 0, 0);
  }

  void OnUpdate(int64_t time_ns) override
  {
    if (!timer_.due(time_ns))
      return;
    const double dt = timer_.update(time_ns);
    const LinkMotion body = context_->linkMotion(link_);
    urdf::Rotation rotation = offset_ * body.pose.rotation;
    rotation.normalize();
    const urdf::Vector3 gravity = context_->gravity();
    if (dt > 0.0)
    {
      const urdf::Vector3 specific_force = sub(scaled(sub(body.velocity, last_velocity_), 1.0 / dt), gravity);
      accel_ = rotate(rotation.GetInverse(), specific_force);
      // The turn between the updates as a rotation vector over dt, in the body frame.
      const urdf::Rotation delta = last_orientation_.GetInverse() * rotation;
      const double axis_length = std::sqrt(delta.x * delta.x + delta.y * delta.y + delta.z * delta.z);
      const double angle = 2.0 * std::acos(std::max(-1.0, std::min(delta.w, 1.0)));
      const urdf::Vector3 turn = axis_length > 0 ? scaled(urdf::Vector3(delta.x, delta.y, delta.z), angle / axis_length / dt)
                                                 : urdf::Vector3(0, 0, 0);
      rate_ = rotate(offset_.GetInverse(), turn);
    }
    last_orientation_ = rotation;
    last_velocity_ = body.velocity;

    const urdf::Vector3 accel = accel_model_(accel_, dt, rng_);
    const urdf::Vector3 rate = rate_model_(rate_, dt, rng_);
    yaw_model_(urdf::Vector3(0, 0, 0), dt, rng_);

    // The pseudo-AHRS: the accelerometer's bias tilts the estimate, the yaw model's bias turns it.
    const urdf::Vector3 accel_bias = accel_model_.currentBias(), rate_bias = rate_model_.currentBias();
    const urdf::Vector3 accel_drift = rotate(body.pose.rotation, accel_bias);
    const double g = norm(gravity), yaw_error = yaw_model_.currentBias().x;
    urdf::Rotation yaw_turn(0, 0, std::sin(yaw_error / 2), std::cos(yaw_error / 2));
    urdf::Rotation tilt(g > 0 ? 0.5 * accel_drift.y / g : 0.0, g > 0 ? -0.5 * accel_drift.x / g : 0.0, 0, 1);
    urdf::Rotation error = yaw_turn * tilt;
    error.normalize();

    imu_.stamp_ns = bias_.stamp_ns = time_ns;
    imu_.orientation = error * rotation;
    imu_.angular_velocity = rate;
    imu_.linear_acceleration = accel;
    imu_port_->publish(imu_);
    bias_.orientation = error;
    bias_.angular_velocity = rate_bias;
    bias_.linear_acceleration = accel_bias;
    bias_port_->publish(bias_);
  }

private:
  ModelPluginContext* context_ = nullptr;
  std::string link_;
  urdf::Rotation offset_;
  HectorSensorModel accel_model_, rate_model_, yaw_model_;
  HectorUpdateTimer timer_;
  std::mt19937 rng_;
  urdf::Rotation last_orientation_;
  urdf::Vector3 last_velocity_, accel_, rate_;
  ImuSample imu_, bias_;
  OutputPort<ImuSample>* imu_port_ = nullptr;
  OutputPort<ImuSample>* bias_port_ = nullptr;
};
}  // namespace

GAZEBO_ROS_MODEL_PLUGIN(HectorGazeboRosImu, modelPluginFile(), "libhector_gazebo_ros_imu.so");

}  // namespace bullet_plant
