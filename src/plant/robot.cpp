// Robot: URDF -> Bullet multibody, the gazebo_ros_control joint layer, sensors.
#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <sstream>

#include "bullet_plant/params.h"
#include "internals.h"
#include "mesh_bounds.h"

namespace bullet_plant
{
namespace
{
constexpr double kInf = std::numeric_limits<double>::infinity();
// Bodies lighter than this get it (with a warning): the articulated-body algorithm needs mass.
constexpr double kMinimumMass = 1e-3;
constexpr double kMinimumInertia = 1e-9;
// Collision margin: Bullet's default (4 cm) is larger than this car's wheels.
constexpr btScalar kCollisionMargin = btScalar(0.0005);

btVector3 vec(const urdf::Vector3& v) { return btVector3(btScalar(v.x), btScalar(v.y), btScalar(v.z)); }

// Inertia tensor of a link's <inertial> about its centre of mass, in the link frame.
btMatrix3x3 inertiaInLink(const urdf::Inertial& in)
{
  btMatrix3x3 I(btScalar(in.ixx), btScalar(in.ixy), btScalar(in.ixz),
                btScalar(in.ixy), btScalar(in.iyy), btScalar(in.iyz),
                btScalar(in.ixz), btScalar(in.iyz), btScalar(in.izz));
  btMatrix3x3 R = toBullet(in.origin).getBasis();
  return R * I * R.transpose();
}

double clampAbs(double v, double limit) { return std::max(-limit, std::min(v, limit)); }

double wrapToPi(double a)
{
  a = std::fmod(a + M_PI, 2.0 * M_PI);
  return a < 0 ? a + M_PI : a - M_PI;
}

// angles::shortest_angular_distance_with_large_limits, for a revolute joint's PID: the error that
// reaches the target without leaving [lower, upper].
double revoluteError(double from, double to, double lower, double upper)
{
  double delta = wrapToPi(to - from);
  double alternative = delta > 0 ? delta - 2 * M_PI : delta + 2 * M_PI;
  auto inside = [&](double d) { return from + d >= lower - 1e-9 && from + d <= upper + 1e-9; };
  if (inside(delta))
    return delta;
  if (inside(alternative))
    return alternative;
  return to - from;  // target outside the limits (clamped by the caller): go straight
}

struct BodyPlan
{
  const urdf::Joint* joint = nullptr;       // the movable joint into the body (null for the base)
  btTransform joint_in_parent = btTransform::getIdentity();  // joint frame in the parent body's URDF frame
};

Shape shapeOf(const urdf::Geometry& g, const std::string& link, Log& log, bool& ok, btTransform& offset)
{
  Shape s;
  ok = true;
  offset.setIdentity();
  switch (g.type)
  {
    case urdf::Geometry::BOX:
    {
      const auto& box = static_cast<const urdf::Box&>(g);
      s.kind = Shape::Kind::Box;
      s.box_size = {{box.dim.x, box.dim.y, box.dim.z}};
      break;
    }
    case urdf::Geometry::CYLINDER:
    {
      const auto& c = static_cast<const urdf::Cylinder&>(g);
      s.kind = Shape::Kind::Cylinder;
      s.radius = c.radius;
      s.length = c.length;
      break;
    }
    case urdf::Geometry::SPHERE:
      s.kind = Shape::Kind::Sphere;
      s.radius = static_cast<const urdf::Sphere&>(g).radius;
      break;
    case urdf::Geometry::MESH:
    {
      const auto& mesh = static_cast<const urdf::Mesh&>(g);
      MeshBounds b;
      std::string reason;
      if (!readMeshBounds(mesh.filename, b, reason))
      {
        log.warn("link '" + link + "': mesh collision " + reason + "; the link has no collision there");
        ok = false;
        return s;
      }
      s.kind = Shape::Kind::Box;
      double scale[3] = {mesh.scale.x, mesh.scale.y, mesh.scale.z};
      btVector3 centre;
      for (int i = 0; i < 3; ++i)
      {
        s.box_size[i] = std::max(1e-4, (b.max[i] - b.min[i]) * std::abs(scale[i]));
        centre[i] = btScalar((b.max[i] + b.min[i]) / 2.0 * scale[i]);
      }
      offset.setOrigin(centre);
      log.warn("link '" + link + "': mesh collision '" + mesh.filename +
               "' is simulated as its bounding box; use box/cylinder/sphere collisions for accurate contact");
      break;
    }
    default:
      ok = false;
  }
  for (double v : {s.radius, s.length, s.box_size[0], s.box_size[1], s.box_size[2]})
    if (!std::isfinite(v) || v < 0)
      ok = false;
  if ((s.kind == Shape::Kind::Box && (s.box_size[0] <= 0 || s.box_size[1] <= 0 || s.box_size[2] <= 0)) ||
      (s.kind != Shape::Kind::Box && s.radius <= 0) || (s.kind == Shape::Kind::Cylinder && s.length <= 0))
  {
    log.warn("link '" + link + "': a collision has a zero or negative size; ignored");
    ok = false;
  }
  return s;
}

btCollisionShape* bulletShape(const Shape& s)
{
  btCollisionShape* shape = nullptr;
  switch (s.kind)
  {
    case Shape::Kind::Box:
      shape = new btBoxShape(btVector3(btScalar(s.box_size[0] / 2), btScalar(s.box_size[1] / 2), btScalar(s.box_size[2] / 2)));
      break;
    case Shape::Kind::Cylinder:
      shape = new btCylinderShapeZ(btVector3(btScalar(s.radius), btScalar(s.radius), btScalar(s.length / 2)));
      break;
    case Shape::Kind::Sphere:
      shape = new btSphereShape(btScalar(s.radius));
      break;
    case Shape::Kind::Plane:
      shape = new btStaticPlaneShape(btVector3(btScalar(s.normal.x), btScalar(s.normal.y), btScalar(s.normal.z)), 0);
      break;
  }
  shape->setMargin(s.kind == Shape::Kind::Sphere ? shape->getMargin() : kCollisionMargin);
  return shape;
}

// The shape as Bullet's axis-aligned primitive where its pose in the body frame is one of its
// symmetries (no offset; for a box a rotation that permutes its axes, for a cylinder one that puts
// its axis on a body axis, for a sphere any): then the collider needs no compound, which costs
// every contact pair a tree walk and a transform per step. Null where the compound is needed.
// The tolerances absorb float rounding of the URDF's angles (cos(pi/2) is 4e-8 in float).
btCollisionShape* alignedShape(const Shape& s, const btTransform& pose)
{
  constexpr btScalar kTolerance = btScalar(1e-6);
  if (pose.getOrigin().length() > kTolerance)
    return nullptr;
  // The body axis that the shape's axis k lies along, or -1.
  auto bodyAxisOf = [&](int k) {
    for (int i = 0; i < 3; ++i)
      if (btFabs(btFabs(pose.getBasis()[i][k]) - 1) < kTolerance)
        return i;
    return -1;
  };
  btCollisionShape* shape = nullptr;
  switch (s.kind)
  {
    case Shape::Kind::Sphere:
      return bulletShape(s);
    case Shape::Kind::Box:
    {
      btVector3 half;
      for (int k = 0; k < 3; ++k)
      {
        const int i = bodyAxisOf(k);
        if (i < 0)
          return nullptr;
        half[i] = btScalar(s.box_size[k] / 2);
      }
      shape = new btBoxShape(half);
      break;
    }
    case Shape::Kind::Cylinder:
    {
      const btScalar r = btScalar(s.radius), h = btScalar(s.length / 2);
      switch (bodyAxisOf(2))
      {
        case 0:
          shape = new btCylinderShapeX(btVector3(h, r, r));
          break;
        case 1:
          shape = new btCylinderShape(btVector3(r, h, r));
          break;
        case 2:
          shape = new btCylinderShapeZ(btVector3(r, r, h));
          break;
        default:
          return nullptr;
      }
      break;
    }
    case Shape::Kind::Plane:
      return nullptr;
  }
  shape->setMargin(kCollisionMargin);
  return shape;
}

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

uint32_t seedFor(const std::string& text)
{
  uint32_t h = 2166136261u;  // FNV-1a: a seed that is the same on every run and machine
  for (unsigned char c : text)
    h = (h ^ c) * 16777619u;
  return h;
}

}  // namespace

namespace detail
{
// The plant side of gazebo_ros_control's joint handles: commands in, state out.
struct JointLayer
{
  static void apply(Robot::Internals& r, double dt);
  static void read(Robot::Internals& r, double dt);
  static void initialise(JointHandle& h, double position) { h.position_ = position; }
  static void freeze(JointHandle& h) { h.position_at_estop_ = h.position_; }
};

// Writes sensor outputs.
struct SensorUpdate
{
  static LaserScan& scan(Lidar& lidar) { return lidar.scan_; }
  static CameraFrame& frame(Camera& camera) { return camera.frame_; }
};
}  // namespace detail

// ---------------------------------------------------------------------------------------- build

void buildRobot(Robot::Internals& r, const urdf::Pose& pose, const std::map<std::string, double>& initial_joints)
{
  Log& log = r.world->log;
  const urdf::ModelInterface& model = *r.description.model;
  urdf::LinkConstSharedPtr root = model.getRoot();
  if (!root)
    throw DescriptionError("URDF of '" + r.name + "' has no root link");

  // 1. Bodies: each movable joint starts one; fixed joints fold their child into the parent body.
  std::vector<BodyPlan> plans(1);
  r.bodies.resize(1);
  r.bodies[0].link = root->name;
  std::map<std::string, std::pair<int, btTransform>> link_in_urdf_frame;  // link -> (body, link in body's URDF frame)
  std::function<void(const urdf::Link&, int, const btTransform&)> visit =
      [&](const urdf::Link& link, int body, const btTransform& in_body) {
        link_in_urdf_frame[link.name] = {body, in_body};
        for (const urdf::JointSharedPtr& joint : link.child_joints)
        {
          urdf::LinkConstSharedPtr child = model.getLink(joint->child_link_name);
          btTransform joint_frame = in_body * toBullet(joint->parent_to_joint_origin_transform);
          bool movable = joint->type == urdf::Joint::REVOLUTE || joint->type == urdf::Joint::CONTINUOUS ||
                         joint->type == urdf::Joint::PRISMATIC;
          if (!movable && joint->type != urdf::Joint::FIXED)
            log.warn("joint '" + joint->name + "' of '" + r.name + "' is floating or planar, which the plant "
                     "does not simulate; it is held fixed");
          if (!movable)
          {
            visit(*child, body, joint_frame);
            continue;
          }
          Body b;
          b.link = child->name;
          b.parent = body;
          r.bodies.push_back(std::move(b));
          BodyPlan plan;
          plan.joint = joint.get();
          plan.joint_in_parent = joint_frame;
          plans.push_back(plan);
          visit(*child, int(r.bodies.size()) - 1, btTransform::getIdentity());
        }
      };
  visit(*root, 0, btTransform::getIdentity());

  // 2. Mass properties of each body, then its principal frame.
  for (size_t bi = 0; bi < r.bodies.size(); ++bi)
  {
    Body& body = r.bodies[bi];
    double mass = 0.0;
    btVector3 weighted(0, 0, 0);
    for (const auto& kv : link_in_urdf_frame)
    {
      urdf::LinkConstSharedPtr link = model.getLink(kv.first);
      if (kv.second.first != int(bi) || !link->inertial || link->inertial->mass <= 0)
        continue;
      mass += link->inertial->mass;
      weighted += kv.second.second * vec(link->inertial->origin.position) * btScalar(link->inertial->mass);
    }
    btVector3 com = mass > 0 ? weighted / btScalar(mass) : btVector3(0, 0, 0);
    btMatrix3x3 I(0, 0, 0, 0, 0, 0, 0, 0, 0);
    for (const auto& kv : link_in_urdf_frame)
    {
      urdf::LinkConstSharedPtr link = model.getLink(kv.first);
      if (kv.second.first != int(bi) || !link->inertial || link->inertial->mass <= 0)
        continue;
      const btTransform& in_body = kv.second.second;
      btMatrix3x3 R = in_body.getBasis();
      btMatrix3x3 own = R * inertiaInLink(*link->inertial) * R.transpose();
      btVector3 d = in_body * vec(link->inertial->origin.position) - com;
      btScalar m = btScalar(link->inertial->mass);
      btMatrix3x3 shift(d.dot(d) - d.x() * d.x(), -d.x() * d.y(), -d.x() * d.z(),
                        -d.y() * d.x(), d.dot(d) - d.y() * d.y(), -d.y() * d.z(),
                        -d.z() * d.x(), -d.z() * d.y(), d.dot(d) - d.z() * d.z());
      for (int i = 0; i < 3; ++i)
        I[i] += own[i] + shift[i] * m;
    }
    if (mass < kMinimumMass && !(bi == 0 && root->name == "world"))
    {
      log.warn("link '" + body.link + "' of '" + r.name + "' (with the links fixed to it) has no mass; "
               "the plant gives it " + std::to_string(kMinimumMass) + " kg");
      mass = kMinimumMass;
    }
    btMatrix3x3 principal;
    I.diagonalize(principal, btScalar(1e-12), 32);
    body.mass = mass;
    for (int i = 0; i < 3; ++i)
      body.inertia_diagonal[i] = std::max(I[i][i], btScalar(kMinimumInertia));
    body.urdf_from_com = btTransform(principal, com);
  }

  // 3. Collision shapes, in each body's COM frame.
  std::vector<Shape> last_child(r.bodies.size());  // the last shape added to each body's compound
  for (const auto& kv : link_in_urdf_frame)
  {
    urdf::LinkConstSharedPtr link = model.getLink(kv.first);
    Body& body = r.bodies[kv.second.first];
    btTransform com_from_link = body.urdf_from_com.inverse() * kv.second.second;
    r.link_in_body[kv.first] = {kv.second.first, com_from_link};
    for (const urdf::CollisionSharedPtr& c : link->collision_array)
    {
      if (!c || !c->geometry)
        continue;
      bool ok = false;
      btTransform mesh_offset;
      Shape shape = shapeOf(*c->geometry, link->name, log, ok, mesh_offset);
      if (!ok)
        continue;
      btTransform in_com = com_from_link * toBullet(c->origin) * mesh_offset;
      if (!body.compound)
        body.compound.reset(new btCompoundShape(false, 4));
      body.child_shapes.emplace_back(bulletShape(shape));
      body.compound->addChildShape(in_com, body.child_shapes.back().get());
      body.shape = body.compound.get();
      last_child[kv.second.first] = shape;
      body.ray_shapes.push_back(RayPrimitive::fromShape(shape, fromBullet(in_com), &r));
      if (link->visual && link->visual->material)
      {
        const urdf::Color& c = link->visual->material->color;
        body.ray_shapes.back().colour = {c.r, c.g, c.b, c.a};
      }
    }
    auto surface = r.description.surfaces.find(link->name);
    if (surface != r.description.surfaces.end() && surface->second.given &&
        (link->name == body.link || !link->collision_array.empty()))
      body.mu = std::min(surface->second.mu1, surface->second.mu2);
  }

  for (size_t bi = 0; bi < r.bodies.size(); ++bi)
  {
    Body& body = r.bodies[bi];
    if (body.compound && body.compound->getNumChildShapes() == 1)
      if (btCollisionShape* aligned = alignedShape(last_child[bi], body.compound->getChildTransform(0)))
      {
        body.compound.reset();
        body.child_shapes.clear();  // the aligned shape in place of the compound's child
        body.child_shapes.emplace_back(aligned);
        body.shape = aligned;
      }
  }

  // 4. The multibody.
  const bool fixed_base = root->name == "world";
  const int n_links = int(r.bodies.size()) - 1;
  r.multibody.reset(new btMultiBody(n_links, btScalar(r.bodies[0].mass), r.bodies[0].inertia_diagonal, fixed_base, false));
  btMultiBody* mb = r.multibody.get();
  std::vector<double> axis_inertia(r.bodies.size(), 0.0);
  for (int bi = 1; bi <= n_links; ++bi)
  {
    const Body& body = r.bodies[bi];
    const Body& parent = r.bodies[body.parent];
    const urdf::Joint& joint = *plans[bi].joint;
    btTransform offset_in_parent = parent.urdf_from_com.inverse() * plans[bi].joint_in_parent;  // joint in parent COM
    btTransform offset_in_child = body.urdf_from_com.inverse();                                  // joint in child COM
    btQuaternion parent_to_this = offset_in_child.getRotation() * offset_in_parent.getRotation().inverse();
    btVector3 axis = offset_in_child.getBasis() * vec(joint.axis);
    if (axis.length2() < btScalar(1e-12))
      axis = offset_in_child.getBasis() * btVector3(1, 0, 0);  // urdfdom's default axis
    axis.normalize();
    // The body's own inertia about the joint axis: a lower bound of what the joint moves.
    btVector3 pivot_to_com = -offset_in_child.getOrigin();
    btVector3 lever = pivot_to_com - axis * axis.dot(pivot_to_com);
    axis_inertia[bi] = joint.type == urdf::Joint::PRISMATIC
                           ? body.mass
                           : axis.dot(body.inertia_diagonal * axis) + body.mass * lever.length2();
    if (joint.type == urdf::Joint::PRISMATIC)
      mb->setupPrismatic(bi - 1, btScalar(body.mass), body.inertia_diagonal, body.parent - 1, parent_to_this, axis,
                         offset_in_parent.getOrigin(), -offset_in_child.getOrigin(), true);
    else
      mb->setupRevolute(bi - 1, btScalar(body.mass), body.inertia_diagonal, body.parent - 1, parent_to_this, axis,
                        offset_in_parent.getOrigin(), -offset_in_child.getOrigin(), true);
  }
  mb->finalizeMultiDof();
  mb->setHasSelfCollision(false);
  mb->setLinearDamping(0);
  mb->setAngularDamping(0);
  mb->setMaxCoordinateVelocity(btScalar(1e4));
  mb->setCanSleep(false);
  r.spawn_pose = toBullet(pose);
  mb->setBaseWorldTransform(r.spawn_pose * r.bodies[0].urdf_from_com);
  r.world->dynamics->addMultiBody(mb);

  // 5. Movable joints: limits, URDF dynamics, the drive the joint layer uses.
  for (int bi = 1; bi <= n_links; ++bi)
  {
    const urdf::Joint& uj = *plans[bi].joint;
    MovableJoint j;
    j.name = uj.name;
    j.link = bi - 1;
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
    mb->setJointPos(j.link, btScalar(j.initial_position));

    j.axis_inertia = axis_inertia[bi];
    auto add = [&](std::unique_ptr<JointDrive>& drive) { drive.reset(new JointDrive(r.world->dynamics.get(), mb, j.link)); };
    add(j.drive);
    if (j.damping > 0 && !explicitDampingStable(j, r.world->step_s))
      add(j.damper);
    if (j.friction > 0)
      add(j.dry_friction);
    if (j.limits.has_position)
    {
      add(j.lower_limit);
      add(j.upper_limit);
    }
    r.joint_index[j.name] = r.joints.size();
    r.joints.push_back(std::move(j));
  }

  // 6. Colliders.
  for (int bi = 0; bi <= n_links; ++bi)
  {
    Body& body = r.bodies[bi];
    if (!body.shape)
      continue;
    r.colliders.emplace_back(new btMultiBodyLinkCollider(mb, bi - 1));
    btMultiBodyLinkCollider* col = r.colliders.back().get();
    col->setCollisionShape(body.shape);
    col->setFriction(btScalar(body.mu));
    col->setRestitution(0);
    col->setWorldTransform(r.bodyWorldTransform(bi));
    r.world->dynamics->addCollisionObject(col, btBroadphaseProxy::DefaultFilter, btBroadphaseProxy::AllFilter);
    if (bi == 0)
      mb->setBaseCollider(col);
    else
      mb->getLink(bi - 1).m_collider = col;
  }
  btAlignedObjectArray<btQuaternion> scratch_q;
  btAlignedObjectArray<btVector3> scratch_m;
  mb->forwardKinematics(scratch_q, scratch_m);
  mb->updateCollisionObjectWorldTransforms(scratch_q, scratch_m);

  // 7. gazebo_ros_control's joint handles.
  for (const TransmissionDescription& t : r.description.transmissions)
  {
    urdf::JointConstSharedPtr uj = model.getJoint(t.joint);
    if (!uj)
      throw DescriptionError("transmission '" + t.name + "' names joint '" + t.joint + "', which robot '" + r.name +
                             "' does not have; fix the transmission or add the joint to the URDF");
    auto index = r.joint_index.find(t.joint);
    if (index == r.joint_index.end())
      throw DescriptionError("transmission '" + t.name + "' names joint '" + t.joint +
                             "', which is fixed; only revolute, continuous and prismatic joints can be actuated");
    if (std::find(r.handle_joint.begin(), r.handle_joint.end(), index->second) != r.handle_joint.end())
    {
      log.warn("joint '" + t.joint + "' appears in more than one transmission; the first one is used");
      continue;
    }
    bool ok = false;
    JointInterface iface = parseInterface(t.hardware_interface, ok);
    if (!ok)
    {
      log.error("transmission '" + t.name + "' of joint '" + t.joint + "' uses '" + t.hardware_interface +
                "', which is not EffortJointInterface, VelocityJointInterface or PositionJointInterface; "
                "the joint gets no command handle");
      continue;
    }
    const MovableJoint& j = r.joints[index->second];
    r.handles.emplace_back(t.joint, j.type, iface, j.limits);
    r.handle_joint.push_back(index->second);
    JointHandle& h = r.handles.back();
    detail::JointLayer::initialise(h, j.initial_position);
    std::string pid_ns = joinPath(r.control_namespace, "gazebo_ros_control/pid_gains/" + t.joint);
    const Param* p = r.world->params.find(joinPath(pid_ns, "p"));
    if (iface != JointInterface::Effort && p && p->isNumber())
      h.setPid(readPidGains(r.world->params, pid_ns));
  }

  // 8. gazebo_ros_control's controller manager, updated every control period.
  if (r.description.control.present)
  {
    r.control_period_ns = r.world->step_ns;
    double period = r.description.control.control_period;
    if (period > 0 && std::llround(period * 1e9) < r.world->step_ns)
      log.warn("Desired controller update period (" + std::to_string(period) + " s) of '" + r.name +
               "' is faster than the simulation period (" + std::to_string(r.world->step_s) + " s); using the latter");
    else if (period > 0)
      r.control_period_ns = std::llround(period * 1e9);
    r.last_control_ns = r.world->time_ns;
    r.controller_manager.reset(new ControllerManager(*r.self, r.world->params, log, r.control_namespace));
    r.controller_manager->setPaused(r.world->paused);
  }

  // 9. Sensors.
  for (const SensorDescription& s : r.description.sensors)
  {
    if (s.type == "ray" || s.type == "gpu_ray")
    {
      if (s.horizontal_samples < 1 || s.vertical_samples < 1 || s.range_max <= 0)
      {
        log.warn("sensor '" + s.name + "' of '" + r.name + "' has no samples or no range; ignored");
        continue;
      }
      r.sensors.emplace_back(new Lidar(s));
      r.sensor_noise.emplace_back(seedFor(r.name + "/" + s.name));
    }
    else if (s.type == "camera" || s.type == "depth")
    {
      if (s.image_width < 1 || s.image_height < 1 || !(s.horizontal_fov > 0 && s.horizontal_fov < M_PI))
      {
        log.warn("camera '" + s.name + "' of '" + r.name + "' has no image size or a field of view outside (0, pi); ignored");
        continue;
      }
      r.sensors.emplace_back(new Camera(s));
      r.sensor_noise.emplace_back(seedFor(r.name + "/" + s.name));
    }
    else
      log.warn("sensor '" + s.name + "' of type '" + s.type + "' of '" + r.name + "' is not simulated (ray, camera, depth are)");
  }
  for (const std::string& w : r.description.warnings)
    log.warn(r.name + ": " + w);
  r.saveGoodState();
}

void destroyRobot(Robot::Internals& r)
{
  r.controller_manager.reset();
  btMultiBodyDynamicsWorld* dynamics = r.world->dynamics.get();
  for (MovableJoint& j : r.joints)
  {
    for (JointDrive* c : {j.drive.get(), j.damper.get(), j.dry_friction.get(), j.lower_limit.get(), j.upper_limit.get()})
      if (c)
        c->disable();  // leaves the world's constraints
  }
  for (auto& col : r.colliders)
    dynamics->removeCollisionObject(col.get());
  if (r.multibody)
    dynamics->removeMultiBody(r.multibody.get());
}

// ---------------------------------------------------------------------------------------- state

btTransform Robot::Internals::bodyWorldTransform(int body) const
{
  const btMultiBody* mb = multibody.get();
  if (body == 0)
    return mb->getBaseWorldTransform();
  btMultiBody* m = const_cast<btMultiBody*>(mb);
  btVector3 origin = m->localPosToWorld(body - 1, btVector3(0, 0, 0));
  btMatrix3x3 basis = m->localFrameToWorld(body - 1, btMatrix3x3::getIdentity());
  return btTransform(basis, origin);
}

btTransform Robot::Internals::linkWorldTransform(const std::string& link) const
{
  auto it = link_in_body.find(link);
  if (it == link_in_body.end())
    throw std::out_of_range("robot '" + name + "' has no link '" + link + "'");
  return bodyWorldTransform(it->second.first) * it->second.second;
}

void Robot::Internals::saveGoodState()
{
  const btMultiBody* mb = multibody.get();
  good_q.resize(joints.size());
  good_qd.resize(joints.size());
  for (size_t i = 0; i < joints.size(); ++i)
  {
    good_q[i] = mb->getJointPos(joints[i].link);
    good_qd[i] = mb->getJointVel(joints[i].link);
  }
  good_base = mb->getBaseWorldTransform();
  good_base_vel = mb->getBaseVel();
  good_base_omega = mb->getBaseOmega();
}

bool Robot::Internals::stateFinite() const
{
  const btMultiBody* mb = multibody.get();
  auto finite3 = [](const btVector3& v) { return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z()); };
  if (!finite3(mb->getBasePos()) || !finite3(mb->getBaseVel()) || !finite3(mb->getBaseOmega()))
    return false;
  btQuaternion q = mb->getWorldToBaseRot();
  if (!std::isfinite(q.x()) || !std::isfinite(q.y()) || !std::isfinite(q.z()) || !std::isfinite(q.w()))
    return false;
  for (const MovableJoint& j : joints)
    if (!std::isfinite(mb->getJointPos(j.link)) || !std::isfinite(mb->getJointVel(j.link)))
      return false;
  return true;
}

