// physics::PhysicsEngine as plugins use it: the step and its pace, joints made at run time, and the
// mutex the simulator holds while it updates the world (a plugin's ROS callbacks take it to act
// between steps).
#pragma once

#include <memory>
#include <string>

#include <boost/thread/recursive_mutex.hpp>
#include <ignition/math/Vector3.hh>

#include "gazebo/physics/PhysicsTypes.hh"
#include "gazebo/transport/TransportTypes.hh"
#include "gazebo/util/system.hh"

namespace gazebo
{
namespace msgs
{
class Physics;
}
namespace physics
{
class WorldBridge;

class GZ_PHYSICS_VISIBLE PhysicsEngine
{
public:
  explicit PhysicsEngine(std::shared_ptr<WorldBridge> bridge);
  virtual ~PhysicsEngine();
  // "bullet": the engine under the plant.
  std::string GetType() const;
  double GetMaxStepSize() const;
  // Within the simulator's bounds; another is refused with an error naming it.
  void SetMaxStepSize(double step);
  double GetRealTimeUpdateRate() const;
  // The world's gravity from the next step on (m/s^2, world frame).
  ignition::math::Vector3d GetGravity() const;
  void SetGravity(const ignition::math::Vector3d& gravity);
  double GetTargetRealTimeFactor() const;
  // A joint between two links made at run time ("fixed", "revolute", "prismatic", ...): it holds
  // nothing until Attach (or Load and Init). `parent` is the model it belongs to.
  JointPtr CreateJoint(const std::string& type, ModelPtr parent = ModelPtr());
  boost::recursive_mutex* GetPhysicsUpdateMutex() const;

private:
  // ~/physics (msgs::Physics), as Gazebo's engine takes it: gravity, max_step_size and
  // enable_physics; what the plant does not change from a message (the solver's settings, the real
  // time rate and factor) one gzwarn naming it.
  void OnPhysicsMsg(const boost::shared_ptr<const msgs::Physics>& msg);

  std::shared_ptr<WorldBridge> bridge_;
  mutable boost::recursive_mutex update_mutex_;
  transport::NodePtr node_;
  transport::SubscriberPtr physics_sub_;
};
}  // namespace physics
}  // namespace gazebo
