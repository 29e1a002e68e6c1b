// common::Animation as Gazebo 11's: key frames over a length of time, a time position that moves on
// with AddTime (wrapping where it loops, held at the ends where it does not), and the value between
// the key frames about it. NumericAnimation interpolates a number linearly (Model::SetJointAnimation
// moves joints by them); PoseAnimation a pose along splines through its key frames (Model::
// SetAnimation moves a model by one).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <ignition/math/RotationSpline.hh>
#include <ignition/math/Spline.hh>

#include "gazebo/common/CommonTypes.hh"
#include "gazebo/common/KeyFrame.hh"
#include "gazebo/util/system.hh"

namespace gazebo
{
namespace common
{
class GZ_COMMON_VISIBLE Animation
{
public:
  Animation(const std::string& _name, const double _length, const bool _loop);
  virtual ~Animation();
  Animation(const Animation&) = delete;  // it owns its key frames
  Animation& operator=(const Animation&) = delete;
  double GetLength() const;
  void SetLength(const double _len);
  // Looping: the time wrapped into [0, length); otherwise held within [0, length].
  void SetTime(const double _time);
  void AddTime(const double _time);
  double GetTime() const;
  unsigned int GetKeyFrameCount() const;
  // Null, with an error naming the index, past the last.
  KeyFrame* GetKeyFrame(const unsigned int _index) const;

protected:
  // A key frame of that type at the time, kept in time order (after any at the same time).
  template <typename KeyFrameType>
  KeyFrameType* CreateKeyFrame(const double _time)
  {
    KeyFrameType* frame = new KeyFrameType(_time);
    this->InsertKeyFrame(frame);
    return frame;
  }
  // The key frames about `_time` (wrapped into the length): the one at or before it, the one after it
  // (the first again past the last) and the first's index; returns how far `_time` is from the first
  // to the second, 0 to 1. The animation has key frames.
  double GetKeyFramesAtTime(double _time, KeyFrame** _kf1, KeyFrame** _kf2, unsigned int& _firstKeyIndex) const;

  std::string name;
  double length;
  double timePos;
  mutable bool build;  // key frames came since the interpolation was built
  bool loop;
  typedef std::vector<KeyFrame*> KeyFrame_V;
  KeyFrame_V keyFrames;

private:
  void InsertKeyFrame(KeyFrame* _frame);
};

class GZ_COMMON_VISIBLE PoseAnimation : public Animation
{
public:
  PoseAnimation(const std::string& _name, const double _length, const bool _loop);
  ~PoseAnimation() override;
  PoseKeyFrame* CreateKeyFrame(const double _time);
  // The pose at the animation's time: the key frame's where it is on one, else along the splines
  // (Catmull-Rom through the translations, squad through the rotations). Unchanged for an animation
  // without key frames.
  void GetInterpolatedKeyFrame(PoseKeyFrame& _kf) const;

protected:
  void GetInterpolatedKeyFrame(const double _time, PoseKeyFrame& _kf) const;
  void BuildInterpolationSplines() const;

private:
  mutable std::unique_ptr<ignition::math::Spline> positionSpline;
  mutable std::unique_ptr<ignition::math::RotationSpline> rotationSpline;
};

class GZ_COMMON_VISIBLE NumericAnimation : public Animation
{
public:
  NumericAnimation(const std::string& _name, const double _length, const bool _loop);
  ~NumericAnimation() override;
  NumericKeyFrame* CreateKeyFrame(const double _time);
  // The value at the animation's time, linearly between the key frames about it. Unchanged for an
  // animation without key frames.
  void GetInterpolatedKeyFrame(NumericKeyFrame& _kf) const;
};
}  // namespace common
}  // namespace gazebo
