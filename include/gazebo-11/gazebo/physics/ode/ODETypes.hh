// The ODE engine's handle types, as Gazebo 11 declares them.
#pragma once

#include <boost/shared_ptr.hpp>

namespace gazebo
{
namespace physics
{
class ODESurfaceParams;
typedef boost::shared_ptr<ODESurfaceParams> ODESurfaceParamsPtr;
}  // namespace physics
}  // namespace gazebo
