// common::KeyFrame, PoseKeyFrame and NumericKeyFrame (gazebo/common/KeyFrame.hh).
#include "gazebo/common/KeyFrame.hh"

namespace gazebo
{
namespace common
{
KeyFrame::KeyFrame(const double _time) : time(_time) {}

KeyFrame::~KeyFrame() = default;

double KeyFrame::GetTime() const { return time; }

PoseKeyFrame::PoseKeyFrame(const double _time) : KeyFrame(_time) {}

PoseKeyFrame::~PoseKeyFrame() = default;

void PoseKeyFrame::Translation(const ignition::math::Vector3d& _trans) { translate = _trans; }

const ignition::math::Vector3d& PoseKeyFrame::Translation() const { return translate; }

void PoseKeyFrame::Rotation(const ignition::math::Quaterniond& _rot) { rotate = _rot; }

const ignition::math::Quaterniond& PoseKeyFrame::Rotation() const { return rotate; }

NumericKeyFrame::NumericKeyFrame(const double _time) : KeyFrame(_time), value(0.0) {}

NumericKeyFrame::~NumericKeyFrame() = default;

void NumericKeyFrame::SetValue(const double& _value) { value = _value; }

const double& NumericKeyFrame::GetValue() const { return value; }
}  // namespace common
}  // namespace gazebo
