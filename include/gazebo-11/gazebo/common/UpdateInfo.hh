// common::UpdateInfo: what event::Events::worldUpdateBegin hands its subscribers each step.
#pragma once

#include <string>

#include "gazebo/common/Time.hh"
#include "gazebo/util/system.hh"

namespace gazebo
{
namespace common
{
class GZ_COMMON_VISIBLE UpdateInfo
{
public:
  std::string worldName;
  common::Time simTime;
  common::Time realTime;
};
}  // namespace common
}  // namespace gazebo