void Robot::Internals::restoreGoodState()
{
  btMultiBody* mb = multibody.get();
  mb->setBaseWorldTransform(good_base);
  mb->setBaseVel(btVector3(0, 0, 0));
  mb->setBaseOmega(btVector3(0, 0, 0));
  for (size_t i = 0; i < joints.size(); ++i)
  {
    mb->setJointPos(joints[i].link, good_q[i]);
    mb->setJointVel(joints[i].link, 0);
  }
  btAlignedObjectArray<btQuaternion> scratch_q;
  btAlignedObjectArray<btVector3> scratch_m;
  mb->forwardKinematics(scratch_q, scratch_m);
  mb->updateCollisionObjectWorldTransforms(scratch_q, scratch_m);
  for (JointHandle& h : handles)
    if (h.pid())
      h.pid()->reset();
}

void Robot::Internals::resetToSpawn()
{
  last_control_ns = world->time_ns;
  if (controller_manager)
    controller_manager->reset(world->time_ns);
  good_base = spawn_pose * bodies[0].urdf_from_com;
  for (size_t i = 0; i < joints.size(); ++i)
    good_q[i] = btScalar(joints[i].initial_position);
  restoreGoodState();
  for (auto& col : colliders)
    world->dynamics->getBroadphase()->getOverlappingPairCache()->cleanProxyFromPairs(
        col->getBroadphaseHandle(), world->dynamics->getDispatcher());
  saveGoodState();
}

