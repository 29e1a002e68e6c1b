// physics::Collision (gazebo/physics/Collision.hh), over its model's ModelBridge.
#include "gazebo/physics/Collision.hh"

#include "gazebo/physics/Link.hh"
#include "gazebo/physics/Model.hh"
#include "gazebo/physics/PlantBridge.hh"
#include "gazebo/physics/Shape.hh"

namespace gazebo
{
namespace physics
{
Collision::Collision(LinkPtr link, std::shared_ptr<ModelBridge> bridge, const CollisionSpec& spec)
  : link_(link),
    bridge_(std::move(bridge)),
    name_(spec.name),
    link_name_(link ? link->GetName() : std::string()),
    pose_(spec.pose),
    shape_type_(spec.shape_type),
    size_(spec.size),
    radius_(spec.radius),
    length_(spec.length),
    mesh_uri_(spec.mesh_uri)
{
  AddType(COLLISION);
}

Collision::~Collision() = default;

std::string Collision::GetName() const { return name_; }

std::string Collision::GetScopedName(bool prependWorldName) const
{
  const LinkPtr link = link_.lock();
  return (link ? link->GetScopedName(prependWorldName) : bridge_->name() + "::" + link_name_) + "::" + name_;
}

LinkPtr Collision::GetLink() const { return link_.lock(); }

ModelPtr Collision::GetModel() const
{
  const LinkPtr link = link_.lock();
  return link ? link->GetModel() : nullptr;
}

ignition::math::Pose3d Collision::WorldPose() const { return pose_ + bridge_->linkPose(link_name_); }

ignition::math::Pose3d Collision::RelativePose() const { return pose_; }

ignition::math::Vector3d Collision::WorldLinearVel() const { return bridge_->linkLinearVel(link_name_); }

ignition::math::Vector3d Collision::WorldAngularVel() const { return bridge_->linkAngularVel(link_name_); }

SurfaceParamsPtr Collision::GetSurface() const { return bridge_->collisionSurface(link_name_, name_); }

unsigned int Collision::GetShapeType() const { return shape_type_; }

ShapePtr Collision::GetShape() const
{
  if (shape_)
    return shape_;
  const CollisionPtr self = boost::const_pointer_cast<Collision>(shared_from_this());
  if (shape_type_ == BOX_SHAPE)
    shape_.reset(new BoxShape(self, size_));
  else if (shape_type_ == CYLINDER_SHAPE)
    shape_.reset(new CylinderShape(self, radius_, length_));
  else if (shape_type_ == SPHERE_SHAPE)
    shape_.reset(new SphereShape(self, radius_));
  else if (shape_type_ == MESH_SHAPE)
    shape_.reset(new MeshShape(self, mesh_uri_, size_));
  else
    shape_.reset(new Shape(self));
  return shape_;
}
}  // namespace physics
}  // namespace gazebo
