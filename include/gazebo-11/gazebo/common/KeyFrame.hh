// common::KeyFrame: a value of an animation at a time (Animation.hh): a pose (PoseKeyFrame) or a
// number (NumericKeyFrame), as Gazebo 11's.
#pragma once

#include <ignition/math/Quaternion.hh>
#include <ignition/math/Vector3.hh>

#include "gazebo/util/system.hh"

namespace gazebo
{
namespace common
{
class GZ_COMMON_VISIBLE KeyFrame
{
public:
  explicit KeyFrame(const double _time);
  virtual ~KeyFrame();
  double GetTime() const;

protected:
  double time;
};

class GZ_COMMON_VISIBLE PoseKeyFrame : public KeyFrame
{
public:
  explicit PoseKeyFrame(const double _time);
  ~PoseKeyFrame() override;
  void Translation(const ignition::math::Vector3d& _trans);
  const ignition::math::Vector3d& Translation() const;
  void Rotation(const ignition::math::Quaterniond& _rot);
  const ignition::math::Quaterniond& Rotation() const;

protected:
  ignition::math::Vector3d translate;
  ignition::math::Quaterniond rotate;
};

class GZ_COMMON_VISIBLE NumericKeyFrame : public KeyFrame
{
public:
  explicit NumericKeyFrame(const double _time);
  ~NumericKeyFrame() override;
  void SetValue(const double& _value);
  const double& GetValue() const;

protected:
  double value;
};
}  // namespace common
}  // namespace gazebo