// ---------------------------------------------------------------------------------------- joint layer

namespace
{
// Applies an effort law to a joint: implicitly through its drive when the law depends on the
// end-of-step state, else as a plain (clamped) joint torque.
void applyLaw(MovableJoint& j, const btMultiBody& mb, const EffortLaw& law, double dt)
{
  double effort_limit = j.limits.effort;
  if (!law.implicit())
  {
    j.drive->disable();
    j.explicit_effort = clampAbs(law.feedforward, effort_limit);
    return;
  }
  // The joint's own damping joins the law: effort - c*qd' folds into the same row.
  double q = mb.getJointPos(j.link);
  double gain = law.stiffness * dt + law.damping + j.damping;  // effort per unit of end-of-step velocity error
  double target = (law.feedforward + law.stiffness * (law.position_target - q) + law.damping * law.velocity_target) / gain;
  j.drive->drive(target, gain * dt, effort_limit * dt);
}

// The actuator's effort in the last step (the joint's own damping, folded into a soft drive, is not the actuator's).
double actuatorEffort(const MovableJoint& j, double velocity, double dt)
{
  double effort = j.explicit_effort + j.drive->appliedImpulse() / dt;
  return j.drive->soft() ? effort + j.damping * velocity : effort;
}

// One-sided rows keep a joint within [lower, upper], only while it is about to reach a limit; a
// joint already past one is pushed back by a fifth of the overlap per step.
void limitRows(MovableJoint& j, double q, double qd, double dt)
{
  constexpr double kMargin = 1e-3, kRecovery = 0.2;
  const double next = q + qd * dt, reach = kMargin + std::abs(qd) * dt;
  const double below = q - j.limits.lower, above = j.limits.upper - q;
  if (next - j.limits.lower < reach)
    j.lower_limit->bound((below >= 0 ? -below : -below * kRecovery) / dt, true);
  else
    j.lower_limit->disable();
  if (j.limits.upper - next < reach)
    j.upper_limit->bound((above >= 0 ? above : above * kRecovery) / dt, false);
  else
    j.upper_limit->disable();
}

void driveRigid(MovableJoint& j, double target_velocity, double dt)
{
  j.drive->drive(clampAbs(target_velocity, j.limits.velocity), kInf, j.limits.effort * dt);
}
}  // namespace


