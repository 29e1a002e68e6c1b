// common::Animation, PoseAnimation and NumericAnimation (gazebo/common/Animation.hh), with Gazebo
// 11's arithmetic: the same key frames found about a time, the same interpolation between them.
#include "gazebo/common/Animation.hh"

#include <algorithm>
#include <cmath>
#include <iterator>

#include <ignition/math/Helpers.hh>

#include "gazebo/common/Console.hh"

namespace gazebo
{
namespace common
{
namespace
{
bool earlier(const KeyFrame* a, const KeyFrame* b) { return a->GetTime() < b->GetTime(); }
}  // namespace

Animation::Animation(const std::string& _name, const double _length, const bool _loop)
  : name(_name), length(_length), timePos(0.0), build(false), loop(_loop)
{
}

Animation::~Animation()
{
  for (KeyFrame* frame : keyFrames)
    delete frame;
}

double Animation::GetLength() const { return length; }

void Animation::SetLength(const double _len) { length = _len; }

void Animation::SetTime(const double _time)
{
  if (ignition::math::equal(_time, timePos))
    return;
  timePos = _time;
  if (loop && length > 0.0)
  {
    timePos = std::fmod(timePos, length);
    if (timePos < 0)
      timePos += length;
  }
  else if (timePos < 0 || !std::isfinite(timePos))  // a NaN step holds it where it starts
    timePos = 0;
  else if (timePos > length)
    timePos = std::max(length, 0.0);
}

void Animation::AddTime(const double _time) { SetTime(timePos + _time); }

double Animation::GetTime() const { return timePos; }

unsigned int Animation::GetKeyFrameCount() const { return static_cast<unsigned int>(keyFrames.size()); }

KeyFrame* Animation::GetKeyFrame(const unsigned int _index) const
{
  if (_index < keyFrames.size())
    return keyFrames[_index];
  gzerr << "Key frame index[" << _index << "] is larger than key frame array size[" << keyFrames.size() << "]\n";
  return nullptr;
}

void Animation::InsertKeyFrame(KeyFrame* _frame)
{
  keyFrames.insert(std::upper_bound(keyFrames.begin(), keyFrames.end(), _frame, earlier), _frame);
  build = true;
}

double Animation::GetKeyFramesAtTime(double _time, KeyFrame** _kf1, KeyFrame** _kf2,
                                     unsigned int& _firstKeyIndex) const
{
  // into (0, length], as Gazebo's repeated subtraction leaves it
  if (_time > length && length > 0.0)
  {
    _time = std::fmod(_time, length);
    if (_time <= 0.0)
      _time = length;
  }
  const KeyFrame at(_time);
  KeyFrame_V::const_iterator first = std::lower_bound(keyFrames.begin(), keyFrames.end(), &at, earlier);
  double t2;
  if (first == keyFrames.end())
  {
    // past the last key frame: towards the first again, a length later
    *_kf2 = keyFrames.front();
    t2 = length + (*_kf2)->GetTime();
    --first;
  }
  else
  {
    *_kf2 = *first;
    t2 = (*_kf2)->GetTime();
    if (first != keyFrames.begin() && _time < (*first)->GetTime())
      --first;
  }
  _firstKeyIndex = static_cast<unsigned int>(std::distance(keyFrames.begin(), first));
  *_kf1 = *first;
  const double t1 = (*_kf1)->GetTime();
  return ignition::math::equal(t1, t2) ? 0.0 : (_time - t1) / (t2 - t1);
}

PoseAnimation::PoseAnimation(const std::string& _name, const double _length, const bool _loop)
  : Animation(_name, _length, _loop)
{
}

PoseAnimation::~PoseAnimation() = default;

PoseKeyFrame* PoseAnimation::CreateKeyFrame(const double _time) { return Animation::CreateKeyFrame<PoseKeyFrame>(_time); }

void PoseAnimation::BuildInterpolationSplines() const
{
  if (!positionSpline)
    positionSpline.reset(new ignition::math::Spline());
  if (!rotationSpline)
    rotationSpline.reset(new ignition::math::RotationSpline());
  positionSpline->AutoCalculate(false);
  rotationSpline->AutoCalculate(false);
  positionSpline->Clear();
  rotationSpline->Clear();
  for (const KeyFrame* frame : keyFrames)
  {
    const PoseKeyFrame* pose = static_cast<const PoseKeyFrame*>(frame);
    positionSpline->AddPoint(pose->Translation());
    rotationSpline->AddPoint(pose->Rotation());
  }
  positionSpline->RecalcTangents();
  rotationSpline->RecalcTangents();
  build = false;
}

void PoseAnimation::GetInterpolatedKeyFrame(PoseKeyFrame& _kf) const { GetInterpolatedKeyFrame(timePos, _kf); }

void PoseAnimation::GetInterpolatedKeyFrame(const double _time, PoseKeyFrame& _kf) const
{
  if (keyFrames.empty())
    return;
  if (build)
    BuildInterpolationSplines();
  KeyFrame *base1, *base2;
  unsigned int first;
  const double t = GetKeyFramesAtTime(_time, &base1, &base2, first);
  const PoseKeyFrame* k1 = static_cast<const PoseKeyFrame*>(base1);
  if (ignition::math::equal(t, 0.0))
  {
    _kf.Translation(k1->Translation());
    _kf.Rotation(k1->Rotation());
  }
  else
  {
    _kf.Translation(positionSpline->Interpolate(first, t));
    _kf.Rotation(rotationSpline->Interpolate(first, t));
  }
}

NumericAnimation::NumericAnimation(const std::string& _name, const double _length, const bool _loop)
  : Animation(_name, _length, _loop)
{
}

NumericAnimation::~NumericAnimation() = default;

NumericKeyFrame* NumericAnimation::CreateKeyFrame(const double _time)
{
  return Animation::CreateKeyFrame<NumericKeyFrame>(_time);
}

void NumericAnimation::GetInterpolatedKeyFrame(NumericKeyFrame& _kf) const
{
  if (keyFrames.empty())
    return;
  KeyFrame *base1, *base2;
  unsigned int first;
  const double t = GetKeyFramesAtTime(timePos, &base1, &base2, first);
  const double v1 = static_cast<const NumericKeyFrame*>(base1)->GetValue();
  if (ignition::math::equal(t, 0.0))
    _kf.SetValue(v1);
  else
    _kf.SetValue(v1 + (static_cast<const NumericKeyFrame*>(base2)->GetValue() - v1) * t);
}
}  // namespace common
}  // namespace gazebo
