// hector_gazebo_plugins' libhector_gazebo_ros_gps.so (ROS 1): the world position of <bodyName> as
// sensor_msgs/NavSatFix on topicName and its velocity as geometry_msgs/Vector3Stamped (north, west,
// up) on velocityTopicName, through hector's error models, on a flat earth tangent at the
// reference latitude, longitude, heading and altitude (WGS84 radii of curvature there). Parameters,
// defaults, the phase-locked update timer and the formulas are upstream's (docs/model_plugins.md).
#include <cmath>

#include "bullet_plant/messages.h"
#include "bullet_plant/hector_sensor_model.h"

namespace bullet_plant
{
namespace
{
constexpr double kEquatorialRadius = 6378137.0;       // WGS84 a, m
constexpr double kFlattening = 1.0 / 298.257223563;  // WGS84 f
constexpr double kDegrees = 180.0 / M_PI;

class HectorGazeboRosGps : public ModelPlugin
{
public:
  bool Load(const ModelPluginDescription& d, ModelPluginContext& context, int64_t time_ns) override
  {
    context_ = &context;
    if (!readHectorBodyName(d, context, link_))
      return false;
    fix_.frame_id = velocity_.frame_id = d.text("frameId", "/world");  // as given: upstream resolves no prefix
    reference_latitude_ = d.number("referenceLatitude", 49.9);
    reference_longitude_ = d.number("referenceLongitude", 8.9);
    reference_heading_ = d.number("referenceHeading", 0.0) / kDegrees;
    reference_altitude_ = d.number("referenceAltitude", 0.0);
    fix_.status = int(d.number("status", 0));
    fix_.service = int(d.number("service", 0));
    position_model_.load(d, "");
    velocity_model_.load(d, "velocity");
    timer_.load(d, 4.0, context);
    // The radii of curvature at the reference latitude, once, as upstream.
    const double e2 = 2 * kFlattening - kFlattening * kFlattening;
    const double s = std::sin(reference_latitude_ / kDegrees);
    const double temp = 1.0 / (1.0 - e2 * s * s);
    const double prime_vertical = kEquatorialRadius * std::sqrt(temp);
    radius_north_ = prime_vertical * (1 - e2) * temp;
    radius_east_ = prime_vertical * std::cos(reference_latitude_ / kDegrees);
    rng_.seed(context.noiseSeed(d));
    fix_port_ = &advertise<NavSatFixSample>(d.text("topicName", "fix"));
    velocity_port_ = &advertise<Vector3StampedSample>(d.text("velocityTopicName", "fix_velocity"));
    Reset(time_ns);
    return true;
  }

  void Reset(int64_t) override
  {
    timer_.reset();
    position_model_.reset(rng_);
    velocity_model_.reset(rng_);
  }

  void OnUpdate(int64_t time_ns) override
  {
    if (!timer_.due(time_ns))
      return;
    const double dt = timer_.update(time_ns);
    const LinkMotion body = context_->linkMotion(link_);
    const urdf::Vector3 velocity = velocity_model_(body.velocity, dt, rng_);
    const urdf::Vector3 position = position_model_(body.pose.position, dt, rng_);
    // A velocity offset integrates into the position error from the next update on.
    const urdf::Vector3 drift = position_model_.currentDrift(), velocity_drift = velocity_model_.currentDrift();
    position_model_.setCurrentDrift(urdf::Vector3(drift.x + dt * velocity_drift.x, drift.y + dt * velocity_drift.y,
                                                  drift.z + dt * velocity_drift.z));

    const double c = std::cos(reference_heading_), s = std::sin(reference_heading_);
    fix_.stamp_ns = velocity_.stamp_ns = time_ns;
    fix_.latitude = reference_latitude_ + (c * position.x + s * position.y) / radius_north_ * kDegrees;
    fix_.longitude = reference_longitude_ - (-s * position.x + c * position.y) / radius_east_ * kDegrees;
    fix_.altitude = reference_altitude_ + position.z;
    const urdf::Vector3 sigma = position_model_.drift(), noise = position_model_.gaussianNoise();
    fix_.position_covariance_diagonal = {{sigma.x * sigma.x + noise.x * noise.x, sigma.y * sigma.y + noise.y * noise.y,
                                          sigma.z * sigma.z + noise.z * noise.z}};
    velocity_.vector = urdf::Vector3(c * velocity.x + s * velocity.y, -s * velocity.x + c * velocity.y, velocity.z);
    fix_port_->publish(fix_);
    velocity_port_->publish(velocity_);
  }

private:
  ModelPluginContext* context_ = nullptr;
  std::string link_;
  double reference_latitude_ = 49.9, reference_longitude_ = 8.9, reference_heading_ = 0, reference_altitude_ = 0;
  double radius_north_ = 0, radius_east_ = 0;
  HectorSensorModel position_model_, velocity_model_;
  HectorUpdateTimer timer_;
  std::mt19937 rng_;
  NavSatFixSample fix_;
  Vector3StampedSample velocity_;
  OutputPort<NavSatFixSample>* fix_port_ = nullptr;
  OutputPort<Vector3StampedSample>* velocity_port_ = nullptr;
};
}  // namespace

GAZEBO_ROS_MODEL_PLUGIN(HectorGazeboRosGps, modelPluginFile(), "libhector_gazebo_ros_gps.so");

}  // namespace bullet_plant
