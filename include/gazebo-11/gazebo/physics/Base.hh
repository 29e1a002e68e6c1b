// physics::Base: the type tags every physics object carries (Gazebo's EntityType bits), which
// plugins test before they cast: `shape->HasType(physics::Base::CYLINDER_SHAPE)`.
#pragma once

#include <string>

#include "gazebo/physics/PhysicsTypes.hh"
#include "gazebo/util/system.hh"

namespace gazebo
{
namespace physics
{
class GZ_PHYSICS_VISIBLE Base
{
public:
  // Gazebo 11's values: a type is a set of these bits (a cylinder is SHAPE | CYLINDER_SHAPE).
  enum EntityType
  {
    BASE = 0x00000000,
    ENTITY = 0x00000001,
    MODEL = 0x00000002,
    LINK = 0x00000004,
    COLLISION = 0x00000008,
    LIGHT = 0x00000010,
    VISUAL = 0x00000020,
    JOINT = 0x00000040,
    BALL_JOINT = 0x00000080,
    HINGE2_JOINT = 0x00000100,
    HINGE_JOINT = 0x00000200,
    SLIDER_JOINT = 0x00000400,
    SCREW_JOINT = 0x00000800,
    UNIVERSAL_JOINT = 0x00001000,
    GEARBOX_JOINT = 0x00002000,
    FIXED_JOINT = 0x00004000,
    ACTOR = 0x00008000,
    SHAPE = 0x00010000,
    BOX_SHAPE = 0x00020000,
    CYLINDER_SHAPE = 0x00040000,
    HEIGHTMAP_SHAPE = 0x00080000,
    MAP_SHAPE = 0x00100000,
    MULTIRAY_SHAPE = 0x00200000,
    RAY_SHAPE = 0x00400000,
    PLANE_SHAPE = 0x00800000,
    SPHERE_SHAPE = 0x01000000,
    MESH_SHAPE = 0x02000000,
    POLYLINE_SHAPE = 0x04000000,
    SENSOR_COLLISION = 0x10000000
  };

  virtual ~Base();
  void AddType(EntityType type) { type_ |= static_cast<unsigned int>(type); }
  bool HasType(const EntityType& type) const
  {
    return (type_ & static_cast<unsigned int>(type)) == static_cast<unsigned int>(type);
  }
  unsigned int GetType() const { return type_; }
  unsigned int Type() const { return type_; }
  // The name of its most specific type, as Gazebo's ("model", "link", "collision", "cylinder" ...).
  std::string TypeStr() const;

private:
  unsigned int type_ = BASE;
};
}  // namespace physics
}  // namespace gazebo
