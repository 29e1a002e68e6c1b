// physics::Joint: a model's movable joint as a plugin drives it (its position and velocity, and an
// effort, a velocity or a position set; axis 0, a joint of the plant having one axis), and a joint
// made at run time (PhysicsEngine::CreateJoint): fixed, prismatic, revolute or ball, between two
// links or a link and the world, until detached; a slide or turn with its position, rate and effort.
#pragma once

#include <limits>
#include <memory>
#include <string>

#include <boost/any.hpp>
#include <ignition/math/Pose3.hh>
#include <ignition/math/Vector3.hh>
#include <sdf/Element.hh>

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
  // Its wrench watched from now on (true), as a ForceTorqueSensor asks; false is a no-op (a watch
  // costs only while the step runs).
  void SetProvideFeedback(bool enable);
  // The joint's frame in its child link's frame, where its model (or Load) put it.
  ignition::math::Pose3d InitialAnchorPose() const;
  void SetLowerLimit(unsigned int index, double limit);
  void SetUpperLimit(unsigned int index, double limit);

  // A joint made at run time: Load names its links and its anchor (`pose` in the child link's
  // frame), or reads them from a <joint> element as SDF has it (name, type, parent, child, pose,
  // axis xyz, limit lower / upper / effort, dynamics damping; "world" for no parent link); Init or
  // Attach holds the child to the parent (null: the world) from where they are now, Detach lets go.
  void Load(LinkPtr parent, LinkPtr child, const ignition::math::Pose3d& pose);
  void Load(sdf::ElementPtr sdf);
  void Init();
  void Attach(LinkPtr parent, LinkPtr child);
  void Detach();
  // Axis 0: set in the joint's frame (a joint made at run time, before it is attached); as its model
  // or its Load gives it (LocalAxis), and in the world now (GlobalAxis).
  void SetAxis(unsigned int index, const ignition::math::Vector3d& axis);
  ignition::math::Vector3d LocalAxis(unsigned int index) const;
  ignition::math::Vector3d GlobalAxis(unsigned int index) const;
  void SetModel(ModelPtr model);
  ModelPtr GetModel() const;
  LinkPtr GetParent() const;
  LinkPtr GetChild() const;

private:
  bool axisZero(unsigned int index, const char* call) const;
  // A model's joint, and a joint made at run time while attached, answer through the bridge.
  bool bridged(const char* call) const;
  // A link of the joint's model by name, or of another model as MODEL::LINK; null with an error.
  LinkPtr linkNamed(const std::string& name) const;
  std::string name_, type_, model_name_;
  std::unique_ptr<JointBridge> bridge_;
  std::shared_ptr<WorldBridge> world_;  // a joint made at run time's world
  ModelPtr model_;
  LinkPtr parent_, child_;
  // A joint made at run time: its anchor in the child link's frame, its axis in the joint's frame
  // (the model's where SDF says use_parent_model_frame), its damping and effort limit.
  ignition::math::Pose3d pose_;
  ignition::math::Vector3d axis_{0, 0, 1};
  bool axis_in_model_frame_ = false;
  double damping_ = 0.0;
  double effort_limit_ = std::numeric_limits<double>::infinity();
  double lower_ = -std::numeric_limits<double>::infinity();
  double upper_ = std::numeric_limits<double>::infinity();
  double motor_velocity_ = 0.0, motor_max_force_ = 0.0;
  mutable bool said_unattached_ = false;
};
}  // namespace physics
}  // namespace gazebo
