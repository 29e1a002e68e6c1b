#include "hardware/model_joint_sim.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <BulletDynamics/Featherstone/btMultiBody.h>

namespace bullet_plant
{
void ModelJointSim::setVelocity(double velocity)
{
  if (std::isfinite(velocity))
    velocity_ = std::max(-kMaxJointSpeed, std::min(velocity, kMaxJointSpeed));
}

void ModelJointSim::setMaxForce(double force)
{
  if (!std::isnan(force))
    max_force_ = std::abs(force);  // infinite: a rigid motor (a joint without an effort limit)
}

void ModelJointSim::setForce(double effort)
{
  if (!std::isfinite(effort))
    return;
  if (!pending_)
    force_ = 0.0;  // the first call since the last step: a new step's sum
  pending_ = true;
  force_ += effort;
}

void ModelJointSim::setPosition(double position, double velocity)
{
  if (!std::isfinite(position) || !std::isfinite(velocity))
    return;
  body_.setJointPos(joint_.link, btScalar(position));
  body_.setJointVel(joint_.link, btScalar(std::max(-kMaxJointSpeed, std::min(velocity, kMaxJointSpeed))));
}

double ModelJointSim::position() const { return body_.getJointPos(joint_.link); }
double ModelJointSim::velocity() const { return body_.getJointVel(joint_.link); }

void ModelJointSim::apply(double dt)
{
  // A motor with no force is no motor (Gazebo's fmax 0): no row for the solver to carry.
  if (max_force_ > 0.0)
    joint_.drive->drive(velocity_, std::numeric_limits<double>::infinity(), max_force_ * dt);
  else if (joint_.drive->enabled())
    joint_.drive->disable();
  if (pending_ && force_ != 0.0)
    body_.addJointTorque(joint_.link, btScalar(force_));
  pending_ = false;
}

}  // namespace bullet_plant
