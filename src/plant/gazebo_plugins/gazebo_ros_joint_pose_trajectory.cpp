// gazebo_plugins' libgazebo_ros_joint_pose_trajectory.so (ROS 1 Noetic): a trajectory_msgs/
// JointTrajectory on <topicName> ("set_joint_trajectory"; empty: none) is played by setting the
// joints' positions, one point per update, with the world's physics off while it plays; the model
// kept where it was (or its header.frame_id link, when that names one). The timing is upstream's:
// the first point at max(header.stamp, now), each next one time_from_start of the point before it
// later (docs/model_plugins.md).
#include <algorithm>
#include <cmath>

#include "bullet_plant/action_messages.h"
#include "bullet_plant/log.h"
#include "bullet_plant/model_plugin.h"

namespace bullet_plant
{
namespace
{
class GazeboRosJointPoseTrajectory : public ModelPlugin
{
public:
  bool Load(const ModelPluginDescription& d, ModelPluginContext& context, int64_t) override
  {
    context_ = &context;
    label_ = pluginLabel(d);
    const std::string topic = d.has("topicName") ? d.text("topicName", "") : "set_joint_trajectory";
    if (!topic.empty())
      subscribe<JointTrajectoryCommand>(topic, [this](const JointTrajectoryCommand& t) { return setTrajectory(t); });
    return true;
  }

  // A reset ends the trajectory and gives the world its physics back (upstream's would keep them
  // off until sim time caught up with the trajectory again).
  void Reset(int64_t) override
  {
    if (playing_)
      finish();
  }

  void OnUpdate(int64_t time_ns) override
  {
    // Gazebo's sim time at world update begin is the end of the coming step (World::Step adds
    // the step before Update); between steps, when a message comes, it is the world's time.
    now_ns_ = time_ns + int64_t(std::llround(context_->stepSize() * 1e9));
    if (!playing_ || now_ns_ < start_ns_)
      return;
    if (index_ >= trajectory_.points.size())
    {
      finish();
      return;
    }
    const TrajectoryPointSample& point = trajectory_.points[index_];
    context_->log().info(label_ + ": time [" + std::to_string(now_ns_ * 1e-9) + "] updating configuration [" +
                         std::to_string(index_) + "/" + std::to_string(trajectory_.points.size()) + "]");
    const std::string reference = reference_link_.empty() ? context_->rootLink() : reference_link_;
    const urdf::Pose reference_pose = context_->linkMotion(reference).pose;
    if (point.positions.size() == trajectory_.joint_names.size())
    {
      for (size_t j = 0; j < trajectory_.joint_names.size(); ++j)
        context_->setJointPosition(trajectory_.joint_names[j], point.positions[j]);  // unknown ones: skipped
      context_->setLinkWorldPose(reference, reference_pose);
    }
    else
      context_->log().error(label_ + ": point[" + std::to_string(index_) + "] in JointTrajectory has different number of "
                            "joint names[" + std::to_string(trajectory_.joint_names.size()) + "] and positions[" +
                            std::to_string(point.positions.size()) + "].");
    start_ns_ += point.time_from_start_ns;
    ++index_;
  }

private:
  bool setTrajectory(const JointTrajectoryCommand& t)
  {
    const std::string& frame = t.frame_id;
    std::string reference;
    if (frame != "world" && frame != "/map" && frame != "map")
    {
      // A link of this model, by its name or scoped "model::link".
      const std::string scope = context_->modelName() + "::";
      reference = frame.compare(0, scope.size(), scope) == 0 ? frame.substr(scope.size()) : frame;
      if (!context_->robotDescription().model->getLink(reference))
      {
        context_->log().error(label_ + ": ros_joint_trajectory plugin needs a reference link [" + frame +
                              "] as frame_id, aborting.");
        return false;
      }
    }
    if (!playing_)
      physics_was_enabled_ = context_->physicsEnabled();  // a trajectory replacing one: as before the first
    trajectory_ = t;
    reference_link_ = reference;
    start_ns_ = std::max(t.stamp_ns, now_ns_);
    index_ = 0;
    playing_ = true;
    context_->setPhysicsEnabled(false);
    return true;
  }

  void finish()
  {
    playing_ = false;
    reference_link_.clear();
    context_->setPhysicsEnabled(physics_was_enabled_);
  }

  ModelPluginContext* context_ = nullptr;
  std::string label_, reference_link_;
  JointTrajectoryCommand trajectory_;
  size_t index_ = 0;
  int64_t start_ns_ = 0, now_ns_ = 0;
  bool playing_ = false, physics_was_enabled_ = true;
};
}  // namespace

GAZEBO_ROS_MODEL_PLUGIN(GazeboRosJointPoseTrajectory, modelPluginFile(), "libgazebo_ros_joint_pose_trajectory.so");

}  // namespace bullet_plant
