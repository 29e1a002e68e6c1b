// Gazebo 11's HarnessPlugin (libHarnessPlugin.so), a model plugin of Gazebo's own that
// gazebo_ros_pkgs' gazebo_ros_harness derives from: it holds a model up by joints it makes at run
// time from its <joint> elements (typically a prismatic joint from the world to a link), lowers or
// raises it with a winch (the <winch><joint>, driven by force through a position and a velocity PID)
// and lets go on a signal (the <detach> joint). Commanded in GzStrings on
// ~/<model>/harness/velocity (a target winch speed, m/s) and ~/<model>/harness/detach ("true"), or
// by SetWinchVelocity and Detach.
#pragma once

#include <mutex>
#include <string>
#include <vector>

#include <sdf/sdf.hh>

#include "gazebo/common/PID.hh"
#include "gazebo/common/Plugin.hh"
#include "gazebo/common/Time.hh"
#include "gazebo/common/UpdateInfo.hh"
#include "gazebo/msgs/msgs.hh"
#include "gazebo/physics/PhysicsTypes.hh"
#include "gazebo/transport/TransportTypes.hh"
#include "gazebo/util/system.hh"

namespace gazebo
{
class GAZEBO_VISIBLE HarnessPlugin : public ModelPlugin
{
public:
  HarnessPlugin();
  ~HarnessPlugin() override;
  void Load(physics::ModelPtr _model, sdf::ElementPtr _sdf) override;
  void Init() override;
  // The winch's target speed along its joint (0: hold where it is now).
  void SetWinchVelocity(const float _value);
  double WinchVelocity() const;
  // Lets go of the <detach> joint for good; the winch stops with it. From any thread.
  void Detach();

private:
  void OnUpdate(const common::UpdateInfo& _info);
  void OnVelocity(ConstGzStringPtr& _msg);
  void OnDetach(ConstGzStringPtr& _msg);
  // The index in `joints` of the joint of that name, or -1.
  int JointIndex(const std::string& _name) const;

  std::vector<physics::JointPtr> joints;
  int winchIndex = 0;
  int detachIndex = 0;
  common::PID winchPosPID;
  common::PID winchVelPID;
  float winchTargetPos = 0.0;
  float winchTargetVel = 0.0;
  common::Time prevSimTime = common::Time::Zero;
  physics::WorldPtr world;
  transport::NodePtr node;
  transport::SubscriberPtr velocitySub;
  transport::SubscriberPtr detachSub;
  event::ConnectionPtr updateConnection;
  // The targets and the joints, set from the transport's and ROS's threads, read each world update.
  mutable std::recursive_mutex mutex;
};
}  // namespace gazebo
