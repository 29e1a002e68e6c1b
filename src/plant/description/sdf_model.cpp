#include "bullet_plant/sdf_model.h"

#include <cmath>
#include <functional>
#include <limits>
#include <map>
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

std::string attribute(const tinyxml2::XMLElement* e, const char* name, const std::string& fallback = "")
{
  const char* value = e ? e->Attribute(name) : nullptr;
  return value ? value : fallback;
}

bool isIdentity(const urdf::Pose& p)
{
  return std::abs(p.position.x) < 1e-12 && std::abs(p.position.y) < 1e-12 && std::abs(p.position.z) < 1e-12 &&
         std::abs(std::abs(p.rotation.w) - 1.0) < 1e-12;
}

// The frames one (possibly nested) model's <pose relative_to> may name, each with its pose and the
// frame that pose is relative to (SDF 1.7; 1.5 and 1.6 wrote `frame`): resolved to the model frame.
class FrameGraph
{
public:
  FrameGraph(std::string model) : model_(std::move(model)) {}
  void add(const std::string& name, const std::string& relative_to, const urdf::Pose& pose)
  {
    entries_[name] = {relative_to, pose};
  }
  bool has(const std::string& name) const { return entries_.count(name) > 0; }
  // The frame's pose in the model frame; throws DescriptionError for a frame the model lacks or a cycle.
  urdf::Pose resolve(const std::string& name, int depth = 0) const
  {
    if (name.empty() || name == kModelFrame)
      return urdf::Pose();
    auto it = entries_.find(name);
    if (it == entries_.end())
      throw DescriptionError("model '" + model_ + "': <pose relative_to=\"" + name + "\"> names no frame, link, joint "
                             "or model of the model");
    if (depth > int(entries_.size()))
      throw DescriptionError("model '" + model_ + "': the poses relative to '" + name + "' form a cycle");
    return compose(resolve(it->second.relative_to, depth + 1), it->second.pose);
  }

private:
  struct Entry
  {
    std::string relative_to;
    urdf::Pose pose;
  };
  std::string model_;
  std::map<std::string, Entry> entries_;
};

// A <pose>'s text and the frame it is relative to ("" when not given).
urdf::Pose poseOf(const tinyxml2::XMLElement* e, std::string& relative_to)
{
  const tinyxml2::XMLElement* pose = e->FirstChildElement("pose");
  relative_to = attribute(pose, "relative_to", attribute(pose, "frame"));
  return xml::parseSdfPose(pose && pose->GetText() ? pose->GetText() : "");
}

struct LinkPart
{
  std::string name;  // scoped: "nested::link"
  urdf::Pose pose;   // in the top model's frame
  const tinyxml2::XMLElement* element;
  Source source;
};

struct JointPart
{
  std::string name, type, parent, child;  // scoped names; parent may be "world"
  urdf::Pose pose;                        // the joint frame in the top model's frame
  const tinyxml2::XMLElement* element;
  int version;
  urdf::Pose model_frame;  // the frame of the model that declares it, in the top model's frame
};

struct ModelParts
{
  std::string name;
  std::vector<LinkPart> links;
  std::vector<JointPart> joints;
  std::vector<const tinyxml2::XMLElement*> plugins;
  std::vector<std::unique_ptr<tinyxml2::XMLDocument>> included;  // documents the parts point into
};

void collectModel(const tinyxml2::XMLElement* model, const std::string& scope, const urdf::Pose& in_top,
                  const Source& source, int depth, ModelParts& parts, RobotDescription& out);

