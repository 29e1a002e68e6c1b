// physics::Contact: the touching points between two collisions, as ContactSensor::Contacts(name)
// gives them and gazebo_ros_bumper includes it: positions and normals in the world, depths, each
// point's wrench (body 1's in its link frame), the time, the collisions and the world.
#pragma once

#include <string>

#include <ignition/math/Vector3.hh>

#include "gazebo/common/Time.hh"
#include "gazebo/msgs/MessageTypes.hh"
#include "gazebo/physics/JointWrench.hh"
#include "gazebo/physics/PhysicsTypes.hh"
#include "gazebo/util/system.hh"

namespace gazebo
{
namespace physics
{
// Gazebo's limit on the points of one contact.
constexpr int MAX_CONTACT_JOINTS = 32;

class GZ_PHYSICS_VISIBLE Contact
{
public:
  Contact() = default;
  Contact(const Contact& contact) = default;
  virtual ~Contact() = default;
  Contact& operator=(const Contact& contact) = default;
  // From a message: its world found by name, its collisions in it (null where not found), its
  // points (at most MAX_CONTACT_JOINTS).
  Contact& operator=(const msgs::Contact& contact);
  void FillMsg(msgs::Contact& msg) const;
  std::string DebugString() const;
  void Reset();

  Collision* collision1 = nullptr;
  Collision* collision2 = nullptr;
  JointWrench wrench[MAX_CONTACT_JOINTS];
  ignition::math::Vector3d positions[MAX_CONTACT_JOINTS];
  ignition::math::Vector3d normals[MAX_CONTACT_JOINTS];
  double depths[MAX_CONTACT_JOINTS] = {};
  int count = 0;
  common::Time time;
  WorldPtr world;
};
}  // namespace physics
}  // namespace gazebo
