// A robot's joint and link properties changed while it runs (Robot::setJointProperties,
// linkProperties, setLinkProperties in include/bullet_plant/robot.h): gazebo_ros's
// set_joint_properties and get/set_link_properties on the multibody the robot builder made.
#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "bullet_plant/robot.h"
#include "physics/dynamics_world.h"
#include "simulation/internals.h"
#include "simulation/robot_builder.h"

namespace bullet_plant
{
namespace
{
bool given(double v) { return !std::isnan(v); }

std::string number(double v)
{
  std::ostringstream text;
  text << v;
  return text.str();
}
}  // namespace

void Robot::setJointProperties(const std::string& joint, const JointProperties& p)
{
  auto it = in_->multibody.joint_index.find(joint);
  if (it == in_->multibody.joint_index.end())
    throw std::out_of_range("robot '" + in_->name + "' has no movable joint '" + joint + "'");
  MovableJoint& j = in_->multibody.joints[it->second];
  const std::string where = "joint '" + joint + "' of '" + in_->name + "': ";
  if (given(p.damping) && !(p.damping >= 0 && std::isfinite(p.damping)))
    throw std::invalid_argument(where + "damping " + number(p.damping) + " is not a finite damping >= 0");
  // ODE's stops may be infinite (dInfinity: none on that side).
  if (given(p.fmax) && !(p.fmax >= 0 && std::isfinite(p.fmax)))
    throw std::invalid_argument(where + "fmax " + number(p.fmax) + " is not a finite force or torque >= 0");
  if (given(p.vel) && !std::isfinite(p.vel))
    throw std::invalid_argument(where + "vel " + number(p.vel) + " is not a finite velocity");
  if (given(p.damping))
    j.damping = p.damping;
  if (given(p.lower) || given(p.upper))
  {
    // A joint without stops has none on either side until one is given.
    double lower = j.limits.has_position ? j.limits.lower : -std::numeric_limits<double>::infinity();
    double upper = j.limits.has_position ? j.limits.upper : std::numeric_limits<double>::infinity();
    if (given(p.lower))
      lower = p.lower;
    if (given(p.upper))
      upper = p.upper;
    // ODE's rule: a low stop above the high one makes neither act.
    j.limits.has_position = lower <= upper;
    j.limits.lower = lower;
    j.limits.upper = upper;
  }
  if (given(p.fmax))
    j.friction = p.fmax;
  if (given(p.vel))
    j.friction_velocity = p.vel;
  updateJointRows(*in_, j);
  wakeUp(*in_->multibody.bullet);
}

LinkProperties Robot::linkProperties(const std::string& link) const
{
  if (const Robot* tree = in_->otherTreeWithLink(link))
    return tree->linkProperties(link);
  if (!in_->multibody.link_in_body.count(link))
    throw std::out_of_range("robot '" + in_->name + "' has no link '" + link + "'");
  LinkProperties out;
  urdf::LinkConstSharedPtr l = in_->description.model->getLink(link);
  if (l && l->inertial)
  {
    const urdf::Inertial& in = *l->inertial;
    out.mass = in.mass;
    out.com = in.origin.position;
    out.ixx = in.ixx;
    out.ixy = in.ixy;
    out.ixz = in.ixz;
    out.iyy = in.iyy;
    out.iyz = in.iyz;
    out.izz = in.izz;
  }
  auto physics = in_->description.link_physics.find(link);
  out.gravity = physics == in_->description.link_physics.end() || physics->second.gravity;
  return out;
}

std::string Robot::setLinkProperties(const std::string& link, const LinkProperties& p)
{
  if (Robot* tree = in_->otherTreeWithLink(link))
    return tree->setLinkProperties(link, p);
  auto placed = in_->multibody.link_in_body.find(link);
  if (placed == in_->multibody.link_in_body.end())
    throw std::out_of_range("robot '" + in_->name + "' has no link '" + link + "'");
  const std::string where = "link '" + link + "' of '" + in_->name + "': ";
  for (double v : {p.mass, p.com.x, p.com.y, p.com.z, p.ixx, p.ixy, p.ixz, p.iyy, p.iyz, p.izz})
    if (!std::isfinite(v))
      throw std::invalid_argument(where + "the mass, centre of mass and inertia must be finite");
  // As the URDF reader takes an <inertial> (robot_description.h: kMaxLinkMass, kMaxLength).
  if (!(p.mass >= 0 && p.mass <= kMaxLinkMass))
    throw std::invalid_argument(where + "mass " + number(p.mass) + " is outside [0, " + number(kMaxLinkMass) + "] kg");
  if (p.ixx < 0 || p.iyy < 0 || p.izz < 0)
    throw std::invalid_argument(where + "a moment of inertia is negative (ixx " + number(p.ixx) + ", iyy " +
                                number(p.iyy) + ", izz " + number(p.izz) + ")");
  const double largest = kMaxLinkMass * kMaxLength * kMaxLength;
  if (std::max({p.ixx, p.iyy, p.izz, std::abs(p.ixy), std::abs(p.ixz), std::abs(p.iyz)}) > largest)
    throw std::invalid_argument(where + "the inertia has a component beyond " + number(largest) + " kg m^2");

  urdf::LinkSharedPtr l;
  in_->description.model->getLink(link, l);
  std::string note;
  auto inertial = l && l->inertial ? std::make_shared<urdf::Inertial>(*l->inertial) : std::make_shared<urdf::Inertial>();
  const urdf::Vector3& old_com = inertial->origin.position;
  if (std::max({std::abs(p.com.x - old_com.x), std::abs(p.com.y - old_com.y), std::abs(p.com.z - old_com.z)}) > 1e-9)
  {
    std::ostringstream text;
    text << " The link's centre of mass stays at " << old_com.x << " " << old_com.y << " " << old_com.z
         << " (a new one would move the body frame its colliders, visuals and sensors hang from).";
    note += text.str();
  }
  inertial->mass = p.mass;
  inertial->ixx = p.ixx;
  inertial->ixy = p.ixy;
  inertial->ixz = p.ixz;
  inertial->iyy = p.iyy;
  inertial->iyz = p.iyz;
  inertial->izz = p.izz;
  if (l)
    l->inertial = inertial;  // a new object: other holders of the old one keep theirs
  in_->description.link_physics[link].gravity = p.gravity;
  updateBodyMass(*in_, placed->second.first, note);
  wakeUp(*in_->multibody.bullet);
  if (!note.empty() && note[0] == ' ')
    note.erase(0, 1);
  return note;
}

}  // namespace bullet_plant
