// The common library's handle types, as Gazebo 11 declares them (std::shared_ptr handles), for
// the classes this API has, and the events' connection.
#pragma once

#include <memory>

#include <boost/shared_ptr.hpp>

namespace gazebo
{
namespace common
{
class Animation;
class PoseAnimation;
class NumericAnimation;
class SphericalCoordinates;

typedef std::shared_ptr<Animation> AnimationPtr;
typedef std::shared_ptr<PoseAnimation> PoseAnimationPtr;
typedef std::shared_ptr<NumericAnimation> NumericAnimationPtr;
// (boost's, as Gazebo 11 declares it)
typedef boost::shared_ptr<SphericalCoordinates> SphericalCoordinatesPtr;
}  // namespace common

namespace event
{
class Connection;
// What Connect* returns; the subscription lasts while one is held (common/Event.hh).
typedef std::shared_ptr<Connection> ConnectionPtr;
}  // namespace event
}  // namespace gazebo