// An <include> inside a model: the included model read as if nested here.
void collectInclude(const tinyxml2::XMLElement* include, const std::string& scope, const urdf::Pose& in_top,
                    const FrameGraph& frames, const Source& source, int depth, ModelParts& parts, RobotDescription& out)
{
  const std::string uri = xml::childText(include, "uri", "");
  std::string reason;
  const std::string dir = depth > sdf::kMaxModelDepth ? "" : sdf::includedModelDir(uri, source, reason);
  if (dir.empty())
  {
    out.warnings.push_back("model '" + parts.name + "': <include> of '" + uri + "': " +
                           (depth > sdf::kMaxModelDepth ? "models nested too deep (an include loop?)" : reason) +
                           "; skipped");
    return;
  }
  Source model_source{sdf::modelFile(dir), dir};
  parts.included.emplace_back(new tinyxml2::XMLDocument);
  tinyxml2::XMLDocument& doc = *parts.included.back();
  sdf::parseXml(doc, sdf::readFile(model_source.file, "model file"), model_source);
  const tinyxml2::XMLElement* sdf = doc.FirstChildElement("sdf");
  const tinyxml2::XMLElement* nested = sdf ? sdf->FirstChildElement("model") : nullptr;
  if (!nested)
  {
    out.warnings.push_back("model '" + parts.name + "': <include> of '" + uri + "': " + model_source.describe() +
                           " has no <sdf><model>; skipped");
    return;
  }
  const std::string name = xml::childText(include, "name", attribute(nested, "name", "model"));
  std::string relative_to;
  urdf::Pose pose = include->FirstChildElement("pose") ? poseOf(include, relative_to) : poseOf(nested, relative_to);
  pose = compose(frames.resolve(relative_to), pose);
  collectModel(nested, scope + name + "::", compose(in_top, pose), model_source, depth + 1, parts, out);
}

void collectModel(const tinyxml2::XMLElement* model, const std::string& scope, const urdf::Pose& in_top,
                  const Source& source, int depth, ModelParts& parts, RobotDescription& out)
{
  const int version = sdf::versionOf(model);
  FrameGraph frames(parts.name);
  // Every named frame first: a pose may be relative to one declared after it.
  for (auto* e = model->FirstChildElement(); e; e = e->NextSiblingElement())
  {
    const std::string tag = e->Name(), name = attribute(e, "name");
    std::string relative_to;
    const urdf::Pose pose = poseOf(e, relative_to);
    if (tag == "link" || tag == "model")
      frames.add(name, relative_to, pose);
    else if (tag == "frame")
    {
      const std::string attached_to = attribute(e, "attached_to");
      frames.add(name, relative_to.empty() ? attached_to : relative_to, pose);
    }
    else if (tag == "joint")
      frames.add(name, relative_to.empty() ? xml::childText(e, "child", "") : relative_to, pose);
  }
  for (auto* e = model->FirstChildElement(); e; e = e->NextSiblingElement())
  {
    const std::string tag = e->Name(), name = attribute(e, "name");
    if (tag == "link")
    {
      for (const LinkPart& link : parts.links)
        if (link.name == scope + name)
          throw DescriptionError("model '" + parts.name + "': link '" + scope + name + "' is given twice; link names "
                                 "must be unique in a model");
      parts.links.push_back({scope + name, compose(in_top, frames.resolve(name)), e, source});
    }
    else if (tag == "joint")
    {
      JointPart joint;
      joint.name = scope + name;
      joint.type = attribute(e, "type");
      joint.element = e;
      joint.version = version;
      joint.model_frame = in_top;
      const std::string parent = xml::childText(e, "parent", ""), child = xml::childText(e, "child", "");
      joint.parent = parent == kWorld ? kWorld : scope + parent;
      joint.child = scope + child;
      joint.pose = compose(in_top, frames.resolve(name));
      parts.joints.push_back(joint);
    }
    else if (tag == "model")
      collectModel(e, scope + name + "::", compose(in_top, frames.resolve(name)), source, depth + 1, parts, out);
    else if (tag == "include")
      collectInclude(e, scope, in_top, frames, source, depth + 1, parts, out);
    else if (tag == "plugin")
      parts.plugins.push_back(e);
    else if (tag == "enable_wind" && sdf::isTrue(xml::trimmed(e->GetText() ? e->GetText() : "")))
      out.warnings.push_back("model '" + parts.name + "': <enable_wind> is ignored (the plant has no wind)");
    else if (tag == "self_collide" && sdf::isTrue(xml::trimmed(e->GetText() ? e->GetText() : "")))
      out.warnings.push_back("model '" + parts.name + "': <self_collide> is ignored: a model's links do not "
                             "collide with each other in the plant");
  }
}

