// physics::Shape and the shapes plugins read a collision's size from (Collision::GetShape, then
// HasType and a cast): BoxShape, CylinderShape, SphereShape, MeshShape, as the model gives them.
// Their sizes are what the model was built with; the plant does not rescale a shape at run time.
#pragma once

#include <string>

#include <boost/weak_ptr.hpp>
#include <ignition/math/Vector3.hh>

#include "gazebo/physics/Base.hh"

namespace gazebo
{
namespace physics
{
class GZ_PHYSICS_VISIBLE Shape : public Base
{
public:
  explicit Shape(CollisionPtr parent);
  ~Shape() override;
  // Its size scale; 1 (the model's sizes are the shape's).
  virtual ignition::math::Vector3d Scale() const { return {1, 1, 1}; }
  CollisionPtr GetCollision() const;

private:
  boost::weak_ptr<Collision> collision_;
};

class GZ_PHYSICS_VISIBLE BoxShape : public Shape
{
public:
  BoxShape(CollisionPtr parent, const ignition::math::Vector3d& size);
  ignition::math::Vector3d Size() const { return size_; }

private:
  ignition::math::Vector3d size_;
};

class GZ_PHYSICS_VISIBLE CylinderShape : public Shape
{
public:
  CylinderShape(CollisionPtr parent, double radius, double length);
  double GetRadius() const { return radius_; }
  double GetLength() const { return length_; }

private:
  double radius_, length_;
};

class GZ_PHYSICS_VISIBLE SphereShape : public Shape
{
public:
  SphereShape(CollisionPtr parent, double radius);
  double GetRadius() const { return radius_; }

private:
  double radius_;
};

class GZ_PHYSICS_VISIBLE MeshShape : public Shape
{
public:
  MeshShape(CollisionPtr parent, const std::string& uri, const ignition::math::Vector3d& scale);
  std::string GetMeshURI() const { return uri_; }
  ignition::math::Vector3d Size() const { return scale_; }
  ignition::math::Vector3d Scale() const override { return scale_; }

private:
  std::string uri_;
  ignition::math::Vector3d scale_;
};
}  // namespace physics
}  // namespace gazebo
