// physics::HingeJoint<T>: the template Gazebo's engines make their hinge joints from. The plant's
// joints are physics::Joint objects answering HasType(Base::HINGE_JOINT); plugins that include this
// header (gazebo_ros_laser does) need only its name.
#pragma once

#include "gazebo/physics/Joint.hh"

namespace gazebo
{
namespace physics
{
template <class T>
class HingeJoint : public T
{
public:
  using T::T;
};
}  // namespace physics
}  // namespace gazebo
