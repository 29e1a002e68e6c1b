#include "hardware/joint_motor_sim.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <BulletDynamics/Featherstone/btMultiBody.h>

namespace bullet_plant
{
void JointMotorSim::setVelocity(double velocity)
{
  if (std::isfinite(velocity))
    velocity_ = std::max(-kMaxJointSpeed, std::min(velocity, kMaxJointSpeed));
}

void JointMotorSim::setMaxForce(double force)
{
  if (std::isfinite(force))
    max_force_ = std::abs(force);
}

double JointMotorSim::position() const { return body_.getJointPos(joint_.link); }
double JointMotorSim::velocity() const { return body_.getJointVel(joint_.link); }

void JointMotorSim::apply(double dt)
{
  joint_.drive->drive(velocity_, std::numeric_limits<double>::infinity(), max_force_ * dt);
}

}  // namespace bullet_plant
