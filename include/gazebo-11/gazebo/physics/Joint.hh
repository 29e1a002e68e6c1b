// physics::Joint: a model's movable joint as a plugin drives it (its position and velocity, and an
// effort, a velocity or a position set; axis 0, a joint of the plant having one axis), and a joint
// made at run time (PhysicsEngine::CreateJoint) that holds two links together until detached.
#pragma once

#include <limits>
#include <memory>
#include <string>

#include <boost/any.hpp>
#include <ignition/math/Pose3.hh>

#include "gazebo/physics/JointWrench.hh"
#include "gazebo/physics/PhysicsTypes.hh"
#include "gazebo/util/system.hh"

namespace gazebo
{
namespace physics
{
class JointBridge;
class WorldBridge;

class GZ_PHYSICS_VISIBLE Joint
{
public:
  // A model's joint, between two of its links.
  Joint(const std::string& name, std::unique_ptr<JointBridge> bridge, const std::string& model_name, LinkPtr parent,
        LinkPtr child);
  // A joint made at run time, of `type`, belonging to `model`, in the world of `world`.
  Joint(const std::string& type, ModelPtr model, std::shared_ptr<WorldBridge> world);
  ~Joint();
  std::string GetName() const;
  // MODEL::JOINT (the world's name first where asked, as Gazebo's).
  std::string GetScopedName(bool prependWorldName = false) const;
  void SetName(const std::string& name);
  // Axis 0; another axis is 0 with one error naming the joint.
  double Position(unsigned int index = 0) const;
  double GetVelocity(unsigned int index) const;
  // Joint::SetVelocity: the joint moving at `velocity` now (the rest of the model keeps its motion).
  void SetVelocity(unsigned int index, double velocity);
  // An effort (N m or N) added for the coming step.
  void SetForce(unsigned int index, double effort);
  // The efforts SetForce gave for the coming step, or the last step's until the next SetForce, as
  // Gazebo's.
  double GetForce(unsigned int index);
  bool SetPosition(unsigned int index, double position, bool preserveWorldVelocity = false);
  // The model's limits (-inf / inf where it has none); a joint made at run time keeps what it is set.
  double LowerLimit(unsigned int index = 0) const;
  double UpperLimit(unsigned int index = 0) const;
  // The model's <limit effort> and <limit velocity> (-1 where it gives none, as Gazebo's).
  double GetEffortLimit(unsigned int index);
  double GetVelocityLimit(unsigned int index);
  // "fmax" and "vel": a motor driving the joint to the velocity with at most the force, every step
  // until told otherwise (ODE's); "hi_stop" and "lo_stop" read the limits. Another key, or a limit
  // or "friction" set, is one gzwarn and false.
  bool SetParam(const std::string& key, unsigned int index, const boost::any& value);
  double GetParam(const std::string& key, unsigned int index);
  // What the joint passed between its links over the last step (JointWrench.hh); watched from the
  // first call, so that call answers zeros.
  JointWrench GetForceTorque(unsigned int index);
  void SetLowerLimit(unsigned int index, double limit);
  void SetUpperLimit(unsigned int index, double limit);

  // A joint made at run time: Load names its links (and its anchor, which a held joint does not
  // need), Init or Attach holds the child to the parent where they are now, Detach lets go.
  void Load(LinkPtr parent, LinkPtr child, const ignition::math::Pose3d& pose);
  void Init();
  void Attach(LinkPtr parent, LinkPtr child);
  void Detach();
  void SetModel(ModelPtr model);
  ModelPtr GetModel() const;
  LinkPtr GetParent() const;
  LinkPtr GetChild() const;

private:
  bool axisZero(unsigned int index, const char* call) const;
  // A model's joint answers through its bridge; a joint made at run time has none.
  bool modelJoint(const char* call) const;
  std::string name_, type_, model_name_;
  std::unique_ptr<JointBridge> bridge_;
  std::shared_ptr<WorldBridge> world_;
  ModelPtr model_;
  LinkPtr parent_, child_;
  int attachment_ = -1;
  double lower_ = -std::numeric_limits<double>::infinity();
  double upper_ = std::numeric_limits<double>::infinity();
  bool warned_type_ = false;
  double motor_velocity_ = 0.0, motor_max_force_ = 0.0;
};
}  // namespace physics
}  // namespace gazebo