void Robot::Internals::applyCommands(double dt) { detail::JointLayer::apply(*this, dt); }

void Robot::Internals::updateControllers(int64_t time_ns)
{
  if (!controller_manager || time_ns - last_control_ns < control_period_ns)
    return;
  controller_manager->update(time_ns, (time_ns - last_control_ns) * 1e-9);
  last_control_ns = time_ns;
}
void Robot::Internals::readState(double dt) { detail::JointLayer::read(*this, dt); }

void detail::JointLayer::apply(Robot::Internals& r, double dt)
{
  auto& joints = r.joints;
  auto& handles = r.handles;
  auto& handle_joint = r.handle_joint;
  const bool e_stop = r.e_stop;
  const btMultiBody& mb = *r.multibody;
  for (MovableJoint& j : joints)
    j.explicit_effort = 0.0;
  for (size_t hi = 0; hi < handles.size(); ++hi)
  {
    JointHandle& h = handles[hi];
    MovableJoint& j = joints[handle_joint[hi]];
    const double q = mb.getJointPos(j.link), qd = mb.getJointVel(j.link);
    switch (h.interface())
    {
      case JointInterface::Effort:
      {
        EffortLaw law;
        if (e_stop)
          law = EffortLaw();
        else if (h.has_law_)
          law = h.law_;
        else
          law.feedforward = h.command_;
        applyLaw(j, mb, law, dt);
        break;
      }
      case JointInterface::Velocity:
      {
        double target = e_stop ? 0.0 : clampAbs(h.command_, j.limits.velocity);
        h.active_target_ = target;
        if (h.pid())
          applyLaw(j, mb, h.pid()->implicitVelocityLaw(target, qd, dt), dt);
        else
          driveRigid(j, target, dt);
        break;
      }
      case JointInterface::Position:
      {
        double target = e_stop ? h.position_at_estop_ : h.command_;
        if (j.limits.has_position)
          target = std::max(j.limits.lower, std::min(target, j.limits.upper));
        h.active_target_ = target;
        if (h.pid())
          applyLaw(j, mb, h.pid()->implicitPositionLaw(h.positionError(target, q), q, dt), dt);
        else
          driveRigid(j, (target - q) / dt, dt);
        break;
      }
    }
  }
  // The joints' passive dynamics: damping (where no drive carries it), dry friction, limits.
  for (MovableJoint& j : joints)
  {
    const double q = mb.getJointPos(j.link), qd = mb.getJointVel(j.link);
    double torque = j.explicit_effort;
    if (j.damping > 0 && !j.drive->enabled())
    {
      if (j.damper)
        j.damper->drive(0.0, j.damping * dt, kInf);
      else
        torque -= j.damping * qd;
    }
    else if (j.damper)
      j.damper->disable();
    if (j.dry_friction)
      j.dry_friction->drive(0.0, kInf, j.friction * dt);
    if (j.limits.has_position)
      limitRows(j, q, qd, dt);
    if (torque != 0.0)
      r.multibody->addJointTorque(j.link, btScalar(torque));
  }
}

