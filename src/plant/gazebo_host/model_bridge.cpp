#include "gazebo_host/model_bridge.h"

#include <cmath>
#include <limits>

#include <boost/make_shared.hpp>
#include <gazebo/common/Console.hh>
#include <gazebo/physics/Base.hh>

#include "bullet_plant/log.h"

namespace bullet_plant
{
namespace
{
urdf::Vector3 toUrdf(const ignition::math::Vector3d& v) { return urdf::Vector3(v.X(), v.Y(), v.Z()); }

bool finite(const ignition::math::Vector3d& v) { return std::isfinite(v.X()) && std::isfinite(v.Y()) && std::isfinite(v.Z()); }

class ContextJoint final : public gazebo::physics::JointBridge
{
public:
  ContextJoint(std::shared_ptr<ModelReach> reach, std::string name) : reach_(std::move(reach)), name_(std::move(name)) {}

  double position() const override
  {
    double position = 0.0, velocity = 0.0;
    if (reach_->context)
      reach_->context->jointState(name_, position, velocity);
    return position;
  }
  double velocity() const override
  {
    double position = 0.0, velocity = 0.0;
    if (reach_->context)
      reach_->context->jointState(name_, position, velocity);
    return velocity;
  }
  bool setVelocity(double velocity) override
  {
    ModelJoint* joint = driven();
    if (joint)
      joint->setPosition(joint->position(), velocity);  // Gazebo's SetVelocity: the rate now, no motor
    return joint != nullptr;
  }
  bool setForce(double effort) override
  {
    ModelJoint* joint = driven();
    if (joint)
      joint->setForce(effort);
    return joint != nullptr;
  }
  double appliedForce() const override
  {
    // a joint no SetForce (or motor) has reached yet had none: asking is not driving it
    return reach_->context && joint_ ? joint_->appliedForce() : 0.0;
  }
  bool setPosition(double position) override
  {
    // Gazebo's SetPosition puts any joint there, one a gazebo_ros_control transmission drives too
    // (its controller goes on from there): such a joint is set as the world sets joints
    // (gazebo_ros_joint_pose_trajectory's), the others through their motor, cheaply, every step.
    if (reach_->context && !asked_ && reach_->context->transmissionDrives(name_))
      return reach_->context->setJointPosition(name_, position);
    ModelJoint* joint = driven();
    if (joint)
      joint->setPosition(position, 0.0);
    return joint != nullptr;
  }
  double lowerLimit() const override { return limit(false); }
  double upperLimit() const override { return limit(true); }
  double effortLimit() const override
  {
    const auto joint = urdfJoint();
    return joint && joint->limits && joint->limits->effort > 0 ? joint->limits->effort
                                                               : std::numeric_limits<double>::infinity();
  }
  double velocityLimit() const override
  {
    const auto joint = urdfJoint();
    return joint && joint->limits && joint->limits->velocity > 0 ? joint->limits->velocity
                                                                 : std::numeric_limits<double>::infinity();
  }
  std::string parentLink() const override
  {
    const auto joint = urdfJoint();
    return joint ? joint->parent_link_name : "";
  }
  ignition::math::Vector3d localAxis() const override
  {
    const auto joint = urdfJoint();
    return joint ? ignition::math::Vector3d(joint->axis.x, joint->axis.y, joint->axis.z) : ignition::math::Vector3d::Zero;
  }
  ignition::math::Vector3d globalAxis() const override
  {
    // URDF's joint frame is the child link's frame: the axis turns with the child.
    const auto joint = urdfJoint();
    if (!joint || !reach_->context)
      return ignition::math::Vector3d::Zero;
    const urdf::Rotation child = reach_->context->linkMotion(joint->child_link_name).pose.rotation;
    const urdf::Vector3 axis = child * joint->axis;
    return ignition::math::Vector3d(axis.x, axis.y, axis.z);
  }
  std::string childLink() const override
  {
    const auto frame = jointFrameToChild();
    if (frame)
      return frame->child_link_name;
    const auto joint = urdfJoint();
    return joint ? joint->child_link_name : "";
  }
  ignition::math::Pose3d anchorPose() const override
  {
    // the frame link's joint holds the child at its pose in the joint frame
    const auto frame = jointFrameToChild();
    return frame ? toIgnition(frame->parent_to_joint_origin_transform).Inverse() : ignition::math::Pose3d::Zero;
  }
  bool setMotorVelocity(double velocity) override
  {
    ModelJoint* joint = driven();
    if (joint)
      joint->setVelocity(velocity);
    return joint != nullptr;
  }
  bool setMotorMaxForce(double force) override
  {
    ModelJoint* joint = driven();
    if (joint)
      joint->setMaxForce(force);
    return joint != nullptr;
  }
  void childWrench(ignition::math::Vector3d& force, ignition::math::Vector3d& torque) override
  {
    force = torque = ignition::math::Vector3d::Zero;
    if (!reach_->context)
      return;
    if (!watched_)
      watched_ = reach_->context->watchJointWrench(name_);
    urdf::Vector3 f, t;
    reach_->context->jointWrench(name_, f, t);
    force = toIgnition(f);
    torque = toIgnition(t);
  }

private:
  // The joint taken for driving at the first call that drives it (the context says once why it
  // cannot be: a transmission drives it); null once the model left the world.
  ModelJoint* driven()
  {
    if (!reach_->context)
      return nullptr;
    if (!asked_)
    {
      joint_ = reach_->context->modelJoint(name_, reach_->label);
      asked_ = true;
    }
    return joint_;
  }
  urdf::JointConstSharedPtr urdfJoint() const
  {
    return reach_->context ? reach_->context->robotDescription().model->getJoint(name_) : nullptr;
  }
  // An SDF joint whose frame is not its child link's hangs a frame link between them (sdf_model.cpp),
  // fixed to the child: that fixed joint; null where the joint's child is its link itself (URDF's
  // rule).
  urdf::JointConstSharedPtr jointFrameToChild() const
  {
    const auto joint = urdfJoint();
    if (!joint)
      return nullptr;
    const RobotDescription& robot = reach_->context->robotDescription();
    if (!robot.frame_links.count(joint->child_link_name))
      return nullptr;
    const auto frame = robot.model->getLink(joint->child_link_name);
    return frame && frame->child_joints.size() == 1 ? frame->child_joints.front() : nullptr;
  }
  double limit(bool upper) const
  {
    const double none = upper ? std::numeric_limits<double>::infinity() : -std::numeric_limits<double>::infinity();
    const auto joint = urdfJoint();
    if (!joint || !joint->limits || joint->type == urdf::Joint::CONTINUOUS)
      return none;
    return upper ? joint->limits->upper : joint->limits->lower;
  }

