// diff_drive_controller/DiffDriveController (ros_controllers, Noetic): a geometry_msgs/Twist on
// cmd_vel to the speeds of the left and right wheel joints (VelocityJointInterface, any number per
// side), odometry from the wheels' mean positions on odom and /tf (docs/interfaces.md section 12).
#include "control/drive_odometry.h"

#include <cmath>

namespace bullet_plant
{
namespace
{
class DiffDriveController : public TwistDriveController
{
public:
  bool init(ControllerContext& c) override
  {
    std::vector<std::string> left, right;
    if (!wheelNames(c, "left_wheel", left) || !wheelNames(c, "right_wheel", right))
      return false;
    if (left.size() != right.size())
    {
      c.log.error("#left wheels (" + std::to_string(left.size()) + ") != #right wheels (" +
                  std::to_string(right.size()) + ").");
      return false;
    }
    readDriveParams(c);
    separation_multiplier_ = paramNumber(c, "wheel_separation_multiplier", 1.0);
    const double radius_multiplier = paramNumber(c, "wheel_radius_multiplier", 1.0);
    left_radius_multiplier_ = paramNumber(c, "left_wheel_radius_multiplier", radius_multiplier);
    right_radius_multiplier_ = paramNumber(c, "right_wheel_radius_multiplier", radius_multiplier);

    const Param* separation = param(c, "wheel_separation");
    const Param* radius = param(c, "wheel_radius");
    const bool need_separation = !(separation && separation->isNumber()), need_radius = !(radius && radius->isNumber());
    separation_ = need_separation ? 0.0 : separation->asDouble();
    radius_ = need_radius ? 0.0 : radius->asDouble();
    if ((need_separation || need_radius) && !geometryFromUrdf(c, left[0], right[0], need_separation, need_radius))
      return false;

    if (!readOdometry(c))
      return false;

    ClaimedResources claimed{interfaceName(JointInterface::Velocity), {}};
    for (auto [names, handles] : {std::make_pair(&left, &left_), std::make_pair(&right, &right_)})
      for (const std::string& name : *names)
      {
        JointHandle* h = c.joints.handle(name);
        if (!h || h->interface() != JointInterface::Velocity)
        {
          c.log.error("Exception thrown while initializing controller '" + c.ns.substr(c.ns.rfind('/') + 1) +
                      "'.\nCould not find resource '" + name + "' in '" + interfaceName(JointInterface::Velocity) + "'.");
          return false;
        }
        handles->push_back(h);
        claimed.resources.push_back(name);
      }
    claimed_.assign(1, claimed);
    openPorts();
    return true;
  }

private:
  double separation() const { return separation_multiplier_ * separation_; }
  double leftRadius() const { return left_radius_multiplier_ * radius_; }
  double rightRadius() const { return right_radius_multiplier_ * radius_; }

  void drive(double linear, double angular) override
  {
    const double left_speed = (linear - angular * separation() / 2.0) / leftRadius();
    const double right_speed = (linear + angular * separation() / 2.0) / rightRadius();
    for (JointHandle* h : left_)
      h->setCommand(left_speed);
    for (JointHandle* h : right_)
      h->setCommand(right_speed);
  }

  void brake() override
  {
    for (JointHandle* h : left_)
      h->setCommand(0.0);
    for (JointHandle* h : right_)
      h->setCommand(0.0);
  }

  void restartMeasurement() override { has_wheel_positions_ = false; }

  // left_wheel / right_wheel: a joint name or a list of them; upstream's error texts.
  static bool wheelNames(ControllerContext& c, const std::string& key, std::vector<std::string>& out)
  {
    const Param* p = param(c, key);
    if (!p)
    {
      c.log.error("Couldn't retrieve wheel param '" + key + "'.");
      return false;
    }
    if (p->type() == Param::Type::String)
    {
      out.push_back(p->asString());
      return true;
    }
    if (p->type() != Param::Type::List)
    {
      c.log.error("Wheel param '" + key + "' is neither a list of strings nor a string.");
      return false;
    }
    if (p->asList().empty())
    {
      c.log.error("Wheel param '" + key + "' is an empty list");
      return false;
    }
    for (size_t i = 0; i < p->asList().size(); ++i)
    {
      if (p->asList()[i].type() != Param::Type::String)
      {
        c.log.error("Wheel param '" + key + "' #" + std::to_string(i) + " isn't a string.");
        return false;
      }
      out.push_back(p->asList()[i].asString());
    }
    return true;
  }

  // wheel_separation: the distance between the first left and right wheel joints' origins in their
  // parents; wheel_radius: the first left wheel link's collision cylinder or sphere.
  bool geometryFromUrdf(ControllerContext& c, const std::string& left, const std::string& right, bool need_separation,
                        bool need_radius)
  {
    urdf::ModelInterfaceSharedPtr model = robotModel(c);
    if (!model)
      return false;
    urdf::JointConstSharedPtr left_joint = model->getJoint(left), right_joint = model->getJoint(right);
    for (auto [joint, name] : {std::make_pair(left_joint, left), std::make_pair(right_joint, right)})
      if (!joint && (need_separation || name == left))
      {
        c.log.error(name + " couldn't be retrieved from model description");
        return false;
      }
    if (need_separation)
    {
      const urdf::Vector3 a = left_joint->parent_to_joint_origin_transform.position;
      const urdf::Vector3 b = right_joint->parent_to_joint_origin_transform.position;
      separation_ = std::sqrt((a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y) + (a.z - b.z) * (a.z - b.z));
    }
    if (need_radius)
    {
      urdf::LinkConstSharedPtr link = model->getLink(left_joint->child_link_name);
      const urdf::Geometry* g = link && link->collision ? link->collision->geometry.get() : nullptr;
      if (g && g->type == urdf::Geometry::CYLINDER)
        radius_ = static_cast<const urdf::Cylinder*>(g)->radius;
      else if (g && g->type == urdf::Geometry::SPHERE)
        radius_ = static_cast<const urdf::Sphere*>(g)->radius;
      else
      {
        c.log.error("Wheel link " + left_joint->child_link_name + " is NOT modeled as a cylinder or sphere!");
        c.log.error("Couldn't retrieve " + left + " wheel radius");
        return false;
      }
    }
    return true;
  }

  // The wheels' mean travel since the last update; the first update after a start takes the wheels
  // where they are (upstream counts their whole travel since the robot was made as one jump).
  void measureOdometry(int64_t time_ns) override
  {
    double left = 0.0, right = 0.0;
    for (size_t i = 0; i < left_.size(); ++i)
    {
      left += left_[i]->position();
      right += right_[i]->position();
    }
    left = left / double(left_.size()) * leftRadius();
    right = right / double(right_.size()) * rightRadius();
    const double dl = has_wheel_positions_ ? left - left_position_ : 0.0;
    const double dr = has_wheel_positions_ ? right - right_position_ : 0.0;
    left_position_ = left;
    right_position_ = right;
    has_wheel_positions_ = true;
    odometry_.update((dr + dl) * 0.5, (dr - dl) / separation(), time_ns);
  }

  std::vector<JointHandle*> left_, right_;
  double separation_ = 0, radius_ = 0;
  double separation_multiplier_ = 1, left_radius_multiplier_ = 1, right_radius_multiplier_ = 1;
  double left_position_ = 0, right_position_ = 0;
  bool has_wheel_positions_ = false;
};
}  // namespace

ROS_CONTROLLER_TYPE(diff_drive, "diff_drive_controller/DiffDriveController", controllerFactory<DiffDriveController>());

}  // namespace bullet_plant