void detail::JointLayer::read(Robot::Internals& r, double dt)
{
  if (!r.stateFinite())
  {
    ++r.recoveries;
    r.world->log.error("robot '" + r.name + "': the physics produced a non-finite state; restored the last good "
                       "state with zero velocity (recovery " + std::to_string(r.recoveries) + ")");
    r.restoreGoodState();
  }
  else
    r.saveGoodState();
  auto& joints = r.joints;
  auto& handles = r.handles;
  auto& handle_joint = r.handle_joint;
  const btMultiBody& mb = *r.multibody;
  for (size_t hi = 0; hi < handles.size(); ++hi)
  {
    JointHandle& h = handles[hi];
    const MovableJoint& j = joints[handle_joint[hi]];
    h.position_ = mb.getJointPos(j.link);
    h.velocity_ = mb.getJointVel(j.link);
    h.effort_ = actuatorEffort(j, h.velocity_, dt);
    if (!h.pid())
      continue;
    double error_after = h.interface() == JointInterface::Velocity ? h.active_target_ - h.velocity_
                                                                     : h.positionError(h.active_target_, h.position_);
    h.pid()->endImplicitStep(error_after, h.effort_, dt);
  }
}

double JointHandle::positionError(double target, double position) const
{
  switch (type_)
  {
    case JointType::Revolute:
      return limits_.has_position ? revoluteError(position, target, limits_.lower, limits_.upper)
                                  : wrapToPi(target - position);
    case JointType::Continuous:
      return wrapToPi(target - position);
    case JointType::Prismatic:
      break;
  }
  return target - position;
}

