// gazebo_plugins' libgazebo_ros_hand_of_god.so (ROS 1 Noetic): <linkName> (required) is pulled by a
// critically damped spring to the pose tf gives for "<frameId>_desired" in "world" (the latest,
// tf2's lookupTransform at time 0), its gravity off: a force kl * error - cl * velocity in the
// world and a torque ka * log(rotation error) - ca * angular velocity in the link's frame,
// cl = 2 sqrt(kl m), ca = 2 sqrt(ka Ixx); its actual pose is broadcast as world ->
// "<frameId>_actual" every step (docs/model_plugins.md).
#include <cmath>
#include <map>

#include "bullet_plant/geometry.h"
#include "bullet_plant/log.h"
#include "bullet_plant/model_plugin.h"

namespace bullet_plant
{
namespace
{
std::string withoutLeadingSlash(const std::string& frame) { return !frame.empty() && frame[0] == '/' ? frame.substr(1) : frame; }

// What the plugin keeps of /tf and /tf_static: the latest transform to each child frame, and the
// pose of a frame in another found through their common root (tf2's lookupTransform at time 0).
class LatestTransforms
{
public:
  void add(const TransformsCommand& message)
  {
    for (const TransformSample& t : message.transforms)
      parent_of_[withoutLeadingSlash(t.child_frame_id)] = {withoutLeadingSlash(t.frame_id), t.pose};
  }

  // The pose of `source` in `target`; false with tf2's kind of reason.
  bool lookup(const std::string& target, const std::string& source, urdf::Pose& pose, std::string& error) const
  {
    std::string target_root, source_root;
    urdf::Pose target_in_root, source_in_root;
    if (!inRoot(target, target_root, target_in_root))
    {
      error = "\"" + target + "\" passed to lookupTransform argument target_frame does not exist. ";
      return false;
    }
    if (!inRoot(source, source_root, source_in_root))
    {
      error = "\"" + source + "\" passed to lookupTransform argument source_frame does not exist. ";
      return false;
    }
    if (target_root != source_root)
    {
      error = "Could not find a connection between '" + target + "' and '" + source +
              "' because they are not part of the same tree.Tf has two or more unconnected trees.";
      return false;
    }
    pose = compose(inverse(target_in_root), source_in_root);
    return true;
  }

private:
  // The frame's pose in the root of its tree; false for a frame tf has never heard of.
  bool inRoot(const std::string& frame, std::string& root, urdf::Pose& pose) const
  {
    auto known = [&](const std::string& f) {
      if (parent_of_.count(f))
        return true;
      for (const auto& kv : parent_of_)
        if (kv.second.first == f)
          return true;
      return false;
    };
    if (!known(frame))
      return false;
    pose = urdf::Pose();
    root = frame;
    for (size_t hops = 0; hops <= parent_of_.size(); ++hops)  // a loop in what was sent ends here
    {
      auto up = parent_of_.find(root);
      if (up == parent_of_.end())
        return true;
      pose = compose(up->second.second, pose);
      root = up->second.first;
    }
    return true;
  }

  std::map<std::string, std::pair<std::string, urdf::Pose>> parent_of_;  // child -> (parent, pose in it)
};

// ignition's Quaternion::Log: (0, v * angle / sin(angle)) for w = cos(angle); the half-angle axis.
urdf::Vector3 quaternionLog(const urdf::Rotation& q)
{
  if (std::fabs(q.w) < 1.0)
  {
    const double angle = std::acos(q.w), s = std::sin(angle);
    if (std::fabs(s) >= 1e-3)
      return urdf::Vector3(q.x * angle / s, q.y * angle / s, q.z * angle / s);
  }
  return urdf::Vector3(q.x, q.y, q.z);
}

class GazeboRosHandOfGod : public ModelPlugin
{
public:
  bool Load(const ModelPluginDescription& d, ModelPluginContext& context, int64_t) override
  {
    context_ = &context;
    label_ = pluginLabel(d);
    frame_id_ = d.text("frameId", "hog");
    kl_ = d.number("kl", 200.0);
    ka_ = d.number("ka", 200.0);
    if (!d.has("linkName"))
    {
      context.log().error(label_ + ": The hand-of-god plugin requires a `linkName` parameter tag; it is not loaded");
      return false;
    }
    link_ = d.text("linkName", "");
    if (!requireLink(d, context, "linkName", link_, "the floating link"))
      return false;
    mass_ = context.linkMass(link_);
    cl_ = 2.0 * std::sqrt(kl_ * mass_);
    ca_ = 2.0 * std::sqrt(ka_ * context.linkIxx(link_));
    for (const char* topic : {"/tf", "/tf_static"})
      subscribe<TransformsCommand>(topic, [this](const TransformsCommand& m) {
        tf_.add(m);
        return true;
      });
    actual_port_ = &advertise<TransformSample>("/tf");
    return true;
  }

  void OnUpdate(int64_t time_ns) override
  {
    const urdf::Vector3 anti_gravity = scaled(context_->gravity(), -mass_);  // SetGravityMode(false)
    urdf::Pose desired;
    std::string error;
    if (!tf_.lookup("world", frame_id_ + "_desired", desired, error))
    {
      if (!errored_)
        context_->log().error(label_ + ": " + error);
      errored_ = true;
      context_->addLinkWrench(link_, anti_gravity, urdf::Vector3());
      return;
    }
    errored_ = false;
    const LinkMotion actual = context_->linkMotion(link_);
    const urdf::Rotation& rotation = actual.pose.rotation;
    const urdf::Vector3 position_error = sub(desired.position, actual.pose.position);
    const urdf::Vector3 rotation_error = quaternionLog(rotation.GetInverse() * desired.rotation);
    const urdf::Vector3 relative_angular_velocity = rotate(rotation.GetInverse(), actual.angular_velocity);
    const urdf::Vector3 force(kl_ * position_error.x - cl_ * actual.velocity.x + anti_gravity.x,
                              kl_ * position_error.y - cl_ * actual.velocity.y + anti_gravity.y,
                              kl_ * position_error.z - cl_ * actual.velocity.z + anti_gravity.z);
    const urdf::Vector3 relative_torque(ka_ * rotation_error.x - ca_ * relative_angular_velocity.x,
                                        ka_ * rotation_error.y - ca_ * relative_angular_velocity.y,
                                        ka_ * rotation_error.z - ca_ * relative_angular_velocity.z);
    context_->addLinkWrench(link_, force, rotate(rotation, relative_torque));
    actual_port_->publish(TransformSample{time_ns, "world", frame_id_ + "_actual", actual.pose});
  }

private:
  ModelPluginContext* context_ = nullptr;
  std::string label_, frame_id_, link_;
  double kl_ = 200.0, ka_ = 200.0, cl_ = 0.0, ca_ = 0.0, mass_ = 0.0;
  bool errored_ = false;
  LatestTransforms tf_;
  OutputPort<TransformSample>* actual_port_ = nullptr;
};
}  // namespace

GAZEBO_ROS_MODEL_PLUGIN(GazeboRosHandOfGod, modelPluginFile(), "libgazebo_ros_hand_of_god.so");

}  // namespace bullet_plant
