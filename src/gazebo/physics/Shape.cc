// physics::Base, Shape and its kinds (gazebo/physics/Base.hh, Shape.hh), and the surface classes
// (SurfaceParams.hh, ode/ODESurfaceParams.hh).
#include "gazebo/physics/Shape.hh"

#include <memory>

#include "gazebo/physics/Collision.hh"
#include "gazebo/physics/SurfaceParams.hh"
#include "gazebo/physics/ode/ODESurfaceParams.hh"

namespace gazebo
{
namespace physics
{
Base::~Base() = default;

std::string Base::TypeStr() const
{
  // The most specific first, as Gazebo's EntityTypename order reads them.
  static const std::pair<EntityType, const char*> names[] = {
      {BOX_SHAPE, "box"},         {CYLINDER_SHAPE, "cylinder"}, {SPHERE_SHAPE, "sphere"},
      {MESH_SHAPE, "trimesh"},    {PLANE_SHAPE, "plane"},       {SHAPE, "shape"},
      {COLLISION, "collision"},   {LINK, "link"},               {MODEL, "model"},
      {JOINT, "joint"},           {ENTITY, "entity"}};
  for (const auto& name : names)
    if (HasType(name.first) && name.first != BASE)
      return name.second;
  return "base";
}

Shape::Shape(CollisionPtr parent) : collision_(parent) { AddType(SHAPE); }

Shape::~Shape() = default;

CollisionPtr Shape::GetCollision() const { return collision_.lock(); }

BoxShape::BoxShape(CollisionPtr parent, const ignition::math::Vector3d& size) : Shape(std::move(parent)), size_(size)
{
  AddType(BOX_SHAPE);
}

CylinderShape::CylinderShape(CollisionPtr parent, double radius, double length)
  : Shape(std::move(parent)), radius_(radius), length_(length)
{
  AddType(CYLINDER_SHAPE);
}

SphereShape::SphereShape(CollisionPtr parent, double radius) : Shape(std::move(parent)), radius_(radius)
{
  AddType(SPHERE_SHAPE);
}

MeshShape::MeshShape(CollisionPtr parent, const std::string& uri, const ignition::math::Vector3d& scale)
  : Shape(std::move(parent)), uri_(uri), scale_(scale)
{
  AddType(MESH_SHAPE);
}

void FrictionPyramid::SetMuPrimary(double mu)
{
  if (mu >= 0)
    mu_primary_ = mu;
}

void FrictionPyramid::SetMuSecondary(double mu)
{
  if (mu >= 0)
    mu_secondary_ = mu;
}

void FrictionPyramid::SetMuTorsion(double mu)
{
  if (mu >= 0)
    mu_torsion_ = mu;
}

SurfaceParams::SurfaceParams() : friction_pyramid_(std::make_shared<physics::FrictionPyramid>()) {}

SurfaceParams::~SurfaceParams() = default;

FrictionPyramidPtr SurfaceParams::FrictionPyramid() const { return friction_pyramid_; }

ODESurfaceParams::ODESurfaceParams() = default;

ODESurfaceParams::~ODESurfaceParams() = default;
}  // namespace physics
}  // namespace gazebo