// ---------------------------------------------------------------------------------------- sensors

void Robot::Internals::appendRayPrimitives(std::vector<RayPrimitive>& out) const
{
  for (size_t bi = 0; bi < bodies.size(); ++bi)
  {
    if (bodies[bi].ray_shapes.empty())
      continue;
    Frame body = Frame::fromPose(fromBullet(bodyWorldTransform(int(bi))));
    for (const RayPrimitive& p : bodies[bi].ray_shapes)
    {
      out.push_back(p);
      out.back().frame = body * p.frame;
    }
  }
}

namespace
{
// One camera frame by ray casting through every pixel centre of a pinhole camera.
void renderCamera(const Camera& camera, CameraFrame& out, const Frame& pose, const RayCaster& caster,
                  const urdf::Vector3& light_direction, std::mt19937& rng, int64_t time_ns)
{
  const SensorDescription& d = camera.description();
  const int w = d.image_width, h = d.image_height;
  const bool depth = camera.depthSensor();
  camera.intrinsics(out.fx, out.fy, out.cx, out.cy);
  out.stamp_ns = time_ns;
  out.frame_id = camera.frameId();
  out.width = w;
  out.height = h;
  out.rgb.resize(size_t(w) * h * 3);
  out.depth.assign(depth ? size_t(w) * h : 0, std::numeric_limits<float>::quiet_NaN());
  out.points.assign(depth ? size_t(w) * h * 3 : 0, std::numeric_limits<float>::quiet_NaN());
  const double near = d.clip_near > 0 ? d.clip_near : 0.0, far = d.clip_far > 0 ? d.clip_far : 100.0;
  double light[3] = {-light_direction.x, -light_direction.y, -light_direction.z};  // towards the light
  const double light_norm = std::sqrt(light[0] * light[0] + light[1] * light[1] + light[2] * light[2]);
  for (double& l : light)
    l = light_norm > 0 ? l / light_norm : 0.0;
  static const float kSky[3] = {0.70f, 0.80f, 0.95f};
  constexpr double kAmbient = 0.35;
  const bool noisy = d.noise.gaussian && d.noise.stddev > 0;
  std::normal_distribution<double> noise(d.noise.mean, noisy ? d.noise.stddev : 1.0);
  for (int v = 0; v < h; ++v)
    for (int u = 0; u < w; ++u)
    {
      // optical (x right, y down, z forward) -> camera link (x forward, y left, z up)
      const double xo = (u - out.cx) / out.fx, yo = (v - out.cy) / out.fy;
      const double length = std::sqrt(1.0 + xo * xo + yo * yo);
      const double in_link[3] = {1.0 / length, -xo / length, -yo / length};
      double dir[3];
      pose.rotate(in_link, dir);
      const RayHit hit = caster.castHit(pose.t, dir, far * length);
      const double z = hit.distance / length;  // depth along the optical axis
      const size_t pixel = size_t(v) * w + u;
      float colour[3] = {kSky[0], kSky[1], kSky[2]};
      if (hit.primitive && z >= near)
      {
        double point[3] = {pose.t[0] + dir[0] * hit.distance, pose.t[1] + dir[1] * hit.distance,
                           pose.t[2] + dir[2] * hit.distance};
        double normal[3];
        hit.primitive->normalAt(point, normal);
        const double diffuse = std::max(0.0, normal[0] * light[0] + normal[1] * light[1] + normal[2] * light[2]);
        const double shade = kAmbient + (1.0 - kAmbient) * diffuse;
        const Rgba& c = hit.primitive->colour;
        colour[0] = float(c.r * shade);
        colour[1] = float(c.g * shade);
        colour[2] = float(c.b * shade);
        if (depth)
        {
          out.depth[pixel] = float(z);
          out.points[3 * pixel] = float(xo * z);
          out.points[3 * pixel + 1] = float(yo * z);
          out.points[3 * pixel + 2] = float(z);
        }
      }
      for (int k = 0; k < 3; ++k)
      {
        double value = colour[k] + (noisy ? noise(rng) : 0.0);
        out.rgb[3 * pixel + k] = uint8_t(std::lround(std::max(0.0, std::min(1.0, value)) * 255.0));
      }
    }
}
}  // namespace

