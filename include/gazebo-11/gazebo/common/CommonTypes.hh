// The common library's handle types, as Gazebo 11 declares them (std::shared_ptr handles), for
// the classes this API has.
#pragma once

#include <memory>

namespace gazebo
{
namespace common
{
class Animation;
class PoseAnimation;
class NumericAnimation;

typedef std::shared_ptr<Animation> AnimationPtr;
typedef std::shared_ptr<PoseAnimation> PoseAnimationPtr;
typedef std::shared_ptr<NumericAnimation> NumericAnimationPtr;
}  // namespace common
}  // namespace gazebo
