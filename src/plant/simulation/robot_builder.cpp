#include "simulation/robot_builder.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <sstream>

#include "bullet_plant/gazebo_host.h"
#include "bullet_plant/geometry.h"
#include "bullet_plant/params.h"
#include "physics/bullet_conversions.h"
#include "simulation/collision_shapes.h"

namespace bullet_plant
{
uint32_t seedFor(const std::string& text)
{
  uint32_t h = 2166136261u;  // FNV-1a: a seed that is the same on every run and machine
  for (unsigned char c : text)
    h = (h ^ c) * 16777619u;
  return h;
}

ContactSurface contactSurface(const SurfaceDescription& surface, const btMatrix3x3& frame, const std::string& where,
                              Log& log, bool& plain)
{
  ContactSurface out;
  auto coefficient = [&](double mu, const char* tag) {
    if (mu >= 0)  // not negative nor NaN: Bullet would push along the motion
      return btScalar(mu);
    log.warn(where + ": <" + tag + "> " + formatNumber(mu) + " is not a friction coefficient; it is taken as 0");
    return btScalar(0);
  };
  out.mu1 = coefficient(surface.mu1, "mu");
  out.mu2 = coefficient(surface.mu2, "mu2");
  const btVector3 fdir1 = toBullet(surface.fdir1);
  if (!fdir1.isZero())
  {
    if (std::isfinite(fdir1.length2()))
      out.fdir1 = frame * fdir1.normalized();
    else
      log.warn(where + ": <fdir1> is not a direction; left out");
  }
  // <contact><ode>: negative where not given; a given value that means nothing is left out.
  auto contact = [&](double value, const char* tag, bool positive) {
    if (value == -1.0)  // the reader's "not given"
      return btScalar(-1);
    if (positive ? value > 0 && std::isfinite(value) : value >= 0 && std::isfinite(value))
      return btScalar(value);
    log.warn(where + ": <" + tag + "> " + formatNumber(value) + (positive ? " is not above 0" : " is negative") +
             "; left out");
    return btScalar(-1);
  };
  out.kp = contact(surface.kp, "kp", true);
  out.kd = contact(surface.kd, "kd", false);
  out.max_vel = contact(surface.max_vel, "max_vel", false);
  out.min_depth = contact(surface.min_depth, "min_depth", false);
  auto slip = [&](double value, const char* tag) {
    if (value >= 0 && std::isfinite(value))
      return btScalar(value);
    log.warn(where + ": <" + tag + "> " + formatNumber(value) + " is not a slip (m/s per N, 0 or more); it is taken as 0");
    return btScalar(0);
  };
  out.slip1 = slip(surface.slip1, "slip1");
  out.slip2 = slip(surface.slip2, "slip2");
  plain = out.mu1 == out.mu2 && out.fdir1.isZero() && out.kp < 0 && out.kd < 0 && out.max_vel < 0 &&
          out.min_depth < 0 && out.slip1 == 0 && out.slip2 == 0;
  return out;
}

namespace
{
constexpr double kInf = std::numeric_limits<double>::infinity();
// Bodies lighter than this get it (with a warning): the articulated-body algorithm needs mass.
constexpr double kMinimumMass = 1e-3;
constexpr double kMinimumInertia = 1e-9;
// The effort limit of a joint whose URDF gives none, when no joint of the robot gives one either
// (N m or N). Otherwise such a joint is as strong as the robot's strongest limited joint: an
// unlimited effort on a light joint (a passive wheel) lets one command launch the robot.
constexpr double kDefaultEffortLimit = 100.0;
// Beyond these a sensor's buffers alone would take gigabytes: a Velodyne HDL-64 casts about 130 k
// rays a scan, an 8K image has 33 M pixels.
constexpr int kMaxRaysPerScan = 1 << 22;
constexpr int kMaxPixelsPerImage = 1 << 25;


// Inertia tensor of a link's <inertial> about its centre of mass, in the link frame.
btMatrix3x3 inertiaInLink(const urdf::Inertial& in)
{
  btMatrix3x3 I(btScalar(in.ixx), btScalar(in.ixy), btScalar(in.ixz),
                btScalar(in.ixy), btScalar(in.iyy), btScalar(in.iyz),
                btScalar(in.ixz), btScalar(in.iyz), btScalar(in.izz));
  btMatrix3x3 R = toBullet(in.origin).getBasis();
  return R * I * R.transpose();
}

// The movable joint into each body (null for the base) and its frame in the parent body's URDF frame.
struct BodyPlan
{
  const urdf::Joint* joint = nullptr;
  btTransform joint_in_parent = btTransform::getIdentity();
};

// Each link's body and its frame in that body's URDF frame.
using LinkPlacement = std::map<std::string, std::pair<int, btTransform>>;

JointInterface parseInterface(const std::string& name, bool& ok)
{
  ok = true;
  if (name == "hardware_interface/EffortJointInterface")
    return JointInterface::Effort;
  if (name == "hardware_interface/VelocityJointInterface")
    return JointInterface::Velocity;
  if (name == "hardware_interface/PositionJointInterface")
    return JointInterface::Position;
  ok = false;
  return JointInterface::Effort;
}

// URDF damping as a plain torque -c*qd is stable while c*dt stays well below the inertia it acts on.
bool explicitDampingStable(const MovableJoint& j, double dt) { return j.damping * dt < 0.5 * j.axis_inertia; }

// A spring as a plain effort -k*(q - reference), integrated with the velocity before the position
// (symplectic Euler), keeps its energy and runs at omega (1 + (omega dt)^2 / 24), omega^2 = k / I,
// but is unstable from omega dt = 2. Held to k dt^2 < 0.1 I (omega dt < 0.32: 0.4 % fast), which
// leaves a margin for the inertia the joint really moves (the child body's own is a lower bound
// only while the rest of the robot is heavier). A stiffer spring is an implicit row, -k at the end
// of the step: stable for any k, at the price of damping of its own and a lower frequency
// (atan(omega dt) / dt), as ODE's implicit spring-damper (Gazebo's joint stops with erp and cfm).
bool explicitSpringAccurate(const MovableJoint& j, double dt)
{
  return j.spring_stiffness * dt * dt < 0.1 * j.axis_inertia;
}

// An SDF ball joint (RobotDescription::ball_joints): a spherical Bullet link.
bool isBall(const Robot::Internals& r, const urdf::Joint& joint)
{
  return joint.type == urdf::Joint::FLOATING && r.description.ball_joints.count(joint.name);
}

// 1. Bodies: each movable joint starts one; fixed joints fold their child into the parent body.
std::vector<BodyPlan> planBodies(Robot::Internals& r, const urdf::LinkConstSharedPtr& root, LinkPlacement& placement)
{
  const urdf::ModelInterface& model = *r.description.model;
  std::vector<Body>& bodies = r.multibody.bodies;
  std::vector<BodyPlan> plans(1);
  bodies.resize(1);
  bodies[0].link = root->name;
  std::function<void(const urdf::Link&, int, const btTransform&)> visit =
      [&](const urdf::Link& link, int body, const btTransform& in_body) {
        placement[link.name] = {body, in_body};
        for (const urdf::JointSharedPtr& joint : link.child_joints)
        {
          urdf::LinkConstSharedPtr child = model.getLink(joint->child_link_name);
          btTransform joint_frame = in_body * toBullet(joint->parent_to_joint_origin_transform);
          bool movable = joint->type == urdf::Joint::REVOLUTE || joint->type == urdf::Joint::CONTINUOUS ||
                         joint->type == urdf::Joint::PRISMATIC || isBall(r, *joint);
          if (!movable && joint->type != urdf::Joint::FIXED)
            r.world->log.warn("joint '" + joint->name + "' of '" + r.name + "' is floating or planar, which the plant "
                              "does not simulate; it is held fixed");
          if (!movable)
          {
            visit(*child, body, joint_frame);
            continue;
          }
          Body b;
          b.link = child->name;
          b.parent = body;
          bodies.push_back(std::move(b));
          BodyPlan plan;
          plan.joint = joint.get();
          plan.joint_in_parent = joint_frame;
          plans.push_back(plan);
          visit(*child, int(bodies.size()) - 1, btTransform::getIdentity());
        }
      };
  visit(*root, 0, btTransform::getIdentity());
  // A body begun by an SDF frame (the model frame, a joint frame) goes by the first link fixed to
  // it: Gazebo's names (contacts, link states) are the links'.
  for (Body& body : bodies)
    if (r.description.frame_links.count(body.link))
      if (urdf::LinkConstSharedPtr frame = model.getLink(body.link))
        for (const urdf::JointSharedPtr& joint : frame->child_joints)
          if (joint->type == urdf::Joint::FIXED && !r.description.frame_links.count(joint->child_link_name))
          {
            body.link = joint->child_link_name;
            break;
          }
  return plans;
}

// Joints between bodies whose masses differ by more than this hold loosely: the iterative solver
// (Bullet's, as ODE's) converges slowly on them, and the robot drifts or jumps.
constexpr double kLooseMassRatio = 1e4;

// Says once which joint joins the most unequal masses, when beyond kLooseMassRatio.
void warnOfMassRatio(Robot::Internals& r)
{
  const std::vector<Body>& bodies = r.multibody.bodies;
  double worst = kLooseMassRatio;
  size_t worst_body = 0;
  for (size_t bi = 1; bi < bodies.size(); ++bi)
  {
    const double a = bodies[bi].mass, b = bodies[size_t(bodies[bi].parent)].mass;
    if (a > 0 && b > 0 && std::max(a / b, b / a) > worst)
    {
      worst = std::max(a / b, b / a);
      worst_body = bi;
    }
  }
  if (worst_body == 0)
    return;
  const Body& child = bodies[worst_body];
  const Body& parent = bodies[size_t(child.parent)];
  std::ostringstream text;
  text << "robot '" << r.name << "': link '" << child.link << "' (" << child.mass << " kg) and its parent '"
       << parent.link << "' (" << parent.mass << " kg) differ " << worst << " times in mass; the solver holds "
       << "their joint loosely (the robot may drift or jump): keep masses within " << kLooseMassRatio << " times";
  r.world->log.warn(text.str());
}

// A body's links' inertials together: their mass, centre of mass and inertia about it, in the body's
// URDF frame.
struct BodyMass
{
  double mass = 0.0;
  btVector3 com{0, 0, 0};
  btMatrix3x3 inertia{0, 0, 0, 0, 0, 0, 0, 0, 0};
};

BodyMass sumBodyMass(const Robot::Internals& r, const LinkPlacement& placement, size_t bi)
{
  const urdf::ModelInterface& model = *r.description.model;
  BodyMass sum;
  btVector3 weighted(0, 0, 0);
  for (const auto& kv : placement)
  {
    urdf::LinkConstSharedPtr link = model.getLink(kv.first);
    if (kv.second.first != int(bi) || !link->inertial || link->inertial->mass <= 0)
      continue;
    sum.mass += link->inertial->mass;
    weighted += kv.second.second * toBullet(link->inertial->origin.position) * btScalar(link->inertial->mass);
  }
  // Below the minimum the body gets kMinimumMass at its frame: a mass of 1e-40 kg would divide
  // by a single-precision zero.
  sum.com = sum.mass >= kMinimumMass ? weighted / btScalar(sum.mass) : btVector3(0, 0, 0);
  for (const auto& kv : placement)
  {
    urdf::LinkConstSharedPtr link = model.getLink(kv.first);
    if (kv.second.first != int(bi) || !link->inertial || link->inertial->mass <= 0)
      continue;
    const btTransform& in_body = kv.second.second;
    btMatrix3x3 R = in_body.getBasis();
    btMatrix3x3 own = R * inertiaInLink(*link->inertial) * R.transpose();
    btVector3 d = in_body * toBullet(link->inertial->origin.position) - sum.com;
    btScalar m = btScalar(link->inertial->mass);
    btMatrix3x3 shift(d.dot(d) - d.x() * d.x(), -d.x() * d.y(), -d.x() * d.z(),
                      -d.y() * d.x(), d.dot(d) - d.y() * d.y(), -d.y() * d.z(),
                      -d.z() * d.x(), -d.z() * d.y(), d.dot(d) - d.z() * d.z());
    for (int i = 0; i < 3; ++i)
      sum.inertia[i] += own[i] + shift[i] * m;
  }
  return sum;
}

// 2. Mass properties of each body (its links' inertials together), then its principal frame.
void massProperties(Robot::Internals& r, const LinkPlacement& placement, bool world_rooted)
{
  for (size_t bi = 0; bi < r.multibody.bodies.size(); ++bi)
  {
    Body& body = r.multibody.bodies[bi];
    BodyMass sum = sumBodyMass(r, placement, bi);
    if (sum.mass < kMinimumMass && !(bi == 0 && world_rooted))
    {
      r.world->log.warn("link '" + body.link + "' of '" + r.name + "' (with the links fixed to it) has no mass; "
                        "the plant gives it " + std::to_string(kMinimumMass) + " kg");
      sum.mass = kMinimumMass;
    }
    btMatrix3x3 principal;
    btMatrix3x3 I = sum.inertia;
    I.diagonalize(principal, btScalar(1e-12), 32);
    body.mass = sum.mass;
    for (int i = 0; i < 3; ++i)
      body.inertia_diagonal[i] = std::max(I[i][i], btScalar(kMinimumInertia));
    body.urdf_from_com = btTransform(principal, sum.com);
  }
  warnOfMassRatio(r);
}

const LinkPhysics& physicsOf(const Robot::Internals& r, const std::string& link)
{
  static const LinkPhysics defaults;
  auto found = r.description.link_physics.find(link);
  return found == r.description.link_physics.end() ? defaults : found->second;
}

// 2b. Where links feel no gravity (SDF's <gravity>false): the mass gravity pulls on each body, the
// share of its links' that do, and where that mass lies, from the body's centre of mass. Gazebo's
// ODE turns gravity off per link (dBodySetGravityMode); a body of links fixed together feels its
// gravity links' weight, at their centre of mass.
void partialGravity(Robot::Internals& r, const LinkPlacement& placement)
{
  const urdf::ModelInterface& model = *r.description.model;
  bool any_off = false;
  for (const auto& kv : placement)
    any_off = any_off || !physicsOf(r, kv.first).gravity;
  if (!any_off)
  {
    r.multibody.partial_gravity.reset();
    return;
  }
  const std::vector<Body>& bodies = r.multibody.bodies;
  auto partial = std::make_unique<PartialGravity>();
  partial->mass.assign(bodies.size(), 0);
  partial->offset.assign(bodies.size(), btVector3(0, 0, 0));
  for (size_t bi = 0; bi < bodies.size(); ++bi)
  {
    double total = 0, pulled = 0;
    btVector3 weighted(0, 0, 0);
    for (const auto& kv : placement)
    {
      urdf::LinkConstSharedPtr link = model.getLink(kv.first);
      if (kv.second.first != int(bi) || !link->inertial || link->inertial->mass <= 0)
        continue;
      total += link->inertial->mass;
      if (!physicsOf(r, kv.first).gravity)
        continue;
      pulled += link->inertial->mass;
      weighted += kv.second.second * toBullet(link->inertial->origin.position) * btScalar(link->inertial->mass);
    }
    // A body lighter than the minimum (given kMinimumMass) feels gravity as its links do.
    bool all_pulled = true;
    for (const auto& kv : placement)
      if (kv.second.first == int(bi))
        all_pulled = all_pulled && physicsOf(r, kv.first).gravity;
    const double share = total > 0 ? pulled / total : (all_pulled ? 1.0 : 0.0);
    partial->mass[bi] = btScalar(bodies[bi].mass * share);
    if (pulled > 0)
      partial->offset[bi] = bodies[bi].urdf_from_com.inverse() * (weighted / btScalar(pulled));
  }
  r.multibody.partial_gravity = std::move(partial);
}

// A wheel-shaped mesh on the link of a continuous joint (whose frame is the joint's) becomes the
// cylinder it fills about the joint axis, said in the collider's note; `shape` and `in_link` follow.
bool fitWheelToJoint(const urdf::Joint* joint, Collider& collider, Shape& shape, btTransform& in_link)
{
  Shape wheel;
  btTransform wheel_in_link;
  if (!joint || joint->type != urdf::Joint::CONTINUOUS || toBullet(joint->axis).length2() == 0 ||
      !fitWheelCylinder(*collider.mesh, in_link, toBullet(joint->axis), wheel, wheel_in_link))
    return false;
  collider.shape.reset(makeCollisionShape(wheel));
  collider.note = "is wheel-shaped about continuous joint '" + joint->name + "': it collides as a cylinder of radius " +
                  std::to_string(wheel.radius) + " m and length " + std::to_string(wheel.length) +
                  " m about the joint axis, which rolls smoothly where its hull's facets would bump";
  wheel.mesh_uri = shape.mesh_uri;
  shape = wheel;
  in_link = wheel_in_link;
  return true;
}

// The SDF names sdformat's URDF converter gives the collisions of `owner` (a body's link) and of the
// links fixed to it, which it lumps into `owner`: by (URDF link, index in its collision_array).
// Its order: the owner's own, then each fixed child's, depth first in child-joint order (urdfdom's,
// by joint name). Entry i is named (the URDF name, or its original link's) + "_collision", + "_i" for
// i > 0, then prefixed "<owner>_fixed_joint_lump__" unless it starts with the owner's name. An SDF
// model's collisions (`sdf_names`) keep their own names.
void nameLumpedCollisions(const urdf::ModelInterface& model, const std::string& owner, const urdf::Link& link,
                          bool sdf_names, std::map<std::pair<std::string, size_t>, std::string>& names, size_t& index)
{
  for (size_t c = 0; c < link.collision_array.size(); ++c, ++index)
  {
    const urdf::CollisionSharedPtr& collision = link.collision_array[c];
    if (sdf_names)
    {
      names[{link.name, c}] = collision->name;
      continue;
    }
    std::string name = (collision && !collision->name.empty() ? collision->name : link.name) + "_collision";
    if (index > 0)
      name += "_" + std::to_string(index);
    if (name.compare(0, owner.size(), owner) != 0)
      name = owner + "_fixed_joint_lump__" + name;
    names[{link.name, c}] = name;
  }
  for (const urdf::JointSharedPtr& joint : link.child_joints)
    if (joint && joint->type == urdf::Joint::FIXED)
      if (urdf::LinkConstSharedPtr child = model.getLink(joint->child_link_name))
        nameLumpedCollisions(model, owner, *child, sdf_names, names, index);
}

// 3. Collision shapes, in each body's COM frame: a compound of the links' shapes, or the only shape
// itself where it is aligned with the body's frame. Meshes on the base of a robot fixed in the world
// are their triangles, elsewhere their convex hulls. Surface friction per body.
void collisionShapes(Robot::Internals& r, const LinkPlacement& placement, const std::vector<BodyPlan>& plans,
                     bool fixed_base)
{
  const urdf::ModelInterface& model = *r.description.model;
  std::vector<Body>& bodies = r.multibody.bodies;
  std::vector<Shape> last_child(bodies.size());  // the last shape added to each body's compound
  std::map<std::pair<std::string, size_t>, std::string>& sdf_names = r.multibody.link_collision_names;
  for (const Body& body : bodies)
    if (urdf::LinkConstSharedPtr owner = model.getLink(body.link))
    {
      size_t index = 0;
      nameLumpedCollisions(model, body.link, *owner, r.description.format == RobotDescription::Format::Sdf,
                           sdf_names, index);
    }
  for (const auto& kv : placement)
  {
    urdf::LinkConstSharedPtr link = model.getLink(kv.first);
    Body& body = bodies[kv.second.first];
    btTransform com_from_link = body.urdf_from_com.inverse() * kv.second.second;
    r.multibody.link_in_body[kv.first] = {kv.second.first, com_from_link};
    const Mobility mobility = fixed_base && kv.second.first == 0 ? Mobility::Static : Mobility::Moving;
    for (size_t ci = 0; ci < link->collision_array.size(); ++ci)
    {
      const urdf::CollisionSharedPtr& c = link->collision_array[ci];
      if (!c || !c->geometry)
        continue;
      Shape shape;
      if (!shapeFromUrdf(*c->geometry, link->name, r.world->log, shape))
        continue;
      btTransform in_com = com_from_link * toBullet(c->origin);
      Collider collider = makeCollider(shape, mobility, fromBullet(in_com), &r);
      if (!collider.shape)
      {
        r.world->log.warn("link '" + link->name + "': mesh collision '" + shape.mesh_uri + "' " + collider.reason +
                          "; the link has no collision there");
        continue;
      }
      if (collider.mesh && mobility == Mobility::Moving && link->name == body.link)
      {
        btTransform in_link = toBullet(c->origin);
        if (fitWheelToJoint(plans[kv.second.first].joint, collider, shape, in_link))
          in_com = com_from_link * in_link;
      }
      if (!collider.note.empty())
        r.world->log.info("link '" + link->name + "' of '" + r.name + "': mesh '" + shape.mesh_uri + "' " + collider.note);
      if (!body.compound)
        body.compound.reset(new btCompoundShape(false, 4));
      body.child_shapes.push_back(std::move(collider.shape));
      // A mesh of convex pieces (collision_shapes.h) goes in as its pieces, each a child of the body's
      // compound under the collision's name and surface: Bullet names a contact by the innermost
      // compound's child, which must be the body's.
      btCollisionShape* added = body.child_shapes.back().get();
      auto* pieces = added->isCompound() ? static_cast<btCompoundShape*>(added) : nullptr;
      const int children = pieces ? pieces->getNumChildShapes() : 1;
      const std::string& name = sdf_names[{link->name, ci}];
      // An SDF collision's own surface (a URDF's friction is the link's, below).
      auto surfaces = r.description.collision_surfaces.find(link->name);
      const bool has_surface = surfaces != r.description.collision_surfaces.end() && ci < surfaces->second.size();
      ContactSurface surface;
      if (has_surface)
      {
        bool plain = true;
        surface = contactSurface(surfaces->second[ci], in_com.getBasis(),
                                 "link '" + link->name + "' of '" + r.name + "' collision '" + name + "'",
                                 r.world->log, plain);
        body.surfaces_plain = body.surfaces_plain && plain;
      }
      for (int k = 0; k < children; ++k)
      {
        if (pieces)
          body.compound->addChildShape(in_com * pieces->getChildTransform(k), pieces->getChildShape(k));
        else
          body.compound->addChildShape(in_com, added);
        body.collision_names.push_back(name);
        if (has_surface)
          body.surfaces.push_back(surface);
      }
      body.shape = body.compound.get();
      last_child[kv.second.first] = shape;
      body.ray_shapes.push_back(std::move(collider.ray));
      body.ray_shapes.back().seen_by = kSeenByLidars;
    }
    auto surface = r.description.surfaces.find(link->name);
    if (surface != r.description.surfaces.end() && surface->second.given &&
        (link->name == body.link || !link->collision_array.empty()))
    {
      body.mu = std::min(surface->second.mu1, surface->second.mu2);
      if (!(body.mu >= 0))  // negative or NaN: Bullet would push along the motion
      {
        if (surface->second.urdf)  // an SDF collision's is said with its surface (contactSurface)
          r.world->log.warn("link '" + link->name + "' of '" + r.name + "': friction mu1/mu2 " +
                          formatNumber(surface->second.mu1) + "/" + formatNumber(surface->second.mu2) +
                          " is not a friction coefficient; it is taken as 0");
        body.mu = 0;
      }
      body.restitution = std::max(0.0, surface->second.restitution);
      body.restitution_threshold = surface->second.restitution_threshold;
    }
  }

  for (Body& body : bodies)
  {
    // The solver needs a body's surfaces where one asks for more than one friction coefficient, or
    // where its collisions' coefficients differ; else its collider's friction says it all.
    for (const ContactSurface& s : body.surfaces)
      body.surfaces_plain = body.surfaces_plain && s.mu1 == body.surfaces.front().mu1;
    if (body.surfaces_plain || body.surfaces.size() != body.collision_names.size())
      body.surfaces.clear();
  }

  for (size_t bi = 0; bi < bodies.size(); ++bi)
  {
    Body& body = bodies[bi];
    if (body.compound && body.compound->getNumChildShapes() == 1)
      if (btCollisionShape* aligned = makeAlignedCollisionShape(last_child[bi], body.compound->getChildTransform(0)))
      {
        body.compound.reset();
        body.child_shapes.clear();  // the aligned shape in place of the compound's child
        body.child_shapes.emplace_back(aligned);
        body.shape = aligned;
      }
  }
}

// 3b. What cameras see: each link's visuals (Gazebo's cameras render visuals, its lidars hit
// collisions), in their material's colour, in the body's COM frame.
void visualShapes(Robot::Internals& r, const LinkPlacement& placement)
{
  const urdf::ModelInterface& model = *r.description.model;
  const Log quiet;  // shapeFromUrdf's words are about collisions; a visual's own warning is below
  for (const auto& kv : placement)
  {
    urdf::LinkConstSharedPtr link = model.getLink(kv.first);
    Body& body = r.multibody.bodies[kv.second.first];
    const btTransform com_from_link = body.urdf_from_com.inverse() * kv.second.second;
    for (size_t index = 0; index < link->visual_array.size(); ++index)
    {
      const urdf::VisualSharedPtr& v = link->visual_array[index];
      if (!v || !v->geometry)
        continue;
      Shape shape;
      std::string reason = "is not a box, cylinder, sphere, capsule, ellipsoid or a mesh that is found";
      std::shared_ptr<const MeshData> mesh;
      if (shapeFromUrdf(*v->geometry, link->name, quiet, shape) &&
          (shape.kind != Shape::Kind::Mesh || (mesh = loadMesh(shape.mesh_file, shape.scale, reason))))
      {
        const urdf::Pose in_com = fromBullet(com_from_link * toBullet(v->origin));
        RayPrimitive p = mesh ? RayPrimitive::fromMesh(mesh, in_com, &r) : RayPrimitive::fromShape(shape, in_com, &r);
        p.seen_by = kSeenByCameras;
        p.material = visualMaterial(r.description, link->name, index, *v);
        if (mesh)
          for (const std::string& problem : textureProblems(*mesh))
            r.world->log.warn("link '" + link->name + "' of '" + r.name + "': mesh '" + shape.mesh_uri + "': " +
                              problem + "; cameras see it without that texture");
        body.ray_shapes.push_back(std::move(p));
        continue;
      }
      r.world->log.warn("link '" + link->name + "' of '" + r.name + "': a visual " + reason +
                        "; cameras do not see it");
    }
  }
}

// 4. The multibody: one Bullet link per body after the base, jointed as the URDF says. Returns each
// body's inertia about its joint axis (a lower bound of what the joint moves).
std::vector<double> createMultibody(Robot::Internals& r, const std::vector<BodyPlan>& plans, bool fixed_base,
                                    const urdf::Pose& pose)
{
  std::vector<Body>& bodies = r.multibody.bodies;
  const int n_links = int(bodies.size()) - 1;
  r.multibody.bullet.reset(new btMultiBody(n_links, btScalar(bodies[0].mass), bodies[0].inertia_diagonal, fixed_base, false));
  btMultiBody* mb = r.multibody.bullet.get();
  std::vector<double> axis_inertia(bodies.size(), 0.0);
  for (int bi = 1; bi <= n_links; ++bi)
  {
    const Body& body = bodies[bi];
    const Body& parent = bodies[body.parent];
    const urdf::Joint& joint = *plans[bi].joint;
    btTransform offset_in_parent = parent.urdf_from_com.inverse() * plans[bi].joint_in_parent;  // joint in parent COM
    btTransform offset_in_child = body.urdf_from_com.inverse();                                  // joint in child COM
    btQuaternion parent_to_this = offset_in_child.getRotation() * offset_in_parent.getRotation().inverse();
    btVector3 axis = offset_in_child.getBasis() * toBullet(joint.axis);
    if (axis.length2() < btScalar(1e-12))
      axis = offset_in_child.getBasis() * btVector3(1, 0, 0);  // urdfdom's default axis
    axis.normalize();
    btVector3 pivot_to_com = -offset_in_child.getOrigin();
    btVector3 lever = pivot_to_com - axis * axis.dot(pivot_to_com);
    axis_inertia[bi] = joint.type == urdf::Joint::PRISMATIC
                           ? body.mass
                           : axis.dot(body.inertia_diagonal * axis) + body.mass * lever.length2();
    if (isBall(r, joint))  // three rotations about the joint frame's origin; no axis
      mb->setupSpherical(bi - 1, btScalar(body.mass), body.inertia_diagonal, body.parent - 1, parent_to_this,
                         offset_in_parent.getOrigin(), -offset_in_child.getOrigin(), true);
    else if (joint.type == urdf::Joint::PRISMATIC)
      mb->setupPrismatic(bi - 1, btScalar(body.mass), body.inertia_diagonal, body.parent - 1, parent_to_this, axis,
                         offset_in_parent.getOrigin(), -offset_in_child.getOrigin(), true);
    else
      mb->setupRevolute(bi - 1, btScalar(body.mass), body.inertia_diagonal, body.parent - 1, parent_to_this, axis,
                        offset_in_parent.getOrigin(), -offset_in_child.getOrigin(), true);
  }
  mb->finalizeMultiDof();
  mb->setHasSelfCollision(false);  // SDF's <self_collide>: addColliders
  if (r.multibody.partial_gravity)
    mb->setUserPointer(r.multibody.partial_gravity.get());
  mb->setLinearDamping(0);
  mb->setAngularDamping(0);
  mb->setMaxCoordinateVelocity(btScalar(kMaxJointSpeed));
  mb->setCanSleep(false);
  r.spawn_pose = toBullet(pose);
  mb->setBaseWorldTransform(r.spawn_pose * bodies[0].urdf_from_com);
  r.world->dynamics->addMultiBody(mb);
  return axis_inertia;
}

// Joints whose URDF gives no effort limit get the robot's largest one (or kDefaultEffortLimit),
// said once per robot.
void limitUnlimitedEfforts(Robot::Internals& r)
{
  double strongest = 0.0;
  std::string unlimited;
  for (const MovableJoint& j : r.multibody.joints)
    if (std::isfinite(j.limits.effort))
      strongest = std::max(strongest, j.limits.effort);
    else if (!j.internal)
      unlimited += (unlimited.empty() ? "'" : ", '") + j.name + "'";
  if (unlimited.empty())
    return;
  const double limit = strongest > 0 ? strongest : kDefaultEffortLimit;
  for (MovableJoint& j : r.multibody.joints)
    if (!std::isfinite(j.limits.effort))
      j.limits.effort = limit;
  r.world->log.info("robot '" + r.name + "': joints " + unlimited + " have no URDF effort limit; they are limited to " +
                    formatNumber(limit) + (strongest > 0 ? " (the robot's largest)" : " (the plant's default)"));
}

// 5b. SDF's couplings (a screw's slide to its turn, a gearbox's gears): a row each, the followers'
// initial positions the leaders' times the multiplier (a follower given one alone moves its leader).
void coupleJoints(Robot::Internals& r, const std::map<std::string, double>& initial_joints)
{
  RobotMultibody& multibody = r.multibody;
  for (const JointCouplingDescription& c : r.description.joint_couplings)
  {
    auto leader = multibody.joint_index.find(c.leader), follower = multibody.joint_index.find(c.follower);
    if (leader == multibody.joint_index.end() || follower == multibody.joint_index.end())
    {
      r.world->log.error("robot '" + r.name + "': joint '" + c.name + "' couples joints '" + c.leader + "' and '" +
                         c.follower + "', which are not both movable; they are not coupled");
      continue;
    }
    MovableJoint& f = multibody.joints[follower->second];
    MovableJoint& l = multibody.joints[leader->second];
    f.internal = c.follower_internal;
    JointCoupling k;
    k.name = c.name;
    k.leader = leader->second;
    k.follower = follower->second;
    k.multiplier = c.multiplier;
    k.row.reset(new JointDrive(r.world->dynamics.get(), multibody.bullet.get(), f.link, l.link, c.multiplier));
    multibody.couplings.push_back(std::move(k));
    if (initial_joints.count(c.follower) && !initial_joints.count(c.leader) && c.multiplier != 0)
    {
      l.initial_position = positionWithinLimits(l, f.initial_position / c.multiplier, r.world->log, r.name,
                                                "initial position");
      multibody.bullet->setJointPos(l.link, btScalar(l.initial_position));
    }
    f.initial_position = c.multiplier * l.initial_position;
    multibody.bullet->setJointPos(f.link, btScalar(f.initial_position));
  }
}

// 5. Movable joints: limits, URDF dynamics, SDF springs, the drive the joint layer uses and the rows
// for damping, springs, dry friction and limits; SDF's ball joints beside them, and couplings.
void createJoints(Robot::Internals& r, const std::vector<BodyPlan>& plans, const std::vector<double>& axis_inertia,
                  const std::map<std::string, double>& initial_joints)
{
  btMultiBody* mb = r.multibody.bullet.get();
  for (size_t bi = 1; bi < plans.size(); ++bi)
  {
    const urdf::Joint& uj = *plans[bi].joint;
    if (isBall(r, uj))
    {
      r.multibody.balls.push_back({uj.name, int(bi) - 1});
      continue;
    }
    MovableJoint j;
    j.name = uj.name;
    j.link = int(bi) - 1;
    j.type = uj.type == urdf::Joint::PRISMATIC ? JointType::Prismatic
             : uj.type == urdf::Joint::CONTINUOUS ? JointType::Continuous : JointType::Revolute;
    j.limits.effort = kInf;
    j.limits.velocity = kInf;
    if (uj.limits)
    {
      j.limits.effort = std::abs(uj.limits->effort);
      j.limits.velocity = uj.limits->velocity > 0 ? uj.limits->velocity : kInf;
      if (j.type != JointType::Continuous && uj.limits->lower < uj.limits->upper)
      {
        j.limits.has_position = true;
        j.limits.lower = uj.limits->lower;
        j.limits.upper = uj.limits->upper;
      }
    }
    if (uj.dynamics)
    {
      j.damping = std::max(0.0, uj.dynamics->damping);
      j.friction = std::max(0.0, uj.dynamics->friction);
    }
    auto initial = initial_joints.find(j.name);
    if (initial != initial_joints.end())
      j.initial_position = initial->second;
    j.initial_position = positionWithinLimits(j, j.initial_position, r.world->log, r.name, "initial position");
    mb->setJointPos(j.link, btScalar(j.initial_position));

    j.axis_inertia = axis_inertia[bi];
    auto spring = r.description.joint_springs.find(j.name);
    if (spring != r.description.joint_springs.end())
    {
      j.spring_stiffness = spring->second.stiffness;
      j.spring_reference = spring->second.reference;
    }
    updateJointRows(r, j);
    r.multibody.joint_index[j.name] = r.multibody.joints.size();
    r.multibody.joints.push_back(std::move(j));
  }
  coupleJoints(r, initial_joints);
  limitUnlimitedEfforts(r);
}

// A body's collider in a model whose links collide with each other (SDF's <self_collide>) or that is
// several trees (free links), as Gazebo's ODE collides a model's links: two bodies of the model
// touch where either self-collides (a self-colliding link's collisions are in a space of their own,
// which ODE collides with the model's space and every other space), never two joined by a joint
// (ODEPhysics::CollisionCallback's dAreConnectedExcluding). A body's links fixed together are one
// body: it self-collides where any of them does. The model it is of is its user pointer (its
// canonical tree's robot), which every collider of the model's trees shares.
class SelfCollidingCollider : public btMultiBodyLinkCollider
{
public:
  SelfCollidingCollider(btMultiBody* multibody, int link, bool self_collide, int joined_to, void* model)
    : btMultiBodyLinkCollider(multibody, link), self_collide_(self_collide), joined_to_(joined_to)
  {
    setUserPointer(model);
  }
  bool checkCollideWithOverride(const btCollisionObject* object) const override
  {
    const btMultiBodyLinkCollider* other = btMultiBodyLinkCollider::upcast(object);
    if (!other || other->getUserPointer() != getUserPointer())
      return true;  // another model's
    const auto* ours = static_cast<const SelfCollidingCollider*>(other);  // every collider of the model is one
    if (other->m_multiBody != m_multiBody)
      return self_collide_ || ours->self_collide_;  // another tree of the model: no joint joins them
    return (self_collide_ || ours->self_collide_) && joined_to_ != other->m_link && ours->joined_to_ != m_link;
  }

private:
  bool self_collide_;
  int joined_to_;  // the Bullet link its joint joins it to (-1 the base), past frames; -2 for the base
};

// Whether any body's links collide with the model's other links.
bool selfColliding(const Robot::Internals& r, std::vector<bool>& body_self_collides)
{
  const std::vector<Body>& bodies = r.multibody.bodies;
  body_self_collides.assign(bodies.size(), false);
  for (const auto& kv : r.multibody.link_in_body)
    if (physicsOf(r, kv.first).self_collide)
      body_self_collides[size_t(kv.second.first)] = true;
  return std::find(body_self_collides.begin(), body_self_collides.end(), true) != body_self_collides.end();
}

// 6. Colliders: one per body with a shape, in the world's broadphase. A robot without any collision
// still gets one, shapeless, on its base: Bullet solves a multibody's constraint rows (the joint
// layer's motors, limits, damping) within its simulation island, and only colliders make islands.
void addColliders(Robot::Internals& r)
{
  btMultiBody* mb = r.multibody.bullet.get();
  std::vector<Body>& bodies = r.multibody.bodies;
  if (std::none_of(bodies.begin(), bodies.end(), [](const Body& b) { return b.shape != nullptr; }))
  {
    bodies[0].child_shapes.emplace_back(new btEmptyShape());
    bodies[0].shape = bodies[0].child_shapes.back().get();
  }
  std::vector<bool> self_collides;
  const bool self_colliding = selfColliding(r, self_collides);
  mb->setHasSelfCollision(self_colliding);
  Robot::Internals* model = r.canonical ? r.canonical : &r;
  for (size_t bi = 0; bi < bodies.size(); ++bi)
  {
    Body& body = bodies[bi];
    if (!body.shape)
      continue;
    if (self_colliding || r.several_trees)
    {
      // The body its joint joins it to, past the frames between two axes of a universal joint.
      int joined = bi == 0 ? -1 : body.parent;
      while (joined > 0 && r.description.frame_links.count(bodies[size_t(joined)].link))
        joined = bodies[size_t(joined)].parent;
      r.multibody.colliders.emplace_back(
          new SelfCollidingCollider(mb, int(bi) - 1, self_collides[bi], bi == 0 ? -2 : joined - 1, model));
    }
    else
      r.multibody.colliders.emplace_back(new btMultiBodyLinkCollider(mb, int(bi) - 1));
    btMultiBodyLinkCollider* col = r.multibody.colliders.back().get();
    col->setCollisionShape(body.shape);
    col->setFriction(btScalar(body.mu));
    r.world->solver->setBounce(*col, btScalar(body.restitution), btScalar(body.restitution_threshold));
    if (!body.surfaces.empty())
      r.world->solver->setSurfaces(*col, body.surfaces, !(bi == 0 && mb->hasFixedBase()));
    col->setWorldTransform(r.multibody.bodyWorldTransform(int(bi)));
    correctInternalEdges(*col);
    r.world->dynamics->addCollisionObject(col, btBroadphaseProxy::DefaultFilter, btBroadphaseProxy::AllFilter);
    if (bi == 0)
      mb->setBaseCollider(col);
    else
      mb->getLink(int(bi) - 1).m_collider = col;
  }
  r.multibody.updateKinematics();
}

// 7. gazebo_ros_control's joint handles, one per transmitted joint, with the pid_gains loops.
void createHandles(Robot::Internals& r)
{
  const urdf::ModelInterface& model = *r.description.model;
  r.joint_layer.setLog(&r.world->log);
  for (const TransmissionDescription& t : r.description.transmissions)
  {
    if (!model.getJoint(t.joint))
      throw DescriptionError("transmission '" + t.name + "' names joint '" + t.joint + "', which robot '" + r.name +
                             "' does not have; fix the transmission or add the joint to the URDF");
    auto index = r.multibody.joint_index.find(t.joint);
    if (index == r.multibody.joint_index.end())
      throw DescriptionError("transmission '" + t.name + "' names joint '" + t.joint + "', which is " +
                             (r.multibody.ball(t.joint) ? "a ball joint" : "fixed") +
                             "; only revolute, continuous and prismatic joints can be actuated");
    if (r.joint_layer.drives(index->second))
    {
      r.world->log.warn("joint '" + t.joint + "' appears in more than one transmission; the first one is used");
      continue;
    }
    bool ok = false;
    JointInterface iface = parseInterface(t.hardware_interface, ok);
    if (!ok)
    {
      r.world->log.error("transmission '" + t.name + "' of joint '" + t.joint + "' uses '" + t.hardware_interface +
                         "', which is not EffortJointInterface, VelocityJointInterface or PositionJointInterface; "
                         "the joint gets no command handle");
      continue;
    }
    JointHandle& h = r.joint_layer.addHandle(r.multibody.joints[index->second], index->second, iface);
    // legacyModeNS (gazebo_ros_control's default): Gazebo reads /gazebo_ros_control/pid_gains; the
    // plant reads them there first and then under the robot namespace (docs/interfaces.md section 11).
    std::string pid_ns = "/gazebo_ros_control/pid_gains/" + t.joint;
    const Param* p = r.description.control.legacy_mode_ns ? r.world->params.find(joinPath(pid_ns, "p")) : nullptr;
    if (!p)
    {
      pid_ns = joinPath(r.control_namespace, "gazebo_ros_control/pid_gains/" + t.joint);
      p = r.world->params.find(joinPath(pid_ns, "p"));
    }
    if (iface != JointInterface::Effort && p && p->isNumber())
      h.setPid(readPidGains(r.world->params, pid_ns));
  }
}

// 8. gazebo_ros_control's controller manager, updated every control period.
void createControllerManager(Robot::Internals& r)
{
  if (!r.description.control.present)
    return;
  r.control_period_ns = r.world->step_ns;
  double period = r.description.control.control_period;
  if (period > 0 && std::llround(period * 1e9) < r.world->step_ns)
    r.world->log.warn("Desired controller update period (" + std::to_string(period) + " s) of '" + r.name +
                      "' is faster than the simulation period (" + std::to_string(r.world->step_s) +
                      " s); using the latter");
  else if (period > 0)
    r.control_period_ns = std::llround(period * 1e9);
  r.last_control_ns = r.world->time_ns;
  r.controller_manager.reset(new ControllerManager(r.joint_layer, r.world->params, r.world->log, r.control_namespace));
  r.controller_manager->setPaused(r.world->paused);
}

// What keeps a ray sensor from scanning, or empty. A fan of any direction (min_angle above max_angle,
// both equal) and any range (min 0, min equal to or above max: every ray reads +inf) scans.
std::string lidarProblem(const SensorDescription& s)
{
  if (s.horizontal_samples < 1 || s.vertical_samples < 1)
    return "<scan> has " + std::to_string(s.horizontal_samples) + " horizontal and " +
           std::to_string(s.vertical_samples) + " vertical <samples>: give each at least 1";
  if (!(s.range_max > 0))
    return "<range><max> is " + formatNumber(s.range_max) + ": give the farthest distance it measures, above 0";
  if (double(s.horizontal_samples) * s.vertical_samples > kMaxRaysPerScan)
    return std::to_string(s.horizontal_samples) + " x " + std::to_string(s.vertical_samples) +
           " rays a scan is more than the " + std::to_string(kMaxRaysPerScan) + " the plant casts";
  return "";
}

// A sonar (Gazebo's: the nearest thing in a cone from its origin along its -z axis, <radius> wide at
// <max> - <min> along it, or in a sphere of that radius) as the plant's lidar samples it: rings of
// rays about -z out to the cone's rim (kSonarRings from straight down, kSonarRaysARing round), or
// rays all round; SonarBridge (gazebo_host) takes the nearest hit within the shape. Rays collide
// with collisions, as Gazebo's sonar shape does.
constexpr int kSonarRings = 8, kSonarRaysARing = 32;
SensorDescription sonarSampling(const SensorDescription& sonar)
{
  SensorDescription rays = sonar;
  rays.type = "ray";
  const double height = sonar.range_max - sonar.range_min;
  const bool sphere = sonar.sonar_geometry == "sphere";
  const double half_angle = sphere ? M_PI : std::atan2(std::max(0.0, sonar.sonar_radius), height);
  rays.horizontal_samples = kSonarRaysARing;
  rays.horizontal_min_angle = -M_PI;
  rays.horizontal_max_angle = M_PI - 2 * M_PI / kSonarRaysARing;
  rays.vertical_samples = sphere ? 2 * kSonarRings + 1 : kSonarRings;
  rays.vertical_min_angle = -M_PI / 2;
  rays.vertical_max_angle = sphere ? M_PI / 2 : -M_PI / 2 + half_angle;
  rays.range_min = 0.0;
  rays.range_max = sphere ? height : height / std::cos(half_angle);  // to the cone's rim
  rays.range_resolution = 0.0;
  rays.noise = Noise();
  return rays;
}

// What keeps a camera from rendering, or empty.
std::string cameraProblem(const SensorDescription& s)
{
  if (s.image_width < 1 || s.image_height < 1)
    return "<image> is " + std::to_string(s.image_width) + " x " + std::to_string(s.image_height) +
           ": give a <width> and <height> of at least 1";
  if (!(s.horizontal_fov > 0 && s.horizontal_fov < M_PI))
    return "<horizontal_fov> is " + formatNumber(s.horizontal_fov) +
           ": a pinhole camera's lies between 0 and pi (radians)";
  if (double(s.image_width) * s.image_height > kMaxPixelsPerImage)
    return std::to_string(s.image_width) + " x " + std::to_string(s.image_height) + " pixels is more than the " +
           std::to_string(kMaxPixelsPerImage) + " the plant renders";
  return "";
}

// 9. Sensors, each with its own noise generator seeded from the robot's and the sensor's names (and
// the world's noise seed, when one is set), in the namespace its plugin publishes in.
std::unique_ptr<Sensor> createSensor(Robot::Internals& r, const SensorDescription& s)
{
  Log& log = r.world->log;
  const uint32_t world_seed = r.world->noise_seed;
  const uint32_t seed = seedFor((world_seed ? std::to_string(world_seed) + "/" : std::string()) + r.name + "/" + s.name);
  const bool lidar = s.type == "ray" || s.type == "gpu_ray", camera = s.type == "camera" || s.type == "depth";
  if (lidar || camera)
  {
    const std::string problem = lidar ? lidarProblem(s) : cameraProblem(s);
    if (!problem.empty())
    {
      log.error("sensor '" + s.name + "' (" + s.type + ") of '" + r.name + "': " + problem + "; it publishes nothing");
      return nullptr;
    }
    return lidar ? std::unique_ptr<Sensor>(new Lidar(s, seed)) : std::unique_ptr<Sensor>(new Camera(s, seed));
  }
  if (s.type == "imu")
  {
    std::unique_ptr<Imu> imu(new Imu(s, seed));
    imu->setReference(compose(fromBullet(r.multibody.linkWorldTransform(s.link, r.name)), s.pose).rotation);
    return std::move(imu);
  }
  if (s.type == "p3d")
    return std::unique_ptr<Sensor>(new GroundTruthOdometry(s, seed));
  if (s.type == "contact")
    return std::unique_ptr<Sensor>(new ContactSensor(s, seed));
  if (s.type == "sonar" && !s.library.empty())
  {
    // the plant has no sonar of its own to publish: one is sampled for a sensor plugin of the user's
    const SensorDescription rays = sonarSampling(s);
    if (rays.range_max > 0)
      return std::unique_ptr<Sensor>(new Lidar(rays, seed));
    log.error("sensor '" + s.name + "' (sonar) of '" + r.name + "': its <max> is not above its <min>; it measures "
              "nothing");
    return nullptr;
  }
  if (!s.library.empty() && measuredByGazeboApi(s.type))
    return nullptr;  // Gazebo's sensor of the user's plugin measures it (loadGazeboSensorPlugins)
  log.warn("sensor '" + s.name + "' of type '" + s.type + "' of '" + r.name +
           "' is not simulated (ray, gpu_ray, camera, depth, imu, contact are; altimeter, magnetometer, gps, "
           "force_torque and sonar with a sensor plugin of the user's own)");
  return nullptr;
}

void createSensors(Robot::Internals& r)
{
  for (const SensorDescription& s : r.description.sensors)
    if (std::unique_ptr<Sensor> sensor = createSensor(r, s))
      r.sensors.push_back(std::move(sensor));
}

// 10. gazebo_plugins' model plugins that drive joints (model_plugin.h), once the robot is in the
// world (loadModelPlugins), after the handles: a joint a transmission drives is refused to them.
// One that cannot load is left out, said by its Load.
void createModelPlugins(Robot::Internals& r)
{
  for (const ModelPluginDescription& d : r.description.model_plugins)
  {
    std::unique_ptr<ModelPlugin> plugin = d.library.empty() ? createModelPlugin(d.filename) : createGazeboModelPlugin();
    if (!plugin)
      continue;
    plugin->setDescription(d);
    try
    {
      if (plugin->Load(d, r.model_plugin_context, r.world->time_ns))
        r.model_plugins.push_back(std::move(plugin));
    }
    catch (const DescriptionError& e)
    {
      r.world->log.error(r.name + ": " + e.what() + "; the plugin is not loaded");
    }
  }
}
// 11. The sensor plugins of the user's own (a <sensor>'s <plugin> file found on the plugin paths),
// over the sensors made in step 9, hosted by the world's Gazebo host as Gazebo's sensors: one for
// each <sensor> (a multicamera's cameras, consecutive descriptions of one element, together).
void loadGazeboSensorPlugins(Robot::Internals& r)
{
  const std::vector<SensorDescription>& described = r.description.sensors;
  for (size_t first = 0, end = 0; first < described.size(); first = end)
  {
    end = first + 1;
    const SensorDescription& d = described[first];
    if (!d.multicamera_camera.empty() && d.element)
      while (end < described.size() && described[end].element == d.element)
        ++end;
    if (d.library.empty())
      continue;
    std::vector<Sensor*> simulated;  // none for a type Gazebo's API measures itself
    for (size_t i = first; i < end && !measuredByGazeboApi(d.type); ++i)
      for (const std::unique_ptr<Sensor>& s : r.sensors)
        if (s->name() == described[i].name)
          simulated.push_back(s.get());
    if (!measuredByGazeboApi(d.type) && simulated.size() != end - first)
      r.world->log.error(r.name + ": sensor '" + d.name + "' plugin '" + d.plugin_name + "' (" + d.plugin_filename +
                         "): its sensor is not simulated; the plugin is not loaded");
    else
      r.model_plugin_context.gazeboHost().loadSensorPlugin(d, simulated, r.model_plugin_context);
  }
}
}  // namespace

namespace
{
// A model nothing drives from inside (no controller manager, model plugins or sensors: a free SDF
// object, a loose part) sleeps when at rest, as Gazebo's bodies do under ODE's auto-disable: a
// resting body then costs the step nothing until a moving body touches it (Bullet's islands), or
// a wrench, a joint effort, a new state or gravity wakes it (wakeUp). At rest: the multibody's
// velocities, squared and summed (Bullet's measure), below kSleepSpeed^2 for kSleepTime. Gazebo
// sets ODE's auto-disable to 0.1 m/s and 0.1 rad/s for 1 s (ODEPhysics::Load); Bullet's multibody
// defaults (0.22 m/s for 2 s) would stop a box still sliding at 0.2 m/s. A robot with
// controllers, plugins or sensors never sleeps: they run at every step whether or not it moves. Nor
// does a model with movable joints, as Gazebo keeps one awake: a pendulum swinging 0.05 rad either
// side moves slower than 0.1 rad/s all the time and would stop.
constexpr double kSleepSpeed = 0.1;
constexpr double kSleepTime = 1.0;

void allowSleep(Robot::Internals& r)
{
  // SDF's <allow_auto_disable>false: never (ODELink::Init's auto-disable flag off); a kinematic
  // model moves at its set velocity whatever touches it.
  const bool driven = r.controller_manager || !r.model_plugins.empty() || !r.sensors.empty() ||
                      !r.multibody.joints.empty() || !r.multibody.balls.empty() || !r.description.allow_auto_disable ||
                      r.kinematic;
  btMultiBody& mb = *r.multibody.bullet;
  mb.setCanSleep(!driven);
  mb.setSleepThreshold(btScalar(kSleepSpeed * kSleepSpeed));
  mb.setSleepTimeout(btScalar(kSleepTime));
}
}  // namespace

void buildRobot(Robot::Internals& r, const urdf::Pose& pose, const std::map<std::string, double>& initial_joints)
{
  urdf::LinkConstSharedPtr root = r.description.model->getRoot();
  if (!root)
    throw DescriptionError("URDF of '" + r.name + "' has no root link");
  const bool world_rooted = root->name == "world";

  LinkPlacement placement;
  const std::vector<BodyPlan> plans = planBodies(r, root, placement);
  // SDF's <kinematic>: a base with a kinematic link is a fixed base, not moved by dynamics, as ODE's
  // kinematic body (infinite mass, no gravity); Bullet moves a fixed base at the velocity set on it,
  // as ODE moves a kinematic body. A kinematic link beyond the base is a joint's child, which the
  // multibody moves by dynamics.
  std::string dynamic_kinematic;
  for (const auto& kv : placement)
    if (physicsOf(r, kv.first).kinematic)
    {
      if (kv.second.first == 0)
        r.kinematic = !world_rooted && !r.description.is_static;
      else
        dynamic_kinematic += (dynamic_kinematic.empty() ? "'" : ", '") + kv.first + "'";
    }
  if (!dynamic_kinematic.empty())
    r.world->log.warn("robot '" + r.name + "': links " + dynamic_kinematic + " are <kinematic> but hang from a "
                      "movable joint; the plant moves them by dynamics (only a model's base link is kinematic)");
  // A static model (<gazebo><static>) never moves: its base is fixed where it is spawned.
  const bool fixed_base = world_rooted || r.description.is_static || r.kinematic;
  massProperties(r, placement, world_rooted);
  partialGravity(r, placement);
  collisionShapes(r, placement, plans, fixed_base && !r.kinematic);
  visualShapes(r, placement);
  const std::vector<double> axis_inertia = createMultibody(r, plans, fixed_base, pose);
  createJoints(r, plans, axis_inertia, initial_joints);
  addColliders(r);
  createHandles(r);
  createControllerManager(r);
  createSensors(r);
  for (const std::string& w : r.description.warnings)
    r.world->log.warn(r.name + ": " + w);
  for (const std::string& e : r.description.errors)
    r.world->log.error(r.name + ": " + e);
  r.recovery.last_good.save(r.multibody);
}

void loadModelPlugins(Robot::Internals& r)
{
  for (const std::string& joint : r.description.joint_feedback)  // before a plugin asks for it
    r.wrench_watches.watch(r.multibody, r.description, joint);
  createModelPlugins(r);
  loadGazeboSensorPlugins(r);
  allowSleep(r);
}

void updateJointRows(Robot::Internals& r, MovableJoint& j)
{
  btMultiBody* mb = r.multibody.bullet.get();
  auto add = [&](std::unique_ptr<JointDrive>& drive) {
    if (!drive)
      drive.reset(new JointDrive(r.world->dynamics.get(), mb, j.link));
  };
  add(j.drive);
  if (j.damping > 0 && !explicitDampingStable(j, r.world->step_s))
    add(j.damper);
  if (j.spring_stiffness > 0 && !explicitSpringAccurate(j, r.world->step_s))
    add(j.spring);
  if (j.friction > 0)
    add(j.dry_friction);
  if (j.limits.has_position)
  {
    add(j.lower_limit);
    add(j.upper_limit);
  }
  else
    for (JointDrive* limit : {j.lower_limit.get(), j.upper_limit.get()})
      if (limit)
        limit->disable();
}

namespace
{
// Each link's body and its frame in that body's URDF frame, as planBodies found them.
LinkPlacement placementOf(const Robot::Internals& r)
{
  LinkPlacement placement;
  for (const auto& kv : r.multibody.link_in_body)
    placement[kv.first] = {kv.second.first,
                           r.multibody.bodies[size_t(kv.second.first)].urdf_from_com * kv.second.second};
  return placement;
}
}  // namespace

void updateBodyMass(Robot::Internals& r, int body_index, std::string& note)
{
  Body& body = r.multibody.bodies[size_t(body_index)];
  btMultiBody& mb = *r.multibody.bullet;
  const LinkPlacement placement = placementOf(r);
  BodyMass sum = sumBodyMass(r, placement, size_t(body_index));
  const bool world_rooted = r.description.model->getRoot()->name == "world";
  if (sum.mass < kMinimumMass && !(body_index == 0 && world_rooted))
  {
    note += " The body of link '" + body.link + "' would have no mass: the plant gives it " +
            formatNumber(kMinimumMass) + " kg.";
    sum.mass = kMinimumMass;
  }
  // Bullet's body frame is the centre of mass on its principal axes as built: moving it would move
  // every collider, visual and sensor mount of the body. The inertia is taken about it, along it.
  const btVector3 shift = sum.com - body.urdf_from_com.getOrigin();
  if (shift.length() > btScalar(1e-6))
  {
    std::ostringstream text;
    text << " The centre of mass of the body of link '" << body.link << "' would move " << shift.length()
         << " m; the plant keeps it where it was built, the inertia taken about it.";
    note += text.str();
    const btVector3& d = shift;
    const btScalar m = btScalar(sum.mass);
    sum.inertia += btMatrix3x3(d.dot(d) - d.x() * d.x(), -d.x() * d.y(), -d.x() * d.z(),
                               -d.y() * d.x(), d.dot(d) - d.y() * d.y(), -d.y() * d.z(),
                               -d.z() * d.x(), -d.z() * d.y(), d.dot(d) - d.z() * d.z()) * m;
  }
  const btMatrix3x3 axes = body.urdf_from_com.getBasis();
  const btMatrix3x3 local = axes.transpose() * sum.inertia * axes;
  btScalar diagonal = 0, off = 0;
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k)
      (i == k ? diagonal : off) = std::max(i == k ? diagonal : off, std::abs(local[i][k]));
  if (off > btScalar(1e-6) * diagonal)
    note += " The principal axes of the body of link '" + body.link + "' would turn; the plant keeps the axes it "
            "was built with (the inertia's products about them are left out).";
  body.mass = sum.mass;
  for (int i = 0; i < 3; ++i)
    body.inertia_diagonal[i] = std::max(local[i][i], btScalar(kMinimumInertia));
  if (body_index == 0)
  {
    mb.setBaseMass(btScalar(body.mass));
    mb.setBaseInertia(body.inertia_diagonal);
  }
  else
  {
    btMultibodyLink& link = mb.getLink(body_index - 1);
    link.m_mass = btScalar(body.mass);
    link.m_inertiaLocal = body.inertia_diagonal;
    // The joint into the body: its inertia about the axis decides which rows it needs.
    for (MovableJoint& j : r.multibody.joints)
      if (j.link == body_index - 1)
      {
        const btVector3& pivot_to_com = link.m_dVector;
        if (j.type == JointType::Prismatic)
          j.axis_inertia = body.mass;
        else
        {
          const btVector3 axis = link.getAxisTop(0);
          const btVector3 lever = pivot_to_com - axis * axis.dot(pivot_to_com);
          j.axis_inertia = axis.dot(body.inertia_diagonal * axis) + body.mass * lever.length2();
        }
        updateJointRows(r, j);
      }
  }
  warnOfMassRatio(r);
  updatePartialGravity(r);
}

void updatePartialGravity(Robot::Internals& r)
{
  partialGravity(r, placementOf(r));
  r.multibody.bullet->setUserPointer(r.multibody.partial_gravity.get());
}

void detachFromPhysics(Robot::Internals& r)
{
  btMultiBodyDynamicsWorld* dynamics = r.world->dynamics.get();
  r.multibody.disableJointRows();
  for (auto& col : r.multibody.colliders)
    dynamics->removeCollisionObject(col.get());
  if (r.multibody.bullet)
    dynamics->removeMultiBody(r.multibody.bullet.get());
}

void removeRobot(Robot::Internals& r)
{
  r.controller_manager.reset();
  if (!r.disabled)
    detachFromPhysics(r);
}

}  // namespace bullet_plant