  std::shared_ptr<ModelReach> reach_;
  std::string name_;
  ModelJoint* joint_ = nullptr;
  bool asked_ = false;
  bool watched_ = false;
};
}  // namespace

ContextModel::ContextModel(ModelPluginContext& context)
  : reach_(std::make_shared<ModelReach>(ModelReach{&context, "model '" + context.modelName() + "'"})),
    name_(context.modelName())
{
}

ModelPluginContext* ContextModel::reach(const char* call) const
{
  if (!reach_->context && !said_gone_)
  {
    said_gone_ = true;  // on Gazebo's console: the model's own log left with it
    gzerr << "Model [" << name_ << "]: " << call << " after the model was deleted; it does nothing" << std::endl;
  }
  return reach_->context;
}

std::string ContextModel::canonicalLink() const
{
  ModelPluginContext* context = reach("GetLink");
  return context ? context->rootLink() : "";
}

std::vector<std::string> ContextModel::linkNames() const
{
  std::vector<std::string> names;
  if (ModelPluginContext* context = reach("GetLinks"))
    for (const auto& link : context->robotDescription().model->links_)
      if (!context->robotDescription().frame_links.count(link.first))
        names.push_back(link.first);
  return names;
}

std::vector<std::string> ContextModel::jointNames() const
{
  std::vector<std::string> names;
  double position, velocity;
  if (ModelPluginContext* context = reach("GetJoints"))
    for (const auto& joint : context->robotDescription().model->joints_)
      if (context->jointState(joint.first, position, velocity))
        names.push_back(joint.first);
  return names;
}

ignition::math::Pose3d ContextModel::linkPose(const std::string& link) const
{
  ModelPluginContext* context = reach("WorldPose");
  if (!context)
    return ignition::math::Pose3d::Zero;
  return toIgnition(context->linkMotion(link).pose);
}

ignition::math::Vector3d ContextModel::linkLinearVel(const std::string& link) const
{
  ModelPluginContext* context = reach("WorldLinearVel");
  return context ? toIgnition(context->linkMotion(link).velocity) : ignition::math::Vector3d::Zero;
}

ignition::math::Vector3d ContextModel::linkAngularVel(const std::string& link) const
{
  ModelPluginContext* context = reach("WorldAngularVel");
  return context ? toIgnition(context->linkMotion(link).angular_velocity) : ignition::math::Vector3d::Zero;
}

void ContextModel::setVelocity(const ignition::math::Vector3d& linear, const ignition::math::Vector3d& angular)
{
  ModelPluginContext* context = reach("SetLinearVel");
  if (!context)
    return;
  if (finite(linear) && finite(angular))
    context->setModelVelocity(toUrdf(linear), toUrdf(angular));
  else
    context->log().warn(reach_->label + ": a non-finite model velocity is ignored");
}

void ContextModel::addLinkWrench(const std::string& link, const ignition::math::Vector3d& force,
                                 const ignition::math::Vector3d& torque)
{
  ModelPluginContext* context = reach("AddForce");
  if (!context)
    return;
  if (finite(force) && finite(torque))
    context->addLinkWrench(link, toUrdf(force), toUrdf(torque));
  else
    context->log().warn(reach_->label + ": a non-finite force or torque on link '" + link + "' is ignored");
}

void ContextModel::addedLinkWrench(const std::string& link, ignition::math::Vector3d& force,
                                   ignition::math::Vector3d& torque) const
{
  urdf::Vector3 f, t;
  if (ModelPluginContext* context = reach("WorldForce"))
    context->addedLinkWrench(link, f, t);
  force = toIgnition(f);
  torque = toIgnition(t);
}

ignition::math::Vector3d ContextModel::bodyCentreOfMass(const std::string& link) const
{
  ModelPluginContext* context = reach("WorldCoGPose");
  return context ? toIgnition(context->bodyCentreOfMass(link)) : ignition::math::Vector3d::Zero;
}

gazebo::physics::LinkInertia ContextModel::linkInertia(const std::string& link) const
{
  gazebo::physics::LinkInertia inertia;
  ModelPluginContext* context = reach("GetInertial");
  if (!context)
    return inertia;
  // A URDF robot's link as Gazebo has it: the links fixed to it lumped into it (its body).
  double mass = 0.0;
  urdf::Pose com;
  urdf::Vector3 moments;
  if (context->lumpedInertia(link, mass, com, moments))
  {
    inertia.mass = mass;
    inertia.pose = {com.position.x, com.position.y, com.position.z, com.rotation.w, com.rotation.x, com.rotation.y,
                    com.rotation.z};
    inertia.ixx = moments.x;
    inertia.iyy = moments.y;
    inertia.izz = moments.z;
    return inertia;
  }
  const urdf::LinkConstSharedPtr l = context->robotDescription().model->getLink(link);
  if (!l || !l->inertial)
    return inertia;
  const urdf::Inertial& i = *l->inertial;
  inertia.mass = i.mass;
  inertia.pose = {i.origin.position.x, i.origin.position.y, i.origin.position.z, i.origin.rotation.w,
                  i.origin.rotation.x, i.origin.rotation.y, i.origin.rotation.z};
  inertia.ixx = i.ixx;
  inertia.iyy = i.iyy;
  inertia.izz = i.izz;
  inertia.ixy = i.ixy;
  inertia.ixz = i.ixz;
  inertia.iyz = i.iyz;
  return inertia;
}

void ContextModel::setLinkGravity(const std::string& link, bool gravity)
{
  if (ModelPluginContext* context = reach("SetGravityMode"))
    context->setLinkGravity(link, gravity);
}

bool ContextModel::isStatic() const
{
  ModelPluginContext* context = reach("IsStatic");
  return context && context->robotDescription().is_static;
}

bool ContextModel::linkGravity(const std::string& link) const
{
  ModelPluginContext* context = reach("GetGravityMode");
  if (!context)
    return true;
  const auto& physics = context->robotDescription().link_physics;
  auto found = physics.find(link);
  return found == physics.end() || found->second.gravity;
}

std::vector<std::string> ContextModel::linkJoints(const std::string& link, bool parent_side) const
{
  std::vector<std::string> names;
  double position, velocity;
  if (ModelPluginContext* context = reach(parent_side ? "GetParentJoints" : "GetChildJoints"))
    for (const auto& joint : context->robotDescription().model->joints_)
      if ((parent_side ? joint.second->child_link_name : joint.second->parent_link_name) == link &&
          context->jointState(joint.first, position, velocity))
        names.push_back(joint.first);
  return names;
}

void ContextModel::setLinkWorldPose(const std::string& link, const ignition::math::Pose3d& pose)
{
  ModelPluginContext* context = reach("SetWorldPose");
  if (!context)
    return;
  const ignition::math::Quaterniond& q = pose.Rot();
  if (!finite(pose.Pos()) || !std::isfinite(q.W() + q.X() + q.Y() + q.Z()))
  {
    context->log().warn(reach_->label + ": a non-finite pose is ignored");
    return;
  }
  urdf::Pose p;
  p.position = toUrdf(pose.Pos());
  p.rotation = urdf::Rotation(q.X(), q.Y(), q.Z(), q.W());
  context->setLinkWorldPose(link, p);
}

std::unique_ptr<gazebo::physics::JointBridge> ContextModel::joint(const std::string& name)
{
  double position, velocity;
  ModelPluginContext* context = reach("GetJoint");
  if (!context || !context->jointState(name, position, velocity))
    return nullptr;
  return std::make_unique<ContextJoint>(reach_, name);
}
}  // namespace bullet_plant

