// physics::Link (gazebo/physics/Link.hh), over its model's ModelBridge.
#include "gazebo/physics/Link.hh"

#include "gazebo/common/Console.hh"
#include "gazebo/physics/Collision.hh"
#include "gazebo/physics/Inertial.hh"
#include "gazebo/physics/Joint.hh"
#include "gazebo/physics/Model.hh"
#include "gazebo/physics/PlantBridge.hh"

namespace gazebo
{
namespace physics
{
Link::Link(const std::string& name, std::shared_ptr<ModelBridge> bridge) : name_(name), bridge_(std::move(bridge))
{
  AddType(LINK);
}

Collision_V Link::GetCollisions() const
{
  if (!collisions_made_)
  {
    collisions_made_ = true;
    const LinkPtr self = boost::const_pointer_cast<Link>(shared_from_this());
    for (const CollisionSpec& spec : bridge_->linkCollisions(name_))
      collisions_.push_back(CollisionPtr(new Collision(self, bridge_, spec)));
  }
  return collisions_;
}

CollisionPtr Link::GetCollision(const std::string& name) const
{
  for (const CollisionPtr& collision : GetCollisions())
    if (collision->GetName() == name)
      return collision;
  return nullptr;
}

CollisionPtr Link::GetCollision(unsigned int index) const
{
  const Collision_V collisions = GetCollisions();
  return index < collisions.size() ? collisions[index] : nullptr;
}

std::string Link::GetName() const { return name_; }

std::string Link::GetScopedName(bool prependWorldName) const
{
  const ModelPtr model = model_.lock();
  return (model ? model->GetScopedName(prependWorldName) : bridge_->name()) + "::" + name_;
}

ModelPtr Link::GetModel() const { return model_.lock(); }

Entity::~Entity() = default;

void Link::SetLinearVel(const ignition::math::Vector3d& velocity)
{
  if (bridge_->canonicalLink() == name_)
    bridge_->setVelocity(velocity, WorldAngularVel());
  else
    gzerr << "Link::SetLinearVel on link [" << GetScopedName() << "]: the plant sets a model's velocity at its "
          << "canonical link [" << bridge_->canonicalLink() << "] only; nothing is changed" << std::endl;
}

void Link::SetAngularVel(const ignition::math::Vector3d& velocity)
{
  if (bridge_->canonicalLink() == name_)
    bridge_->setVelocity(WorldLinearVel(), velocity);
  else
    gzerr << "Link::SetAngularVel on link [" << GetScopedName() << "]: the plant sets a model's velocity at its "
          << "canonical link [" << bridge_->canonicalLink() << "] only; nothing is changed" << std::endl;
}

void Link::SetEnabled(bool enable) const
{
  if (!enable)
    gzwarn << "Link::SetEnabled(false) on link [" << GetScopedName() << "]: the plant keeps every link of a model "
           << "in its simulation; nothing is changed" << std::endl;
}

void Link::SetGravityMode(bool mode) { bridge_->setLinkGravity(name_, mode); }

void Link::SetWorldPose(const ignition::math::Pose3d& pose, bool /*notify*/, bool /*publish*/)
{
  bridge_->setLinkWorldPose(name_, pose);
}

bool Link::GetGravityMode() const { return bridge_->linkGravity(name_); }

ignition::math::Pose3d Link::WorldPose() const { return bridge_->linkPose(name_); }

ignition::math::Vector3d Link::WorldLinearVel() const { return bridge_->linkLinearVel(name_); }

ignition::math::Vector3d Link::WorldLinearVel(const ignition::math::Vector3d& _offset) const
{
  return WorldLinearVel(_offset, WorldPose().Rot());
}

ignition::math::Vector3d Link::WorldLinearVel(const ignition::math::Vector3d& _offset,
                                              const ignition::math::Quaterniond& _q) const
{
  return WorldLinearVel() + WorldAngularVel().Cross(_q.RotateVector(_offset));
}

ignition::math::Vector3d Link::WorldAngularVel() const { return bridge_->linkAngularVel(name_); }

ignition::math::Pose3d Link::RelativePose() const
{
  const ModelPtr model = GetModel();
  return model ? WorldPose() - model->WorldPose() : WorldPose();
}

ignition::math::Vector3d Link::RelativeLinearVel() const { return WorldPose().Rot().RotateVectorReverse(WorldLinearVel()); }

ignition::math::Vector3d Link::RelativeAngularVel() const
{
  return WorldPose().Rot().RotateVectorReverse(WorldAngularVel());
}

void Link::AddForce(const ignition::math::Vector3d& force) { bridge_->addLinkWrench(name_, force, ignition::math::Vector3d::Zero); }

void Link::AddTorque(const ignition::math::Vector3d& torque) { bridge_->addLinkWrench(name_, ignition::math::Vector3d::Zero, torque); }

void Link::AddRelativeForce(const ignition::math::Vector3d& force) { AddForce(WorldPose().Rot().RotateVector(force)); }

void Link::AddRelativeTorque(const ignition::math::Vector3d& torque) { AddTorque(WorldPose().Rot().RotateVector(torque)); }

void Link::AddForceAtWorldPosition(const ignition::math::Vector3d& force, const ignition::math::Vector3d& position)
{
  // At the body's centre of mass, with its moment about it.
  bridge_->addLinkWrench(name_, force, (position - bridge_->bodyCentreOfMass(name_)).Cross(force));
}

void Link::AddForceAtRelativePosition(const ignition::math::Vector3d& force, const ignition::math::Vector3d& position)
{
  AddForceAtWorldPosition(force, WorldPose().CoordPositionAdd(position));
}

void Link::SetForce(const ignition::math::Vector3d& force) { AddForce(force - WorldForce()); }

void Link::SetTorque(const ignition::math::Vector3d& torque) { AddTorque(torque - WorldTorque()); }

ignition::math::Vector3d Link::WorldForce() const
{
  ignition::math::Vector3d force, torque;
  bridge_->addedLinkWrench(name_, force, torque);
  return force;
}

ignition::math::Vector3d Link::WorldTorque() const
{
  ignition::math::Vector3d force, torque;
  bridge_->addedLinkWrench(name_, force, torque);
  return torque;
}

ignition::math::Pose3d Link::WorldCoGPose() const
{
  return ignition::math::Pose3d(bridge_->bodyCentreOfMass(name_), WorldPose().Rot());
}

InertialPtr Link::GetInertial() const
{
  const LinkInertia inertia = bridge_->linkInertia(name_);
  InertialPtr inertial(new Inertial(inertia.mass));
  inertial->SetPose(inertia.pose);
  inertial->SetInertiaMatrix(inertia.ixx, inertia.iyy, inertia.izz, inertia.ixy, inertia.ixz, inertia.iyz);
  return inertial;
}

namespace
{
Joint_V jointsOf(const ModelPtr& model, const std::vector<std::string>& names)
{
  Joint_V joints;
  if (model)
    for (const std::string& name : names)
      if (JointPtr joint = model->GetJoint(name))
        joints.push_back(joint);
  return joints;
}
}  // namespace

Joint_V Link::GetParentJoints() const { return jointsOf(GetModel(), bridge_->linkJoints(name_, true)); }

Joint_V Link::GetChildJoints() const { return jointsOf(GetModel(), bridge_->linkJoints(name_, false)); }
}  // namespace physics
}  // namespace gazebo
