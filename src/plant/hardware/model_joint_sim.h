// The plant side of a joint a model plugin drives (model_plugin.h's ModelJoint): Gazebo's velocity
// motor (SetParam "vel" and "fmax") as a rigid velocity row of at most the force, held until
// changed; SetForce as an explicit torque of the coming step; SetPosition as the joint's state set.
#pragma once

#include "bullet_plant/model_plugin.h"
#include "physics/movable_joint.h"

class btMultiBody;

namespace bullet_plant
{
class ModelJointSim : public ModelJoint
{
public:
  ModelJointSim(MovableJoint& joint, btMultiBody& body) : joint_(joint), body_(body) {}

  void setVelocity(double velocity) override;
  void setMaxForce(double force) override;
  void setForce(double effort) override;
  double appliedForce() const override { return force_; }
  void setPosition(double position, double velocity) override;
  double position() const override;
  double velocity() const override;
  double effortLimit() const override { return joint_.limits.effort; }
  // Before each step: the motor's row and the force for the coming one.
  void apply(double dt);

private:
  MovableJoint& joint_;
  btMultiBody& body_;
  double velocity_ = 0.0, max_force_ = 0.0;
  double force_ = 0.0;     // SetForce's sum: for the coming step where pending_, else the last step's
  bool pending_ = false;  // SetForce was called since the last step
};

}  // namespace bullet_plant