// <inertial>: SDF's defaults (mass 1 kg, unit moments) where absent; the mass and inertia checked as
// a physics engine needs them.
urdf::InertialSharedPtr readInertial(const tinyxml2::XMLElement* link, const std::string& model, const std::string& name)
{
  auto inertial = std::make_shared<urdf::Inertial>();
  inertial->mass = 1.0;
  inertial->ixx = inertial->iyy = inertial->izz = 1.0;
  inertial->ixy = inertial->ixz = inertial->iyz = 0.0;
  const tinyxml2::XMLElement* e = link->FirstChildElement("inertial");
  const std::string where = "model '" + model + "' link '" + name + "': <inertial>";
  if (e)
  {
    inertial->mass = xml::childDouble(e, "mass", 1.0);
    inertial->origin = xml::parseSdfPose(xml::childText(e, "pose", ""));
    inertial->ixx = xml::childDouble(e, "inertia/ixx", 1.0);
    inertial->iyy = xml::childDouble(e, "inertia/iyy", 1.0);
    inertial->izz = xml::childDouble(e, "inertia/izz", 1.0);
    inertial->ixy = xml::childDouble(e, "inertia/ixy", 0.0);
    inertial->ixz = xml::childDouble(e, "inertia/ixz", 0.0);
    inertial->iyz = xml::childDouble(e, "inertia/iyz", 0.0);
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
  if (!(a > 0 && minor2 > 0 && det > 0) || std::max({a, b, c}) > largest)
  {
    std::ostringstream text;
    text << where << "<inertia> ixx " << a << " iyy " << b << " izz " << c << " ixy " << d << " ixz " << f << " iyz "
         << g << " is not positive definite (or beyond " << largest
         << " kg m^2): every moment must be positive and each at most the sum of the other two";
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
  for (auto* c = part.element->FirstChildElement("collision"); c; c = c->NextSiblingElement("collision"))
  {
    const std::string name = attribute(c, "name", "collision");
    const std::string where = in_link + " collision '" + name + "'";
    const tinyxml2::XMLElement* geometry = c->FirstChildElement("geometry");
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
    collision->origin = xml::parseSdfPose(xml::childText(c, "pose", ""));
    collision->geometry = toUrdfGeometry(shape);
    link->collision_array.push_back(collision);
    SurfaceDescription surface = sdf::readSurface(c);
    if (surface.given && !out.surfaces[part.name].given)
      out.surfaces[part.name] = surface;  // the plant's friction is per link: the first collision's
  }
  if (!link->collision_array.empty())
    link->collision = link->collision_array.front();
  for (auto* v = part.element->FirstChildElement("visual"); v; v = v->NextSiblingElement("visual"))
  {
    const std::string name = attribute(v, "name", "visual");
    const tinyxml2::XMLElement* geometry = v->FirstChildElement("geometry");
    Shape shape;
    if (!geometry || !sdf::readGeometry(geometry, in_link + " visual '" + name + "'", part.source, shape, out.warnings,
                                        "cameras do not see it") ||
        shape.kind == Shape::Kind::Plane)
      continue;
    auto visual = std::make_shared<urdf::Visual>();
    visual->name = name;
    visual->origin = xml::parseSdfPose(xml::childText(v, "pose", ""));
    visual->geometry = toUrdfGeometry(shape);
    const Rgba colour = sdf::readColour(v);
    visual->material = std::make_shared<urdf::Material>();
    visual->material->color.init(std::to_string(colour.r) + " " + std::to_string(colour.g) + " " +
                                 std::to_string(colour.b) + " " + std::to_string(colour.a));
    link->visual_array.push_back(visual);
  }
  if (!link->visual_array.empty())
    link->visual = link->visual_array.front();
  for (const char* flag : {"gravity", "kinematic"})
  {
    const std::string text = xml::childText(part.element, flag, "");
    if (!text.empty() && sdf::isTrue(text) != (std::string(flag) == "gravity"))
      out.warnings.push_back(in_link + ": <" + flag + ">" + text + "</" + flag + "> is not simulated yet; the link "
                             "moves as a dynamic link under gravity");
  }
  readSensors(part.element, part.name, out);
  return link;
}

// The joint's axis in the joint frame: SDF 1.4 gives it in the model frame, 1.5 and 1.6 where
// <use_parent_model_frame> says, 1.7 where <xyz expressed_in> says.
urdf::Vector3 jointAxis(const JointPart& joint, const std::string& model)
{
  const tinyxml2::XMLElement* axis = joint.element->FirstChildElement("axis");
  const tinyxml2::XMLElement* xyz_element = axis ? axis->FirstChildElement("xyz") : nullptr;
  const std::string text = xyz_element && xyz_element->GetText() ? xyz_element->GetText() : "0 0 1";
  const std::vector<double> xyz = xml::numbers(text, 3, "model '" + model + "' joint '" + joint.name + "' <axis><xyz>");
  const double norm = std::sqrt(xyz[0] * xyz[0] + xyz[1] * xyz[1] + xyz[2] * xyz[2]);
  if (!(norm > 1e-9) || !std::isfinite(norm))
    throw DescriptionError("model '" + model + "' joint '" + joint.name + "': <axis><xyz> " + xml::trimmed(text) +
                           " is not a direction: give a vector that is not zero");
  urdf::Vector3 v(xyz[0] / norm, xyz[1] / norm, xyz[2] / norm);
  const std::string expressed_in = attribute(xyz_element, "expressed_in");
  const bool in_model = joint.version < 105 || sdf::isTrue(xml::childText(axis, "use_parent_model_frame", "false")) ||
                        expressed_in == kModelFrame;
  if (in_model)  // model frame -> joint frame
    v = rotate(inverse(compose(inverse(joint.model_frame), joint.pose)).rotation, v);
  else if (!expressed_in.empty())
    throw DescriptionError("model '" + model + "' joint '" + joint.name + "': <xyz expressed_in=\"" + expressed_in +
                           "\"> is not supported (the joint frame or __model__ are)");
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

// A movable or fixed SDF joint as a URDF joint from `parent_frame` (the parent link's frame, in the
// model) to its child frame, the joint frame.
std::shared_ptr<urdf::Joint> readJoint(const JointPart& part, const urdf::Pose& parent_frame, const std::string& parent,
                                       const std::string& child, const std::string& model, RobotDescription& out)
{
  auto j = std::make_shared<urdf::Joint>();
  j->name = part.name;
  j->parent_link_name = parent;
  j->child_link_name = child;
  j->parent_to_joint_origin_transform = compose(inverse(parent_frame), part.pose);
  const std::string& type = part.type;
  if (type == "fixed")
  {
    j->type = urdf::Joint::FIXED;
    return j;
  }
  if (type != "revolute" && type != "continuous" && type != "prismatic")
  {
    if (type == "ball" || type == "universal" || type == "revolute2" || type == "screw" || type == "gearbox")
      out.warnings.push_back("model '" + model + "' joint '" + part.name + "' is of type '" + type +
                             "', which the plant does not simulate yet (revolute, continuous, prismatic, fixed); "
                             "it is held fixed");
    else
      throw DescriptionError("model '" + model + "' joint '" + part.name + "': type '" + type +
                             "' is not an SDF joint type (revolute, continuous, prismatic, fixed, ball, universal, "
                             "revolute2, screw, gearbox)");
    j->type = urdf::Joint::FIXED;
    return j;
  }
  j->axis = jointAxis(part, model);
  const tinyxml2::XMLElement* axis = part.element->FirstChildElement("axis");
  const std::string where = "model '" + model + "' joint '" + part.name + "' <axis>";
  auto limits = std::make_shared<urdf::JointLimits>();
  limits->lower = xml::childDouble(axis, "limit/lower", -kSdfUnlimited);
  limits->upper = xml::childDouble(axis, "limit/upper", kSdfUnlimited);
  limits->effort = xml::childDouble(axis, "limit/effort", -1.0);
  limits->velocity = xml::childDouble(axis, "limit/velocity", -1.0);
  if (std::isnan(limits->lower) || std::isnan(limits->upper))
    throw DescriptionError(where + "<limit>: lower and upper must be numbers");
  // SDF: a negative effort or velocity limit is none.
  if (limits->effort < 0)
    limits->effort = std::numeric_limits<double>::infinity();
  const bool unlimited = limits->lower <= -kSdfUnlimited && limits->upper >= kSdfUnlimited;
  if (unlimited)
    limits->lower = limits->upper = 0.0;  // no position limits (the builder's lower < upper test)
  j->limits = limits;
  j->type = type == "prismatic" ? urdf::Joint::PRISMATIC
            : type == "continuous" || unlimited ? urdf::Joint::CONTINUOUS
                                                : urdf::Joint::REVOLUTE;
  if (const tinyxml2::XMLElement* dynamics = axis ? axis->FirstChildElement("dynamics") : nullptr)
  {
    j->dynamics = std::make_shared<urdf::JointDynamics>();
    j->dynamics->damping = xml::childDouble(dynamics, "damping", 0.0);
    j->dynamics->friction = xml::childDouble(dynamics, "friction", 0.0);
    if (!(j->dynamics->damping >= 0) || !(j->dynamics->friction >= 0))
      throw DescriptionError(where + "<dynamics>: damping " + formatNumber(j->dynamics->damping) + " and friction " +
                             formatNumber(j->dynamics->friction) + " must be numbers >= 0");
    JointSpring spring;
    spring.stiffness = xml::childDouble(dynamics, "spring_stiffness", 0.0);
    spring.reference = xml::childDouble(dynamics, "spring_reference", 0.0);
    if (!(spring.stiffness >= 0) || !std::isfinite(spring.stiffness) || !std::isfinite(spring.reference))
      throw DescriptionError(where + "<dynamics>: spring_stiffness " + formatNumber(spring.stiffness) +
                             " must be a finite number >= 0, spring_reference finite");
    if (spring.stiffness > 0)
      out.joint_springs[part.name] = spring;
  }
  return j;
}

// The model's links and joints as a URDF tree: links in their own frames, a joint frame apart from
// its child link's as a frame link between them, the model frame as a frame link at the root when
// it is not the root link's.
void buildTree(const ModelParts& parts, RobotDescription& out)
{
  const std::string& model = parts.name;
  auto tree = std::make_shared<urdf::ModelInterface>();
  tree->name_ = model;
  std::map<std::string, const LinkPart*> links;
  for (const LinkPart& part : parts.links)
  {
    links[part.name] = &part;
    tree->links_[part.name] = readLink(part, model, out);
  }
  if (links.empty())
    throw DescriptionError("model '" + model + "' has no <link>: a model that moves needs one");
  std::map<std::string, std::string> parent_of;  // child link -> joint
  bool world_rooted = false;
  for (const JointPart& part : parts.joints)
  {
    const std::string where = "model '" + model + "' joint '" + part.name + "'";
    if (tree->joints_.count(part.name))
      throw DescriptionError(where + " is given twice; joint names must be unique in a model");
    if (!links.count(part.child))
      throw DescriptionError(where + ": <child> '" + part.child + "' is no link of the model");
    if (part.parent != kWorld && !links.count(part.parent))
      throw DescriptionError(where + ": <parent> '" + part.parent + "' is no link of the model (nor 'world')");
    if (part.parent == part.child)
      throw DescriptionError(where + " joins link '" + part.child + "' to itself");
    if (parent_of.count(part.child))
      throw DescriptionError(where + " closes a kinematic loop: link '" + part.child + "' already hangs from joint '" +
                             parent_of[part.child] + "'. The plant simulates a model's links as a tree (a Featherstone "
                             "multibody) and has no loop-closing constraints yet; model the loop as two models, or "
                             "leave one joint out");
    parent_of[part.child] = part.name;
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
    if (isIdentity(joint_in_child))
      tree->joints_[part.name] = readJoint(part, parent_frame, parent, part.child, model, out);
    else
    {
      const std::string frame = part.name + "::__joint_frame__";
      tree->links_[frame] = frameLink(frame, out);
      tree->joints_[part.name] = readJoint(part, parent_frame, parent, frame, model, out);
      tree->joints_[frame] = fixedJoint(frame, frame, part.child, inverse(joint_in_child));
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
  // Free links beside another tree (or one fixed to the world): Gazebo lets each move on its own;
  // the plant's model is one tree.
  if (roots.size() > 1 || (world_rooted && !roots.empty()))
  {
    std::string names;
    for (const std::string& root : roots)
      names += (names.empty() ? "'" : ", '") + root + "'";
    throw DescriptionError("model '" + model + "': links " + names + (world_rooted ? " are not joined to the world" : " are not joined by joints") +
                           ": the plant simulates a model as one tree of links. Join them with a joint, or put each "
                           "in a <model> of its own");
  }
  if (!world_rooted)
  {
    const urdf::Pose root_frame = links[roots[0]]->pose;
    if (isIdentity(root_frame))
      tree->root_link_ = tree->links_[roots[0]];
    else
    {
      tree->links_[kModelFrame] = frameLink(kModelFrame, out);
      tree->joints_[kModelFrame] = fixedJoint(kModelFrame, kModelFrame, roots[0], root_frame);
    }
  }
  std::map<std::string, std::string> parent_link_tree;
  tree->initTree(parent_link_tree);
  tree->initRoot(parent_link_tree);
  out.model = tree;
}

}  // namespace

namespace sdf
{
ModelDescription readModel(const tinyxml2::XMLElement* model, const Source& source, int depth)
{
  ModelDescription out;
  out.name = attribute(model, "name", "model");
  std::string relative_to;
  out.pose = poseOf(model, relative_to);
  out.robot.base_dir = source.dir;
  out.robot.sdf_collision_names = true;
  out.robot.is_static = isTrue(xml::childText(model, "static", "false"));
  ModelParts parts;
  parts.name = out.name;
  collectModel(model, "", urdf::Pose(), source, depth, parts, out.robot);
  buildTree(parts, out.robot);
  for (const tinyxml2::XMLElement* plugin : parts.plugins)
    readModelPlugin(plugin, out.robot);
  return out;
}
}  // namespace sdf

ModelDescription parseSdfModel(const std::string& sdf_xml, const std::string& base_dir)
{
  const Source source{"", base_dir};
  tinyxml2::XMLDocument doc;
  sdf::parseXml(doc, sdf_xml, source);
  const tinyxml2::XMLElement* root = doc.RootElement();
  const tinyxml2::XMLElement* model = nullptr;
  if (root && std::string(root->Name()) == "model")
    model = root;
  else if (root && std::string(root->Name()) == "sdf")
  {
    model = root->FirstChildElement("model");
    if (!model)
      if (const tinyxml2::XMLElement* world = root->FirstChildElement("world"))
        model = world->FirstChildElement("model");
  }
  if (!model)
    throw DescriptionError("SDF has no <model> (an <sdf> with a <model> in it)");
  return sdf::readModel(model, source);
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
