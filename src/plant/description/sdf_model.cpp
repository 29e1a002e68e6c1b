#include "bullet_plant/sdf_model.h"

#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <set>
#include <sstream>

#include <tinyxml2.h>

#include "bullet_plant/log.h"
#include "description/gazebo_elements.h"
#include "description/sdf_elements.h"
#include "description/xml_util.h"

namespace bullet_plant
{
namespace
{
using sdf::Source;

// SDF's "no limit" (sdformat's defaults for <limit><lower>/<upper>): beyond it a joint is free.
constexpr double kSdfUnlimited = 1e16;
// Names SDF reserves for the model's own frame and for the world.
const std::string kModelFrame = "__model__";
const std::string kWorld = "world";

std::string attribute(const sdf::ElementPtr& e, const char* name, const std::string& fallback = "")
{
  return sdf::attribute(e, name, fallback);
}

// A refusal from a shared reader (a number that is not one, "<mass>: 'nan' is not a finite number")
// with the model element it is in said first.
DescriptionError inContext(const std::string& where, const DescriptionError& e)
{
  const std::string what = e.what();
  return what.rfind("model '", 0) == 0 ? e : DescriptionError(where + ": " + what);
}

bool isIdentity(const urdf::Pose& p)
{
  return std::abs(p.position.x) < 1e-12 && std::abs(p.position.y) < 1e-12 && std::abs(p.position.z) < 1e-12 &&
         std::abs(std::abs(p.rotation.w) - 1.0) < 1e-12;
}

// The frames one (possibly nested) model's <pose relative_to> may name, each with its pose and the
// frame that pose is relative to (SDF 1.7; 1.5 and 1.6 wrote `frame`, which sdformat's 1.6 to 1.7
// converter renames relative_to): resolved to the model frame. A nested model's frames are named
// through it ("inner::link"), as a joint's <child> in the outer model names them. Where a link, a
// nested model, a <frame> and a joint share a name (1.6 allows a joint named as its link), the name
// is the link's (then the model's, the frame's).
class FrameGraph
{
public:
  enum Rank { kLink, kModel, kFrame, kJoint };
  FrameGraph(std::string model) : model_(std::move(model)) {}
  void add(const std::string& name, Rank rank, const std::string& relative_to, const urdf::Pose& pose)
  {
    auto it = entries_.find(name);
    if (it == entries_.end() || rank < it->second.rank)
      entries_[name] = {rank, relative_to, pose};
  }
  void nest(const std::string& name, std::shared_ptr<const FrameGraph> graph) { nested_[name] = std::move(graph); }
  bool has(const std::string& name) const
  {
    if (name.empty() || name == kModelFrame || entries_.count(name))
      return true;
    const size_t scope = name.find("::");
    auto nested = scope == std::string::npos ? nested_.end() : nested_.find(name.substr(0, scope));
    return nested != nested_.end() && entries_.count(nested->first) && nested->second->has(name.substr(scope + 2));
  }
  // The frame's pose in the model frame; throws DescriptionError for a frame the model lacks or a cycle.
  urdf::Pose resolve(const std::string& name, int depth = 0) const
  {
    if (name.empty() || name == kModelFrame)
      return urdf::Pose();
    if (depth > int(entries_.size()) + 1)
      throw DescriptionError("model '" + model_ + "': the poses relative to '" + name + "' form a cycle; give one of "
                             "them relative to another frame");
    auto it = entries_.find(name);
    if (it != entries_.end())
      return resolve(it->second.relative_to, it->second.pose, depth + 1);
    const size_t scope = name.find("::");
    auto nested = scope == std::string::npos ? nested_.end() : nested_.find(name.substr(0, scope));
    if (nested == nested_.end())
      throw DescriptionError("model '" + model_ + "': <pose relative_to=\"" + name + "\"> names no frame, link, "
                             "joint or model of the model");
    return compose(resolve(nested->first, depth + 1), nested->second->resolve(name.substr(scope + 2)));
  }
  // A pose relative to the frame `relative_to` ("": the model frame), in the model frame.
  urdf::Pose resolve(const std::string& relative_to, const urdf::Pose& pose, int depth = 0) const
  {
    return compose(resolve(relative_to, depth), pose);
  }

private:
  struct Entry
  {
    Rank rank;
    std::string relative_to;
    urdf::Pose pose;
  };
  std::string model_;
  std::map<std::string, Entry> entries_;
  std::map<std::string, std::shared_ptr<const FrameGraph>> nested_;
};

struct LinkPart
{
  std::string name;  // scoped: "nested::link"
  urdf::Pose pose;   // in the top model's frame
  sdf::ElementPtr element;
  Source source;  // the file it was read from (an included model's)
  bool model_self_collide;  // the <self_collide> of the model declaring it: the link's default
};

struct JointPart
{
  std::string name, type, parent, child;  // scoped names; parent may be "world"
  urdf::Pose pose;                        // the joint frame in the top model's frame
  sdf::ElementPtr element;
  urdf::Pose model_frame;  // the frame of the model that declares it, in the top model's frame
  // 1.7's <axis><xyz expressed_in> and <axis2><xyz expressed_in> naming a frame of the declaring model
  // (not __model__): that frame, in the top model's frame.
  std::map<std::string, urdf::Pose> axis_frames;
};

struct ModelParts
{
  std::string name;
  std::vector<LinkPart> links;
  std::vector<JointPart> joints;
  std::vector<sdf::ElementPtr> plugins;
};

// One model's links, joints, plugins and nested models into `parts`, `in_top` being its frame in the
// top model's; its frames, for the model holding it.
std::shared_ptr<const FrameGraph> collectModel(const sdf::ElementPtr& model, const std::string& scope,
                                               const urdf::Pose& in_top, const Source& source, int depth,
                                               ModelParts& parts, RobotDescription& out)
{
  if (depth > sdf::kMaxModelDepth * 4)
    throw DescriptionError("model '" + parts.name + "': models nested " + std::to_string(depth) + " deep at '" + scope +
                           "'; the plant reads at most " + std::to_string(sdf::kMaxModelDepth * 4));
  const bool self_collide = sdf::flag(model, "self_collide", false);
  if (!sdf::flag(model, "allow_auto_disable", true))
    out.allow_auto_disable = false;
  auto graph = std::make_shared<FrameGraph>(parts.name);
  FrameGraph& frames = *graph;
  // Every named frame first: a pose may be relative to one declared after it.
  for (sdf::ElementPtr e = model->GetFirstElement(); e; e = e->GetNextElement())
  {
    const std::string tag = e->GetName(), name = attribute(e, "name");
    std::string relative_to;
    const urdf::Pose pose = sdf::pose(e, relative_to);
    if (tag == "link")
      frames.add(name, FrameGraph::kLink, relative_to, pose);
    else if (tag == "model")
      frames.add(name, FrameGraph::kModel, relative_to, pose);
    else if (tag == "frame")
    {
      const std::string attached_to = attribute(e, "attached_to");
      frames.add(name, FrameGraph::kFrame, relative_to.empty() ? attached_to : relative_to, pose);
    }
    else if (tag == "joint")
      frames.add(name, FrameGraph::kJoint, relative_to.empty() ? sdf::childText(e, "child", "") : relative_to, pose);
  }
  // Nested models next (an <include>d one is one, sdformat having read it in): the joints below may
  // name their frames ("inner::link").
  for (sdf::ElementPtr e = model->GetFirstElement(); e; e = e->GetNextElement())
  {
    const std::string tag = e->GetName(), name = attribute(e, "name");
    if (tag == "model")
      frames.nest(name, collectModel(e, scope + name + "::", compose(in_top, frames.resolve(name)),
                                     sdf::sourceOf(e, source), depth + 1, parts, out));
  }
  for (sdf::ElementPtr e = model->GetFirstElement(); e; e = e->GetNextElement())
  {
    const std::string tag = e->GetName(), name = attribute(e, "name");
    if (tag == "link")
    {
      for (const LinkPart& link : parts.links)
        if (link.name == scope + name)
          throw DescriptionError("model '" + parts.name + "': link '" + scope + name + "' is given twice; link names "
                                 "must be unique in a model");
      std::string relative_to;
      const urdf::Pose pose = sdf::pose(e, relative_to);
      parts.links.push_back({scope + name, compose(in_top, frames.resolve(relative_to, pose)), e, source, self_collide});
    }
    else if (tag == "joint")
    {
      JointPart joint;
      joint.name = scope + name;
      joint.type = attribute(e, "type");
      joint.element = e;
      joint.model_frame = in_top;
      const std::string parent = sdf::childText(e, "parent", ""), child = sdf::childText(e, "child", "");
      joint.parent = parent == kWorld ? kWorld : scope + parent;
      joint.child = scope + child;
      if (!frames.has(child) || child == kWorld || child.empty())
        throw DescriptionError("model '" + parts.name + "' joint '" + joint.name + "': <child> '" + child +
                               "' is no link of the model; name one of its links");
      std::string relative_to;
      const urdf::Pose pose = sdf::pose(e, relative_to);
      joint.pose = compose(in_top, frames.resolve(relative_to.empty() ? child : relative_to, pose));
      for (const char* axis_tag : {"axis", "axis2"})
      {
        const sdf::ElementPtr axis = sdf::child(e, axis_tag);
        const std::string expressed_in = attribute(sdf::child(axis, "xyz"), "expressed_in");
        if (expressed_in.empty() || expressed_in == kModelFrame)
          continue;
        if (!frames.has(expressed_in))
          throw DescriptionError("model '" + parts.name + "' joint '" + joint.name + "': <" + axis_tag +
                                 "><xyz expressed_in=\"" + expressed_in + "\"> names no frame, link, joint or "
                                 "model of the model; name one, or __model__ (or leave it out: the joint frame)");
        joint.axis_frames[axis_tag] = compose(in_top, frames.resolve(expressed_in));
      }
      parts.joints.push_back(joint);
    }
    else if (tag == "plugin")
      parts.plugins.push_back(e);
    else if (tag == "enable_wind" && sdf::isTrue(sdf::text(e)))
      out.warnings.push_back("model '" + parts.name + "': <enable_wind> is ignored (the plant has no wind)");
  }
  return graph;
}

// <inertial>: SDF's defaults (mass 1 kg, unit moments) where absent; the mass and inertia checked as
// a physics engine needs them.
urdf::InertialSharedPtr readInertial(const sdf::ElementPtr& link, const std::string& model, const std::string& name)
{
  auto inertial = std::make_shared<urdf::Inertial>();
  inertial->mass = 1.0;
  inertial->ixx = inertial->iyy = inertial->izz = 1.0;
  inertial->ixy = inertial->ixz = inertial->iyz = 0.0;
  const sdf::ElementPtr e = sdf::child(link, "inertial");
  const std::string where = "model '" + model + "' link '" + name + "': <inertial>";
  if (e)
  {
    inertial->mass = sdf::childDouble(e, "mass", 1.0);
    inertial->origin = sdf::pose(e);
    inertial->ixx = sdf::childDouble(e, "inertia/ixx", 1.0);
    inertial->iyy = sdf::childDouble(e, "inertia/iyy", 1.0);
    inertial->izz = sdf::childDouble(e, "inertia/izz", 1.0);
    inertial->ixy = sdf::childDouble(e, "inertia/ixy", 0.0);
    inertial->ixz = sdf::childDouble(e, "inertia/ixz", 0.0);
    inertial->iyz = sdf::childDouble(e, "inertia/iyz", 0.0);
  }
  if (!(inertial->mass > 0) || inertial->mass > kMaxLinkMass)
    throw DescriptionError(where + "<mass> " + formatNumber(inertial->mass) + " is not a mass the plant can simulate: "
                           "give a positive mass of at most " + formatNumber(kMaxLinkMass) +
                           " kg, or make the model <static>");
  // Positive definite: the leading minors of the 3x3 inertia are positive (Sylvester).
  const double a = inertial->ixx, b = inertial->iyy, c = inertial->izz;
  const double d = inertial->ixy, f = inertial->ixz, g = inertial->iyz;
  const double minor2 = a * b - d * d;
  const double det = a * (b * c - g * g) - d * (d * c - g * f) + f * (d * g - b * f);
  const double largest = kMaxLinkMass * kMaxLength * kMaxLength;
  // The principal moments (the eigenvalues, by the trigonometric method for symmetric 3x3 matrices)
  // obey the triangle inequality, as sdformat's MassMatrix3::IsValid asks: the largest is at most the
  // sum of the other two (within 1e-6 of the largest).
  const double mean = (a + b + c) / 3.0;
  const double off = d * d + f * f + g * g;
  const double spread = std::sqrt(((a - mean) * (a - mean) + (b - mean) * (b - mean) + (c - mean) * (c - mean) +
                                   2.0 * off) / 6.0);
  double largest_moment = mean;
  if (spread > 0)
  {
    const double p = spread;
    const double b11 = (a - mean) / p, b22 = (b - mean) / p, b33 = (c - mean) / p;
    const double b12 = d / p, b13 = f / p, b23 = g / p;
    const double half_det = (b11 * (b22 * b33 - b23 * b23) - b12 * (b12 * b33 - b23 * b13) +
                             b13 * (b12 * b23 - b22 * b13)) / 2.0;
    const double phi = std::acos(std::max(-1.0, std::min(1.0, half_det))) / 3.0;
    largest_moment = mean + 2.0 * p * std::cos(phi);
  }
  const bool triangle = largest_moment <= (3.0 * mean - largest_moment) + 1e-6 * largest_moment;
  if (!(a > 0 && minor2 > 0 && det > 0) || !triangle || std::max({a, b, c}) > largest)
  {
    std::ostringstream text;
    text << where << "<inertia> ixx " << a << " iyy " << b << " izz " << c << " ixy " << d << " ixz " << f << " iyz "
         << g << " is not " << (a > 0 && minor2 > 0 && det > 0 ? "a body's inertia" : "positive definite") << " (or beyond " << largest
         << " kg m^2): every principal moment must be positive and each at most the sum of the other two";
    throw DescriptionError(text.str());
  }
  return inertial;
}

urdf::GeometrySharedPtr toUrdfGeometry(const Shape& shape)
{
  switch (shape.kind)
  {
    case Shape::Kind::Box:
    {
      auto box = std::make_shared<urdf::Box>();
      box->dim = urdf::Vector3(shape.box_size[0], shape.box_size[1], shape.box_size[2]);
      return box;
    }
    case Shape::Kind::Cylinder:
    {
      auto cylinder = std::make_shared<urdf::Cylinder>();
      cylinder->radius = shape.radius;
      cylinder->length = shape.length;
      return cylinder;
    }
    case Shape::Kind::Sphere:
    {
      auto sphere = std::make_shared<urdf::Sphere>();
      sphere->radius = shape.radius;
      return sphere;
    }
    case Shape::Kind::Mesh:
    {
      auto mesh = std::make_shared<urdf::Mesh>();
      mesh->filename = shape.mesh_file;
      mesh->scale = shape.scale;
      return mesh;
    }
    case Shape::Kind::Capsule:
    case Shape::Kind::Ellipsoid:
    {
      auto carried = std::make_shared<ShapeGeometry>();
      carried->shape = shape;
      return carried;
    }
    case Shape::Kind::Plane:
      break;
  }
  return nullptr;
}

// A link's collisions, visuals, surface and sensors, in its own frame.
urdf::LinkSharedPtr readLink(const LinkPart& part, const std::string& model, RobotDescription& out)
{
  auto link = std::make_shared<urdf::Link>();
  link->name = part.name;
  link->inertial = readInertial(part.element, model, part.name);
  const std::string in_link = "model '" + model + "' link '" + part.name + "'";
  for (sdf::ElementPtr c = sdf::child(part.element, "collision"); c; c = c->GetNextElement("collision"))
  {
    const std::string name = attribute(c, "name", "collision");
    const std::string where = in_link + " collision '" + name + "'";
    const sdf::ElementPtr geometry = sdf::child(c, "geometry");
    Shape shape;
    if (!geometry)
    {
      out.warnings.push_back(where + " has no <geometry>; left out");
      continue;
    }
    if (!sdf::readGeometry(geometry, where, part.source, shape, out.warnings))
      continue;
    if (shape.kind == Shape::Kind::Plane)
    {
      out.warnings.push_back(where + ": a <plane> moves only in a <static> model; left out");
      continue;
    }
    auto collision = std::make_shared<urdf::Collision>();
    collision->name = name;
    collision->origin = sdf::pose(c);
    collision->geometry = toUrdfGeometry(shape);
    link->collision_array.push_back(collision);
    SurfaceDescription surface = sdf::readSurface(c, where);
    if (surface.given && !out.surfaces[part.name].given)
      out.surfaces[part.name] = surface;  // the link's bounce: its first collision's
    out.collision_surfaces[part.name].push_back(surface);
  }
  if (!link->collision_array.empty())
    link->collision = link->collision_array.front();
  for (sdf::ElementPtr v = sdf::child(part.element, "visual"); v; v = v->GetNextElement("visual"))
  {
    const std::string name = attribute(v, "name", "visual");
    const sdf::ElementPtr geometry = sdf::child(v, "geometry");
    Shape shape;
    if (!geometry || !sdf::readGeometry(geometry, in_link + " visual '" + name + "'", part.source, shape, out.warnings,
                                        "cameras do not see it") ||
        shape.kind == Shape::Kind::Plane)
      continue;
    auto visual = std::make_shared<urdf::Visual>();
    visual->name = name;
    visual->origin = sdf::pose(v);
    visual->geometry = toUrdfGeometry(shape);
    const VisualMaterial material = sdf::readMaterial(v, in_link + " visual '" + name + "'", out.warnings);
    out.visual_materials[part.name].push_back(material);
    // the colour a URDF consumer (rviz's markers) shows: the one cameras see where no texture is
    bool textured = false;
    const Rgba colour = material.resolve(Material::gazeboWhite(), textured).diffuse;
    visual->material = std::make_shared<urdf::Material>();
    visual->material->color.init(std::to_string(colour.r) + " " + std::to_string(colour.g) + " " +
                                 std::to_string(colour.b) + " " + std::to_string(colour.a));
    link->visual_array.push_back(visual);
  }
  if (!link->visual_array.empty())
    link->visual = link->visual_array.front();
  LinkPhysics physics;
  physics.gravity = sdf::flag(part.element, "gravity", true);
  physics.kinematic = sdf::flag(part.element, "kinematic", false);
  physics.self_collide = sdf::flag(part.element, "self_collide", part.model_self_collide);
  out.link_physics[part.name] = physics;
  readSensors(part.element, part.name, out);
  return link;
}

// The joint's axis (`axis_tag`: axis or axis2) in the joint frame: in the frame <xyz expressed_in>
// names (default: the joint frame). sdformat's converters bring older files there: 1.4 gave the axis
// in the model frame, 1.5 and 1.6 where <use_parent_model_frame> said, which becomes
// expressed_in="__model__".
urdf::Vector3 jointAxis(const JointPart& joint, const std::string& model, const char* axis_tag = "axis")
{
  const sdf::ElementPtr axis = sdf::child(joint.element, axis_tag);
  const sdf::ElementPtr xyz_element = sdf::child(axis, "xyz");
  const std::string text = xyz_element ? sdf::text(xyz_element) : "0 0 1";
  const std::string where = "model '" + model + "' joint '" + joint.name + "': <" + axis_tag + "><xyz>";
  const std::vector<double> xyz = xml::numbers(text, 3, where);
  const double norm = std::sqrt(xyz[0] * xyz[0] + xyz[1] * xyz[1] + xyz[2] * xyz[2]);
  if (!(norm > 1e-9) || !std::isfinite(norm))
    throw DescriptionError(where + " " + xml::trimmed(text) + " is not a direction: give a finite vector that is "
                           "not zero");
  urdf::Vector3 v(xyz[0] / norm, xyz[1] / norm, xyz[2] / norm);
  const std::string expressed_in = attribute(xyz_element, "expressed_in");
  const bool in_model = expressed_in == kModelFrame;
  const auto named = joint.axis_frames.find(axis_tag);
  if (in_model || named != joint.axis_frames.end())
  {
    const urdf::Pose& frame = in_model ? joint.model_frame : named->second;
    v = rotate(inverse(compose(inverse(frame), joint.pose)).rotation, v);  // that frame -> joint frame
  }
  return v;
}

std::shared_ptr<urdf::Joint> fixedJoint(const std::string& name, const std::string& parent, const std::string& child,
                                        const urdf::Pose& origin)
{
  auto j = std::make_shared<urdf::Joint>();
  j->name = name;
  j->type = urdf::Joint::FIXED;
  j->parent_link_name = parent;
  j->child_link_name = child;
  j->parent_to_joint_origin_transform = origin;
  return j;
}

std::shared_ptr<urdf::Link> frameLink(const std::string& name, RobotDescription& out)
{
  auto link = std::make_shared<urdf::Link>();
  link->name = name;
  out.frame_links.insert(name);
  return link;
}

// One axis (`axis_tag`: axis or axis2) of a movable SDF joint on the URDF joint `j`: its direction,
// <limit> and <dynamics>; `type` revolute (continuous without limits) or prismatic.
void readAxis(urdf::Joint& j, const JointPart& part, const char* axis_tag, const std::string& type,
              const std::string& model, RobotDescription& out)
{
  j.axis = jointAxis(part, model, axis_tag);
  // <physics><provide_feedback>: the joint's wrench measured from the start (Joint::GetForceTorque).
  if (sdf::isTrue(sdf::childText(part.element, "physics/provide_feedback", "false")))
    out.joint_feedback.insert(part.name);
  const sdf::ElementPtr axis = sdf::child(part.element, axis_tag);
  const std::string where = "model '" + model + "' joint '" + part.name + "' <" + axis_tag + ">";
  auto limits = std::make_shared<urdf::JointLimits>();
  limits->lower = sdf::childDouble(axis, "limit/lower", -kSdfUnlimited);
  limits->upper = sdf::childDouble(axis, "limit/upper", kSdfUnlimited);
  limits->effort = sdf::childDouble(axis, "limit/effort", -1.0);
  limits->velocity = sdf::childDouble(axis, "limit/velocity", -1.0);
  if (std::isnan(limits->lower) || std::isnan(limits->upper))
    throw DescriptionError(where + "<limit>: lower and upper must be numbers");
  // SDF: a negative effort or velocity limit is none.
  if (!(limits->effort >= 0))
    limits->effort = std::numeric_limits<double>::infinity();
  if (!(limits->velocity >= 0))
    limits->velocity = -1.0;
  const bool unlimited = limits->lower <= -kSdfUnlimited && limits->upper >= kSdfUnlimited;
  if (unlimited)
    limits->lower = limits->upper = 0.0;  // no position limits (the builder's lower < upper test)
  else if (!(limits->lower <= limits->upper) || !std::isfinite(limits->lower) || !std::isfinite(limits->upper) ||
           std::max(std::abs(limits->lower), std::abs(limits->upper)) > kSdfUnlimited)
    throw DescriptionError(where + "<limit>: lower " + formatNumber(limits->lower) + " and upper " +
                           formatNumber(limits->upper) + " are no range: give lower <= upper, both finite (or leave "
                           "both out for a joint without limits)");
  j.limits = limits;
  j.type = type == "prismatic" ? urdf::Joint::PRISMATIC
           : type == "continuous" || unlimited ? urdf::Joint::CONTINUOUS
                                               : urdf::Joint::REVOLUTE;
  if (const sdf::ElementPtr dynamics = sdf::child(axis, "dynamics"))
  {
    j.dynamics = std::make_shared<urdf::JointDynamics>();
    j.dynamics->damping = sdf::childDouble(dynamics, "damping", 0.0);
    j.dynamics->friction = sdf::childDouble(dynamics, "friction", 0.0);
    if (!(j.dynamics->damping >= 0 && std::isfinite(j.dynamics->damping)) ||
        !(j.dynamics->friction >= 0 && std::isfinite(j.dynamics->friction)))
      throw DescriptionError(where + "<dynamics>: damping " + formatNumber(j.dynamics->damping) + " and friction " +
                             formatNumber(j.dynamics->friction) + " must be finite numbers >= 0");
    JointSpring spring;
    spring.stiffness = sdf::childDouble(dynamics, "spring_stiffness", 0.0);
    spring.reference = sdf::childDouble(dynamics, "spring_reference", 0.0);
    if (!(spring.stiffness >= 0) || !std::isfinite(spring.stiffness) || !std::isfinite(spring.reference))
      throw DescriptionError(where + "<dynamics>: spring_stiffness " + formatNumber(spring.stiffness) +
                             " must be a finite number >= 0, spring_reference finite");
    if (spring.stiffness > 0)
    {
      out.joint_springs[j.name] = spring;
      // Kept for the physics, which has no joint springs yet (nothing reads joint_springs).
      out.warnings.push_back(where + "<dynamics><spring_stiffness> " + formatNumber(spring.stiffness) +
                             ": joint springs are not simulated yet; the joint moves without it");
    }
  }
}

// The mass the frame between a universal (or revolute2) joint's two axes gets, and the one between a
// screw's turn and its slide: SDF's frame has none, and the physics needs one (the robot builder's
// least mass without a warning).
constexpr double kAxisFrameMass = 1e-3;  // kg
constexpr double kAxisFrameInertia = 1e-6;  // kg m^2

// One SDF joint as two URDF joints in a row (a universal's two axes, a screw's turn and slide):
// `first` now ends at a new frame link `frame`, from which a second joint `second` (a revolute at the
// joint's origin, to be given its axis) goes on to first's child. Returns the second joint.
urdf::Joint& splitJoint(urdf::ModelInterface& tree, urdf::Joint& first, const std::string& frame,
                        const std::string& second, const std::string& model, RobotDescription& out)
{
  auto link = std::make_shared<urdf::Link>();
  link->name = frame;
  link->inertial = std::make_shared<urdf::Inertial>();
  link->inertial->mass = kAxisFrameMass;
  link->inertial->ixx = link->inertial->iyy = link->inertial->izz = kAxisFrameInertia;
  tree.links_[frame] = link;
  out.frame_links.insert(frame);
  auto joint = std::make_shared<urdf::Joint>();
  joint->name = second;
  joint->type = urdf::Joint::REVOLUTE;
  joint->parent_link_name = frame;
  joint->child_link_name = first.child_link_name;
  first.child_link_name = frame;
  if (tree.joints_.count(second))
    throw DescriptionError("model '" + model + "' joint '" + second + "' is given twice");
  tree.joints_[second] = joint;
  return *joint;
}

// A screw joint's thread as Gazebo 11 reads it: <thread_pitch> in rad/m, the child advancing
// -angle / thread_pitch along the axis (ODEScrewJoint hands ODE -thread_pitch, whose screw row holds
// the slide at angle / its pitch), so a positive value is a left-handed thread, as sdformat's
// joint.sdf says. Where only SDF 1.10's <screw_thread_pitch> (m per turn, positive right-handed) is
// given, that: thread_pitch = -2 pi / screw_thread_pitch. Returns the metres the child advances per
// radian it turns; throws DescriptionError for a thread that is none (zero, not finite) or
// advances more than kMaxLength a turn.
double screwAdvancePerRadian(const JointPart& part, const std::string& model)
{
  const sdf::ElementPtr e = part.element;
  const std::string where = "model '" + model + "' joint '" + part.name + "' (screw)";
  const bool per_turn = !sdf::child(e, "thread_pitch") && sdf::child(e, "screw_thread_pitch");
  const char* tag = per_turn ? "screw_thread_pitch" : "thread_pitch";
  const double value = sdf::childDouble(e, tag, 1.0);  // sdformat's default for either
  const double advance = per_turn ? value / (2 * M_PI) : -1.0 / value;
  if (!(value != 0) || !std::isfinite(value) || !(std::abs(advance) * 2 * M_PI <= kMaxLength))
    throw DescriptionError(where + ": <" + tag + "> " + formatNumber(value) + " is no thread: give " +
                           (per_turn ? "the metres the child advances a turn (positive: right-handed)"
                                     : "the radians the child turns a metre it advances (Gazebo's: positive "
                                       "for a left-handed thread)") +
                           ", not 0, finite, and at most " + formatNumber(kMaxLength) + " m a turn");
  return advance;
}

// An SDF joint as URDF joints from `parent_frame` (the parent link's frame, in the model) to `child`,
// a link in the joint frame, added to `tree`. Revolute, continuous, prismatic and fixed joints are one
// URDF joint; universal and revolute2 are two revolutes, the second named "<joint>::axis2", through
// a frame link at the joint frame (Gazebo reports them as one joint of two axes). A ball is one
// FLOATING URDF joint named in RobotDescription::ball_joints (the builder makes it spherical). A screw
// is a revolute (its turn, named as the joint, with <axis>'s limits and dynamics) and a prismatic
// slide "<joint>::__screw_slide__" along the same axis through a frame link, the slide tied to the
// turn (RobotDescription::joint_couplings). A gearbox here is one that is its child's only joint:
// held fixed (buildTree couples the others).
void addJoint(urdf::ModelInterface& tree, const JointPart& part, const urdf::Pose& parent_frame,
              const std::string& parent, const std::string& child, const std::string& model, RobotDescription& out)
{
  auto j = std::make_shared<urdf::Joint>();
  j->name = part.name;
  j->parent_link_name = parent;
  j->child_link_name = child;
  j->parent_to_joint_origin_transform = compose(inverse(parent_frame), part.pose);
  tree.joints_[part.name] = j;
  const std::string& type = part.type;
  const std::string where = "model '" + model + "' joint '" + part.name + "'";
  if (type == "revolute" || type == "continuous" || type == "prismatic")
    readAxis(*j, part, "axis", type, model, out);
  else if (type == "universal" || type == "revolute2")
  {
    if (!sdf::child(part.element, "axis2"))
      throw DescriptionError(where + " of type '" + type + "' has no <axis2>: give its second axis");
    readAxis(*j, part, "axis", "revolute", model, out);
    urdf::Joint& second = splitJoint(tree, *j, part.name + "::__axis2_frame__", part.name + "::axis2", model, out);
    readAxis(second, part, "axis2", "revolute", model, out);
    out.warnings.push_back(where + " (" + type + "): simulated as two revolute joints, '" + part.name +
                           "' about <axis> and '" + second.name + "' about <axis2>");
  }
  else if (type == "ball")
  {
    j->type = urdf::Joint::FLOATING;
    out.ball_joints.insert(part.name);
    if (sdf::child(part.element, "axis") || sdf::child(part.element, "axis2"))
      out.warnings.push_back(where + " (ball): its <axis> is ignored: a ball joint turns freely about its origin, "
                             "without an axis, limits, damping or friction, as Gazebo's");
  }
  else if (type == "screw")
  {
    const double advance = screwAdvancePerRadian(part, model);
    readAxis(*j, part, "axis", "revolute", model, out);
    urdf::Joint& slide =
        splitJoint(tree, *j, part.name + "::__screw_frame__", part.name + "::__screw_slide__", model, out);
    slide.type = urdf::Joint::PRISMATIC;
    slide.axis = j->axis;  // the frame turns about the axis, which stays where it is
    out.joint_couplings.push_back({part.name, part.name, slide.name, advance, true});
  }
  else if (type == "fixed")
    j->type = urdf::Joint::FIXED;
  else if (type == "gearbox")
  {
    out.warnings.push_back(where + " is a gearbox and the only joint link '" + part.child + "' hangs from: a "
                           "gearbox couples two revolute joints that hang from its <gearbox_reference_body>, and "
                           "alone it would leave the link free in five directions, which the plant's tree of links "
                           "cannot; it is held fixed");
    j->type = urdf::Joint::FIXED;
  }
  else
    throw DescriptionError("model '" + model + "' joint '" + part.name + "': type '" + type +
                           "' is not an SDF joint type (revolute, continuous, prismatic, fixed, ball, universal, "
                           "revolute2, screw, gearbox)");
}

// The link at the top of the rigid body `link` is part of: up through fixed joints (and gearboxes
// held fixed) to a link that hangs from a movable joint, from none, or the world.
std::string rigidRoot(std::string link, const std::map<std::string, const JointPart*>& hangs_from)
{
  for (size_t guard = 0; guard <= hangs_from.size(); ++guard)  // a tree: the guard only bounds the walk
  {
    auto it = hangs_from.find(link);
    if (it == hangs_from.end() || (it->second->type != "fixed" && it->second->type != "gearbox"))
      break;
    link = it->second->parent;
  }
  return link;
}

// A gearbox between two links that each hang from a revolute joint off its <gearbox_reference_body>
// (or a link fixed to it). Gazebo 11's ODE gearbox holds theta_child = -gearbox_ratio theta_parent,
// each angle its link's from the reference body, the child's about <axis> and the parent's about
// <axis2> (ODEGearboxJoint hands ODE's first body, the child, <axis>; sdformat's joint.sdf words it
// the other way round, which is the same where the two axes agree, as they do in Gazebo's gearbox
// world). In the plant's tree that ties the two revolute joints' positions, q_child = m q_parent
// with m = -ratio times the signs of the joints' axes along the gearbox's: a coupling
// (RobotDescription::joint_couplings). A gearbox the plant cannot tie so is left out with an error,
// the model moving on without it; a ratio that is no number refuses the model (sdf::childDouble).
void coupleGears(const JointPart& gearbox, const std::map<std::string, const LinkPart*>& links,
                 const std::map<std::string, const JointPart*>& hangs_from, const std::string& model,
                 RobotDescription& out)
{
  const std::string where = "model '" + model + "' joint '" + gearbox.name + "' (gearbox)";
  const double ratio = sdf::childDouble(gearbox.element, "gearbox_ratio", 1.0);
  const std::string reference = xml::trimmed(sdf::childText(gearbox.element, "gearbox_reference_body", ""));
  auto leaveOut = [&](const std::string& why) {
    out.errors.push_back(where + ": " + why + "; the gears are not coupled");
  };
  if (reference != kWorld && !links.count(reference))
    return leaveOut("<gearbox_reference_body> '" + reference + "' is no link of the model (nor 'world'): name the "
                    "link both gears turn on");
  const std::string base = rigidRoot(reference, hangs_from);
  struct Gear
  {
    const char* role;
    std::string link;
    const char* axis_tag;
    const JointPart* joint;
    double sign;
  };
  Gear gears[2] = {{"parent", gearbox.parent, "axis2", nullptr, 0.0}, {"child", gearbox.child, "axis", nullptr, 0.0}};
  for (Gear& gear : gears)
  {
    const std::string its = std::string("its ") + gear.role + " '" + gear.link + "'";
    auto it = hangs_from.find(gear.link);
    if (it == hangs_from.end())
      return leaveOut(its + " hangs from no joint: a gearbox couples two revolute joints that hang from its "
                      "<gearbox_reference_body> '" + reference + "'");
    const JointPart& joint = *it->second;
    if (joint.type != "revolute" && joint.type != "continuous")
      return leaveOut(its + " hangs from joint '" + joint.name + "', which is " + joint.type + ": a gearbox couples two "
                      "revolute joints that hang from its <gearbox_reference_body> '" + reference + "'");
    if (rigidRoot(joint.parent, hangs_from) != base)
      return leaveOut("joint '" + joint.name + "' that " + its + " hangs from does not hang from its "
                      "<gearbox_reference_body> '" + reference + "' (nor from a link fixed to it): a gear's angle is "
                      "its angle from that body");
    const urdf::Vector3 a = rotate(joint.pose.rotation, jointAxis(joint, model));
    const urdf::Vector3 b = rotate(gearbox.pose.rotation, jointAxis(gearbox, model, gear.axis_tag));
    const double along = a.x * b.x + a.y * b.y + a.z * b.z;
    if (!(std::abs(along) >= 1 - 1e-6))
      return leaveOut(std::string("its <") + gear.axis_tag + "> is not along the axis of joint '" + joint.name +
                      "' that " + its + " turns about: the plant couples the two joints' angles");
    gear.joint = &joint;
    gear.sign = along > 0 ? 1.0 : -1.0;
  }
  for (const JointCouplingDescription& other : out.joint_couplings)
    if (other.follower == gears[1].joint->name)
      return leaveOut("joint '" + other.follower + "' is the child gear of gearbox '" + other.name + "' already");
  if (ratio == 0)
    out.warnings.push_back(where + ": <gearbox_ratio> 0 holds the child gear's joint '" + gears[1].joint->name +
                           "' still");
  out.joint_couplings.push_back(
      {gearbox.name, gears[0].joint->name, gears[1].joint->name, -ratio * gears[0].sign * gears[1].sign, false});
}

// Makes `root` the root of `tree` (the world, or a link: the model frame a frame link above it where
// that is not the link's own frame) and links urdfdom's tree.
void rootTree(urdf::ModelInterface& tree, const std::string& root, const std::map<std::string, const LinkPart*>& links,
              RobotDescription& out)
{
  if (root != kWorld)
  {
    const urdf::Pose root_frame = links.at(root)->pose;
    if (isIdentity(root_frame))
      tree.root_link_ = tree.links_[root];
    else
    {
      tree.links_[kModelFrame] = frameLink(kModelFrame, out);
      tree.joints_[kModelFrame] = fixedJoint(kModelFrame, kModelFrame, root, root_frame);
    }
  }
  std::map<std::string, std::string> parent_link_tree;
  tree.initTree(parent_link_tree);
  tree.initRoot(parent_link_tree);
}

// The model's links and joints as URDF trees: links in their own frames, a joint frame apart from
// its child link's as a frame link between them, the model frame as a frame link at the root when
// it is not the root link's. The canonical link's tree becomes out.model; each other tree (links no
// joint joins to it) goes to `other_trees`.
void buildTree(const ModelParts& parts, RobotDescription& out, std::vector<urdf::ModelInterfaceSharedPtr>& other_trees)
{
  const std::string& model = parts.name;
  auto tree = std::make_shared<urdf::ModelInterface>();
  tree->name_ = model;
  std::map<std::string, const LinkPart*> links;
  for (const LinkPart& part : parts.links)
  {
    links[part.name] = &part;
    try
    {
      tree->links_[part.name] = readLink(part, model, out);
    }
    catch (const DescriptionError& e)
    {
      throw inContext("model '" + model + "' link '" + part.name + "'", e);
    }
  }
  if (links.empty())
    throw DescriptionError("model '" + model + "' has no <link>: a model that moves needs one");
  std::map<std::string, std::string> parent_of;  // child link -> joint
  std::map<std::string, const JointPart*> hangs_from;  // child link -> its joint
  std::set<std::string> joint_names;
  std::vector<const JointPart*> gearboxes;
  bool world_rooted = false;
  auto addTreeJoint = [&](const JointPart& part) {
    const std::string where = "model '" + model + "' joint '" + part.name + "'";
    if (parent_of.count(part.child))
      throw DescriptionError(where + " closes a kinematic loop: link '" + part.child + "' already hangs from joint '" +
                             parent_of[part.child] + "'. The plant simulates a model's links as a tree (a Featherstone "
                             "multibody) and has no loop-closing constraints yet; model the loop as two models, or "
                             "leave one joint out");
    parent_of[part.child] = part.name;
    hangs_from[part.child] = &part;
    const urdf::Pose child_frame = links[part.child]->pose;
    const urdf::Pose parent_frame = part.parent == kWorld ? urdf::Pose() : links[part.parent]->pose;
    std::string parent = part.parent;
    if (part.parent == kWorld)
    {
      world_rooted = true;
      if (!tree->links_.count(kWorld))
        tree->links_[kWorld] = frameLink(kWorld, out);
    }
    const urdf::Pose joint_in_child = compose(inverse(child_frame), part.pose);
    try
    {
      if (isIdentity(joint_in_child))
        addJoint(*tree, part, parent_frame, parent, part.child, model, out);
      else
      {
        const std::string frame = part.name + "::__joint_frame__";
        tree->links_[frame] = frameLink(frame, out);
        addJoint(*tree, part, parent_frame, parent, frame, model, out);
        tree->joints_[frame] = fixedJoint(frame, frame, part.child, inverse(joint_in_child));
      }
    }
    catch (const DescriptionError& e)
    {
      throw inContext(where, e);
    }
  };
  for (const JointPart& part : parts.joints)
  {
    const std::string where = "model '" + model + "' joint '" + part.name + "'";
    if (!joint_names.insert(part.name).second || tree->joints_.count(part.name))
      throw DescriptionError(where + " is given twice; joint names must be unique in a model");
    if (!links.count(part.child))
      throw DescriptionError(where + ": <child> '" + part.child + "' is no link of the model");
    if (part.parent != kWorld && !links.count(part.parent))
      throw DescriptionError(where + ": <parent> '" + part.parent + "' is no link of the model (nor 'world')");
    if (part.parent == part.child)
      throw DescriptionError(where + " joins link '" + part.child + "' to itself");
    if (part.type == "gearbox")
      gearboxes.push_back(&part);  // once the tree is known: a constraint between two of its joints
    else
      addTreeJoint(part);
    readSensors(part.element, part.child, out, part.name);
  }
  for (const JointPart* gearbox : gearboxes)
  {
    if (!parent_of.count(gearbox->child))
    {
      addTreeJoint(*gearbox);  // its child's only joint: held fixed (addJoint)
      continue;
    }
    try
    {
      coupleGears(*gearbox, links, hangs_from, model, out);
    }
    catch (const DescriptionError& e)
    {
      throw inContext("model '" + model + "' joint '" + gearbox->name + "'", e);
    }
  }
  // The roots: links no joint hangs from.
  std::vector<std::string> roots;
  for (const LinkPart& part : parts.links)
    if (!parent_of.count(part.name))
      roots.push_back(part.name);
  if (roots.empty() && !world_rooted)
    throw DescriptionError("model '" + model + "': every link hangs from a joint, so the joints close a loop; the "
                           "plant simulates a model's links as a tree");
  // Links no joint joins to the canonical link's tree (free links, or links beside a tree fixed to
  // the world): Gazebo moves each such tree on its own. Each becomes a tree of its own, split off
  // whole (its links, their joint frames and joints).
  std::map<std::string, std::string> parent_link;  // child -> parent, over every joint of the tree
  for (const auto& joint : tree->joints_)
    parent_link[joint.second->child_link_name] = joint.second->parent_link_name;
  auto rootOf = [&](const std::string& link) {
    std::string up = link;
    for (size_t hops = 0; parent_link.count(up); ++hops)
    {
      if (hops > parent_link.size())
        throw DescriptionError("model '" + model + "': the joints above link '" + link + "' close a loop; the plant "
                               "simulates a model's links as trees");
      up = parent_link[up];
    }
    return up;
  };
  for (const auto& link : tree->links_)
    rootOf(link.first);  // a loop of joints hangs from no root: refused
  std::vector<std::string> tree_roots = roots;
  if (world_rooted)
    tree_roots.insert(tree_roots.begin(), kWorld);
  const std::string canonical_root = rootOf(parts.links.front().name);
  for (const std::string& root : tree_roots)
  {
    if (root == canonical_root)
      continue;
    auto other = std::make_shared<urdf::ModelInterface>();
    other->name_ = model;
    for (auto link = tree->links_.begin(); link != tree->links_.end();)
      if (rootOf(link->first) == root)
      {
        other->links_.insert(*link);
        link = tree->links_.erase(link);
      }
      else
        ++link;
    for (auto joint = tree->joints_.begin(); joint != tree->joints_.end();)
      if (other->links_.count(joint->second->child_link_name))
      {
        other->joints_.insert(*joint);
        joint = tree->joints_.erase(joint);
      }
      else
        ++joint;
    rootTree(*other, root, links, out);
    other_trees.push_back(other);
  }
  rootTree(*tree, canonical_root, links, out);
  out.model = tree;
}

// The description of one of the model's trees: what `whole` says of that tree's links and joints.
// `canonical`: the canonical link's tree, which keeps the model's plugins and gazebo_ros_control.
RobotDescription treeDescription(const RobotDescription& whole, const urdf::ModelInterfaceSharedPtr& tree,
                                 bool canonical)
{
  RobotDescription out;
  out.model = tree;
  out.is_static = whole.is_static;
  out.allow_auto_disable = whole.allow_auto_disable;
  out.format = whole.format;
  out.base_dir = whole.base_dir;
  if (canonical)
  {
    out.control = whole.control;
    out.transmissions = whole.transmissions;
    out.model_plugins = whole.model_plugins;
    out.warnings = whole.warnings;
    out.errors = whole.errors;
  }
  auto keepLinks = [&](const auto& by_link, auto& kept) {
    for (const auto& entry : by_link)
      if (tree->links_.count(entry.first))
        kept.insert(entry);
  };
  keepLinks(whole.surfaces, out.surfaces);
  keepLinks(whole.collision_surfaces, out.collision_surfaces);
  keepLinks(whole.link_physics, out.link_physics);
  keepLinks(whole.visual_materials, out.visual_materials);
  for (const auto& spring : whole.joint_springs)
    if (tree->joints_.count(spring.first))
      out.joint_springs.insert(spring);
  for (const std::string& joint : whole.joint_feedback)
    if (tree->joints_.count(joint))
      out.joint_feedback.insert(joint);
  for (const std::string& link : whole.frame_links)
    if (tree->links_.count(link))
      out.frame_links.insert(link);
  for (const std::string& joint : whole.ball_joints)
    if (tree->joints_.count(joint))
      out.ball_joints.insert(joint);
  for (const JointCouplingDescription& coupling : whole.joint_couplings)
    if (tree->joints_.count(coupling.leader))
      out.joint_couplings.push_back(coupling);
  for (const SensorDescription& sensor : whole.sensors)
    if (tree->links_.count(sensor.link))
      out.sensors.push_back(sensor);
  return out;
}

}  // namespace

namespace sdf
{
ModelDescription readModel(const ElementPtr& model, const Source& source)
{
  ModelDescription out;
  out.name = attribute(model, "name", "model");

  out.robot.base_dir = source.dir;
  out.robot.format = RobotDescription::Format::Sdf;
  out.robot.is_static = isTrue(childText(model, "static", "false"));
  ModelParts parts;
  parts.name = out.name;
  try
  {
    out.pose = pose(model);
    collectModel(model, "", urdf::Pose(), source, 0, parts, out.robot);
  }
  catch (const DescriptionError& e)
  {
    throw inContext("model '" + out.name + "'", e);
  }
  std::vector<urdf::ModelInterfaceSharedPtr> other_trees;
  buildTree(parts, out.robot, other_trees);
  for (const ElementPtr& plugin : parts.plugins)
    readModelPlugin(plugin, out.robot);
  if (!other_trees.empty())
  {
    RobotDescription whole = std::move(out.robot);
    out.robot = treeDescription(whole, whole.model, true);
    for (const urdf::ModelInterfaceSharedPtr& tree : other_trees)
      out.robot.other_trees.push_back(treeDescription(whole, tree, false));
  }
  return out;
}
}  // namespace sdf

ModelDescription parseSdfModel(const std::string& sdf_xml, const std::string& base_dir)
{
  const sdf::Source source{"", base_dir};
  const sdf::Document doc = sdf::readDocument(sdf_xml, source);
  sdf::ElementPtr model = sdf::child(doc.root(), "model");
  if (!model)
    model = sdf::child(doc.root(), "world/model");
  if (!model)
    throw DescriptionError("SDF has no <model> (an <sdf> with a <model> in it)");
  ModelDescription out = sdf::readModel(model, source);
  out.robot.warnings.insert(out.robot.warnings.end(), doc.warnings.begin(), doc.warnings.end());
  return out;
}

ModelDescription parseModelXml(const std::string& xml, const std::string& base_dir)
{
  tinyxml2::XMLDocument doc;
  const bool parsed = doc.Parse(xml.c_str(), xml.size()) == tinyxml2::XML_SUCCESS;
  const tinyxml2::XMLElement* root = parsed ? doc.RootElement() : nullptr;
  if (root && (std::string(root->Name()) == "sdf" || std::string(root->Name()) == "model"))
    return parseSdfModel(xml, base_dir);
  ModelDescription out;
  out.robot = parseRobotDescription(xml, base_dir);  // URDF, or its parser's complaint
  out.name = out.robot.model->getName();
  return out;
}

}  // namespace bullet_plant
