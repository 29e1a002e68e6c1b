// physics::Collision: one <collision> of a link, as its model gives it: its name, its pose, its
// shape (GetShape, sizes as built) and its surface (GetSurface: an ODESurfaceParams whose friction
// coefficients and slips a plugin may change while the world runs; the same object for the
// model's life).
#pragma once

#include <memory>
#include <string>

#include <boost/enable_shared_from_this.hpp>
#include <boost/weak_ptr.hpp>
#include <ignition/math/Pose3.hh>

#include "gazebo/physics/Entity.hh"
#include "gazebo/physics/PhysicsTypes.hh"
#include "gazebo/util/system.hh"

namespace gazebo
{
namespace physics
{
class ModelBridge;
struct CollisionSpec;

class GZ_PHYSICS_VISIBLE Collision : public Entity, public boost::enable_shared_from_this<Collision>
{
public:
  Collision(LinkPtr link, std::shared_ptr<ModelBridge> bridge, const CollisionSpec& spec);
  ~Collision() override;
  std::string GetName() const override;
  // MODEL::LINK::COLLISION.
  std::string GetScopedName(bool prependWorldName = false) const override;
  LinkPtr GetLink() const;
  LinkPtr GetParentLink() const { return GetLink(); }
  ModelPtr GetModel() const;
  // Its pose in the world now, and in its link (as the model gives it).
  ignition::math::Pose3d WorldPose() const override;
  ignition::math::Pose3d RelativePose() const override;
  ignition::math::Pose3d InitialRelativePose() const { return RelativePose(); }
  // Its link's.
  ignition::math::Vector3d WorldLinearVel() const override;
  ignition::math::Vector3d WorldAngularVel() const override;
  SurfaceParamsPtr GetSurface() const;
  ShapePtr GetShape() const;
  // The shape's type (Base::BOX_SHAPE ...), SHAPE for one the API has no class for.
  unsigned int GetShapeType() const;
  unsigned int GetMaxContacts() const { return 20; }  // SDF's default

private:
  boost::weak_ptr<Link> link_;
  std::shared_ptr<ModelBridge> bridge_;
  std::string name_, link_name_;
  ignition::math::Pose3d pose_;
  unsigned int shape_type_;
  mutable ShapePtr shape_;
  // What the shape is made from at the first GetShape (it needs the collision's own handle).
  ignition::math::Vector3d size_;
  double radius_ = 0.0, length_ = 0.0;
  std::string mesh_uri_;
};
}  // namespace physics
}  // namespace gazebo