void Robot::Internals::updateSensors(int64_t time_ns)
{
  std::vector<RayPrimitive> scene;
  for (size_t si = 0; si < sensors.size(); ++si)
  {
    Sensor& sensor = *sensors[si];
    if (!sensor.active() || !sensor.due(time_ns))
      continue;
    if (scene.empty())
    {
      scene = world->static_ray_shapes;
      for (const auto& other : world->robots)
        other->in_->appendRayPrimitives(scene);
    }
    const SensorDescription& d = sensor.description();
    Frame frame = Frame::fromPose(fromBullet(linkWorldTransform(d.link))) * Frame::fromPose(d.pose);
    if (auto* camera = dynamic_cast<Camera*>(&sensor))
    {
      // Cameras see everything, their own robot too (as Gazebo's do).
      renderCamera(*camera, detail::SensorUpdate::frame(*camera), frame, RayCaster(scene, nullptr),
                   world->description.light_direction, sensor_noise[si], time_ns);
      continue;
    }
    auto* lidar = dynamic_cast<Lidar*>(&sensor);
    if (!lidar)
      continue;
    RayCaster caster(scene, this);
    const int n = d.horizontal_samples;
    const double da = n > 1 ? (d.horizontal_max_angle - d.horizontal_min_angle) / (n - 1) : 0.0;
    std::vector<double> elevations(d.vertical_samples, d.vertical_min_angle);
    for (int v = 1; v < d.vertical_samples; ++v)
      elevations[v] = d.vertical_min_angle + v * (d.vertical_max_angle - d.vertical_min_angle) / (d.vertical_samples - 1);
    std::vector<double> distances;
    caster.castFan(frame, d.horizontal_min_angle, da, n, elevations, d.range_max, distances);

    LaserScan& scan = detail::SensorUpdate::scan(*lidar);
    scan.stamp_ns = time_ns;
    scan.frame_id = lidar->frameId();
    scan.angle_min = float(d.horizontal_min_angle);
    scan.angle_max = float(d.horizontal_max_angle);
    scan.angle_increment = float(da);
    scan.time_increment = 0.0f;
    scan.scan_time = d.update_rate > 0 ? float(1.0 / d.update_rate) : 0.0f;
    scan.range_min = float(d.range_min);
    scan.range_max = float(d.range_max);
    scan.vertical_samples = d.vertical_samples;
    scan.ranges.resize(distances.size());
    std::normal_distribution<double> noise(d.noise.mean, d.noise.stddev > 0 ? d.noise.stddev : 1.0);
    const bool noisy = d.noise.gaussian && d.noise.stddev > 0;
    for (size_t i = 0; i < distances.size(); ++i)
    {
      double r = distances[i];
      if (std::isinf(r))
        scan.ranges[i] = std::numeric_limits<float>::infinity();
      else if (r < d.range_min)
        scan.ranges[i] = -std::numeric_limits<float>::infinity();
      else
      {
        if (noisy)
          r += noise(sensor_noise[si]);
        scan.ranges[i] = float(std::max(d.range_min, std::min(r, d.range_max)));
      }
    }
  }
}

