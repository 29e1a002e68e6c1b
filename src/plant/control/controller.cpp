// The Controller base: the samples a controller produces for its topics, queued for the node and
// kept for Python to read.
#include "bullet_plant/controllers.h"

namespace bullet_plant
{
std::vector<JointStateSample> Controller::takeJointStates()
{
  std::vector<JointStateSample> out;
  out.swap(joint_states_);
  return out;
}

std::vector<ControllerStateSample> Controller::takeControllerStates()
{
  std::vector<ControllerStateSample> out;
  out.swap(controller_states_);
  return out;
}

std::vector<OdometrySample> Controller::takeOdometry()
{
  std::vector<OdometrySample> out;
  out.swap(odometry_);
  return out;
}

void Controller::emit(const OdometrySample& s)
{
  latest_odometry_ = s;
  has_odometry_ = true;
  ++samples_;
  if (odometry_.size() < 1000)
    odometry_.push_back(s);
}

void Controller::emit(const JointStateSample& s)
{
  latest_joint_state_ = s;
  has_joint_state_ = true;
  ++samples_;
  if (joint_states_.size() < 1000)  // nobody draining (Python): keep the latest only
    joint_states_.push_back(s);
}

void Controller::emit(const ControllerStateSample& s)
{
  latest_state_ = s;
  has_state_ = true;
  ++samples_;
  if (controller_states_.size() < 1000)
    controller_states_.push_back(s);
}

}  // namespace bullet_plant
