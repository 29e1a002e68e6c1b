// hector_gazebo_plugins' libhector_gazebo_ros_magnetic.so (ROS 1): the earth's magnetic field in
// <bodyName>'s frame as geometry_msgs/Vector3Stamped on topicName, from <magnitude>, the reference
// heading, <declination> and <inclination> (north-west-up world, compass angles), through hector's
// error model. Parameters, defaults and the formula are upstream's (docs/model_plugins.md).
#include <cmath>

#include "bullet_plant/geometry.h"
#include "bullet_plant/messages.h"
#include "bullet_plant/hector_sensor_model.h"

namespace bullet_plant
{
namespace
{
class HectorGazeboRosMagnetic : public ModelPlugin
{
public:
  bool Load(const ModelPluginDescription& d, ModelPluginContext& context, int64_t time_ns) override
  {
    context_ = &context;
    if (!readHectorBodyName(d, context, link_))
      return false;
    field_.frame_id = d.text("frameId", link_);
    const double magnitude = d.number("magnitude", 1.0);
    const double heading = d.number("referenceHeading", 0.0) * M_PI / 180;
    const double declination = d.number("declination", 0.0) * M_PI / 180;
    const double inclination = d.number("inclination", 60.0) * M_PI / 180;
    world_field_ = urdf::Vector3(magnitude * std::cos(inclination) * std::cos(heading - declination),
                                 magnitude * std::cos(inclination) * std::sin(heading - declination),
                                 -magnitude * std::sin(inclination));
    model_.load(d, "");
    timer_.load(d, 0.0, context);
    rng_.seed(context.noiseSeed(d));
    port_ = &advertise<Vector3StampedSample>(d.text("topicName", "magnetic"));
    Reset(time_ns);
    return true;
  }

  void Reset(int64_t) override
  {
    timer_.reset();
    model_.reset(rng_);
  }

  void OnUpdate(int64_t time_ns) override
  {
    if (!timer_.due(time_ns))
      return;
    const double dt = timer_.update(time_ns);
    const urdf::Rotation orientation = context_->linkMotion(link_).pose.rotation;
    field_.stamp_ns = time_ns;
    field_.vector = model_(rotate(orientation.GetInverse(), world_field_), dt, rng_);
    port_->publish(field_);
  }

private:
  ModelPluginContext* context_ = nullptr;
  std::string link_;
  urdf::Vector3 world_field_;
  HectorSensorModel model_;
  HectorUpdateTimer timer_;
  std::mt19937 rng_;
  Vector3StampedSample field_;
  OutputPort<Vector3StampedSample>* port_ = nullptr;
};
}  // namespace

GAZEBO_ROS_MODEL_PLUGIN(HectorGazeboRosMagnetic, modelPluginFile(), "libhector_gazebo_ros_magnetic.so");

}  // namespace bullet_plant
