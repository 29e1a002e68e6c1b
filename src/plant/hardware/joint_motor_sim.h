// The plant side of Gazebo's joint velocity motor (Joint::SetParam "vel" and "fmax"), which model
// plugins drive (model_plugin.h): a rigid velocity row of at most the force, held until changed.
#pragma once

#include "bullet_plant/model_plugin.h"
#include "physics/movable_joint.h"

class btMultiBody;

namespace bullet_plant
{
class JointMotorSim : public JointMotor
{
public:
  JointMotorSim(MovableJoint& joint, const btMultiBody& body) : joint_(joint), body_(body) {}

  void setVelocity(double velocity) override;
  void setMaxForce(double force) override;
  double position() const override;
  double velocity() const override;
  // Before each step: the row for the coming one.
  void apply(double dt);

private:
  MovableJoint& joint_;
  const btMultiBody& body_;
  double velocity_ = 0.0, max_force_ = 0.0;
};

}  // namespace bullet_plant