// ---------------------------------------------------------------------------------------- Robot

Robot::Robot(std::unique_ptr<Internals> internals) : in_(std::move(internals)) { in_->self = this; }

ControllerManager* Robot::controllerManager() { return in_->controller_manager.get(); }
double Robot::controlPeriod() const { return in_->control_period_ns * 1e-9; }
Robot::~Robot() { destroyRobot(*in_); }

const std::string& Robot::name() const { return in_->name; }
const std::string& Robot::controlNamespace() const { return in_->control_namespace; }
const RobotDescription& Robot::description() const { return in_->description; }
std::vector<JointHandle>& Robot::handles() { return in_->handles; }
long Robot::recoveries() const { return in_->recoveries; }

JointHandle* Robot::handle(const std::string& joint)
{
  for (JointHandle& h : in_->handles)
    if (h.name() == joint)
      return &h;
  return nullptr;
}

std::vector<std::string> Robot::jointNames() const
{
  std::vector<std::string> names;
  for (const MovableJoint& j : in_->joints)
    names.push_back(j.name);
  return names;
}

bool Robot::jointState(const std::string& joint, double& position, double& velocity, double& effort) const
{
  auto it = in_->joint_index.find(joint);
  if (it == in_->joint_index.end())
    return false;
  const MovableJoint& j = in_->joints[it->second];
  position = in_->multibody->getJointPos(j.link);
  velocity = in_->multibody->getJointVel(j.link);
  effort = actuatorEffort(j, velocity, in_->world->step_s);
  return true;
}

urdf::Pose Robot::basePose() const
{
  return fromBullet(in_->multibody->getBaseWorldTransform() * in_->bodies[0].urdf_from_com.inverse());
}

Twist Robot::baseTwist() const
{
  const btMultiBody& mb = *in_->multibody;
  btVector3 omega = mb.getBaseOmega();
  btVector3 root = (mb.getBaseWorldTransform() * in_->bodies[0].urdf_from_com.inverse()).getOrigin();
  btVector3 v = mb.getBaseVel() + omega.cross(root - mb.getBasePos());
  Twist t;
  for (int i = 0; i < 3; ++i)
  {
    t.linear[i] = v[i];
    t.angular[i] = omega[i];
  }
  return t;
}

urdf::Pose Robot::linkPose(const std::string& link) const { return fromBullet(in_->linkWorldTransform(link)); }

void Robot::setEStop(bool on)
{
  if (on && !in_->e_stop)
    for (JointHandle& h : in_->handles)
      detail::JointLayer::freeze(h);
  in_->e_stop = on;
}

bool Robot::eStop() const { return in_->e_stop; }

std::vector<Sensor*> Robot::sensors()
{
  std::vector<Sensor*> out;
  for (auto& s : in_->sensors)
    out.push_back(s.get());
  return out;
}

namespace
{
template <class Kind>
std::vector<Kind*> sensorsOfKind(const std::vector<std::unique_ptr<Sensor>>& sensors)
{
  std::vector<Kind*> out;
  for (auto& s : sensors)
    if (auto* kind = dynamic_cast<Kind*>(s.get()))
      out.push_back(kind);
  return out;
}
}  // namespace

std::vector<Camera*> Robot::cameras() { return sensorsOfKind<Camera>(in_->sensors); }
std::vector<Lidar*> Robot::lidars() { return sensorsOfKind<Lidar>(in_->sensors); }

Sensor* Robot::sensor(const std::string& name)
{
  for (auto& s : in_->sensors)
    if (s->name() == name)
      return s.get();
  return nullptr;
}

}  // namespace bullet_plant