namespace bullet_plant
{
namespace
{
CollisionFriction frictionOf(const gazebo::physics::ODESurfaceParams& surface)
{
  CollisionFriction friction;
  friction.mu1 = surface.FrictionPyramid()->MuPrimary();
  friction.mu2 = surface.FrictionPyramid()->MuSecondary();
  friction.slip1 = surface.slip1;
  friction.slip2 = surface.slip2;
  return friction;
}
}  // namespace

std::vector<gazebo::physics::CollisionSpec> ContextModel::linkCollisions(const std::string& link) const
{
  using gazebo::physics::Base;
  std::vector<gazebo::physics::CollisionSpec> out;
  ModelPluginContext* context = reach("GetCollisions");
  if (!context)
    return out;
  for (const LinkCollision& collision : context->linkCollisions(link))
  {
    gazebo::physics::CollisionSpec spec;
    spec.name = collision.name;
    const urdf::Pose& o = collision.origin;
    spec.pose = {o.position.x, o.position.y, o.position.z, o.rotation.w, o.rotation.x, o.rotation.y, o.rotation.z};
    spec.shape_type = Base::SHAPE;
    const urdf::Geometry& geometry = *collision.geometry;
    switch (geometry.type)
    {
      case urdf::Geometry::BOX:
        spec.shape_type = Base::BOX_SHAPE;
        spec.size = toIgnition(static_cast<const urdf::Box&>(geometry).dim);
        break;
      case urdf::Geometry::CYLINDER:
        spec.shape_type = Base::CYLINDER_SHAPE;
        spec.radius = static_cast<const urdf::Cylinder&>(geometry).radius;
        spec.length = static_cast<const urdf::Cylinder&>(geometry).length;
        break;
      case urdf::Geometry::SPHERE:
        spec.shape_type = Base::SPHERE_SHAPE;
        spec.radius = static_cast<const urdf::Sphere&>(geometry).radius;
        break;
      case urdf::Geometry::MESH:
      {
        const auto& mesh = static_cast<const urdf::Mesh&>(geometry);
        if (!mesh.filename.empty())  // else SDF's capsule or ellipsoid (ShapeGeometry): no class here
        {
          spec.shape_type = Base::MESH_SHAPE;
          spec.mesh_uri = mesh.filename;
          spec.size = toIgnition(mesh.scale);
        }
        break;
      }
    }
    out.push_back(std::move(spec));
  }
  return out;
}

gazebo::physics::SurfaceParamsPtr ContextModel::collisionSurface(const std::string& link, const std::string& collision)
{
  auto handed = surfaces_.find({link, collision});
  if (handed != surfaces_.end())
    return handed->second.surface;
  ModelPluginContext* context = reach("GetSurface");
  if (!context)
    return nullptr;
  for (const LinkCollision& c : context->linkCollisions(link))
  {
    if (c.name != collision)
      continue;
    // The model's <surface>, where SDF's defaults fill what it does not give.
    const SurfaceDescription& d = c.surface;
    auto surface = boost::make_shared<gazebo::physics::ODESurfaceParams>();
    surface->FrictionPyramid()->SetMuPrimary(d.mu1);
    surface->FrictionPyramid()->SetMuSecondary(d.mu2);
    surface->FrictionPyramid()->direction1 = toIgnition(d.fdir1);
    surface->slip1 = d.slip1;
    surface->slip2 = d.slip2;
    if (d.kp > 0)
      surface->kp = d.kp;
    if (d.kd >= 0)
      surface->kd = d.kd;
    if (d.max_vel >= 0)
      surface->maxVel = d.max_vel;
    if (d.min_depth >= 0)
      surface->minDepth = d.min_depth;
    surface->bounce = d.restitution;
    surface->bounceThreshold = d.restitution_threshold;
    HandedSurface& entry = surfaces_[{link, collision}];
    entry.surface = surface;
    entry.pushed = frictionOf(*surface);
    return surface;
  }
  return nullptr;
}

void ContextModel::pushSurfaces()
{
  if (surfaces_.empty() || !reach_->context)
    return;
  for (auto& [key, handed] : surfaces_)
  {
    const CollisionFriction now = frictionOf(*handed.surface);
    if (now.mu1 == handed.pushed.mu1 && now.mu2 == handed.pushed.mu2 && now.slip1 == handed.pushed.slip1 &&
        now.slip2 == handed.pushed.slip2)
      continue;
    if (reach_->context->setCollisionFriction(key.first, key.second, now))
      handed.pushed = now;
    else if (!said_bad_surface_)
    {
      said_bad_surface_ = true;
      gzerr << "collision [" << name_ << "::" << key.first << "::" << key.second << "]: a friction coefficient or "
            << "slip that is negative or not a number (mu " << now.mu1 << ", mu2 " << now.mu2 << ", slip1 "
            << now.slip1 << ", slip2 " << now.slip2 << ") is not taken; the surface keeps what it had" << std::endl;
    }
  }
}
}  // namespace bullet_plant
