// ackermann_steering_controller/AckermannSteeringController: a geometry_msgs/Twist on cmd_vel to the
// rear wheel speed and the steering angle, its odometry on odom and /tf (docs/interfaces.md section 12).
#include "control/drive_odometry.h"

#include <cmath>
#include <tuple>

namespace bullet_plant
{
namespace
{
// ackermann_steering_controller/AckermannSteeringController: a bicycle model of one rear wheel
// (VelocityJointInterface) and one front steering joint (PositionJointInterface). cmd_vel's
// linear.x is the speed and angular.z the steering angle; odometry integrates the rear wheel's
// travel and the steering joint's angle.
class AckermannSteeringController : public TwistDriveController
{
public:
  bool init(ControllerContext& c) override
  {
    readDriveParams(c);
    const std::string rear_wheel = paramText(c, "rear_wheel", "rear_wheel_joint");
    const std::string front_steer = paramText(c, "front_steer", "front_steer_joint");
    const double separation_multiplier = paramNumber(c, "wheel_separation_h_multiplier", 1.0);
    const double radius_multiplier = paramNumber(c, "wheel_radius_multiplier", 1.0);
    steer_pos_multiplier_ = paramNumber(c, "steer_pos_multiplier", 1.0);

    const Param* separation = param(c, "wheel_separation_h");
    const Param* radius = param(c, "wheel_radius");
    separation_ = separation && separation->isNumber() ? separation->asDouble() : 0.0;
    wheel_radius_ = radius && radius->isNumber() ? radius->asDouble() : 0.0;
    if (!(separation && separation->isNumber() && radius && radius->isNumber()) &&
        !geometryFromUrdf(c, rear_wheel, front_steer, !(separation && separation->isNumber()),
                          !(radius && radius->isNumber())))
      return false;
    odometry_separation_ = separation_multiplier * separation_;
    odometry_radius_ = radius_multiplier * wheel_radius_;

    if (!readOdometry(c))
      return false;

    rear_wheel_ = c.joints.handle(rear_wheel);
    front_steer_ = c.joints.handle(front_steer);
    for (auto [handle, name, iface] : {std::make_tuple(rear_wheel_, rear_wheel, JointInterface::Velocity),
                                       std::make_tuple(front_steer_, front_steer, JointInterface::Position)})
      if (!handle || handle->interface() != iface)
      {
        c.log.error("Exception thrown while initializing controller '" + c.ns.substr(c.ns.rfind('/') + 1) +
                    "'.\nCould not find resource '" + name + "' in '" + interfaceName(iface) + "'.");
        return false;
      }
    claimed_ = {ClaimedResources{interfaceName(JointInterface::Position), {front_steer}},
                ClaimedResources{interfaceName(JointInterface::Velocity), {rear_wheel}}};
    openPorts();
    return true;
  }

private:
  void drive(double linear, double angular) override
  {
    rear_wheel_->setCommand(linear / wheel_radius_);
    front_steer_->setCommand(angular);
  }

  void brake() override
  {
    rear_wheel_->setCommand(0.0);
    front_steer_->setCommand(0.0);
  }

  void restartMeasurement() override { has_wheel_position_ = false; }

  // ros_controllers' ackermann odometry: the rear wheel's travel since the last update and the
  // steering angle give the increment.
  void measureOdometry(int64_t time_ns) override
  {
    const double wheel = rear_wheel_->position() * odometry_radius_;
    // The first update after a start takes the wheel where it is (upstream would count the
    // wheel's whole travel since the robot was made as one jump).
    const double linear = has_wheel_position_ ? wheel - wheel_position_ : 0.0;
    wheel_position_ = wheel;
    has_wheel_position_ = true;
    odometry_.update(linear, std::tan(front_steer_->position() * steer_pos_multiplier_) * linear / odometry_separation_,
                     time_ns);
  }

  // wheel_separation_h: the x distance between the two joints' origins in their parents; the
  // wheel radius: the rear wheel link's collision cylinder. Read from <manager ns>/robot_description.
  bool geometryFromUrdf(ControllerContext& c, const std::string& rear_wheel, const std::string& front_steer,
                        bool need_separation, bool need_radius)
  {
    urdf::ModelInterfaceSharedPtr model = robotModel(c);
    if (!model)
      return false;
    urdf::JointConstSharedPtr wheel = model->getJoint(rear_wheel), steer = model->getJoint(front_steer);
    if (!wheel || (need_separation && !steer))
    {
      c.log.error((!wheel ? rear_wheel : front_steer) + " couldn't be retrieved from model description");
      return false;
    }
    if (need_separation)
      separation_ = std::abs(wheel->parent_to_joint_origin_transform.position.x -
                             steer->parent_to_joint_origin_transform.position.x);
    if (need_radius)
    {
      urdf::LinkConstSharedPtr link = model->getLink(wheel->child_link_name);
      if (!link || !link->collision || !link->collision->geometry ||
          link->collision->geometry->type != urdf::Geometry::CYLINDER)
      {
        c.log.error("Wheel link " + wheel->child_link_name + " is NOT modeled as a cylinder!");
        c.log.error("Couldn't retrieve " + rear_wheel + " wheel radius");
        return false;
      }
      wheel_radius_ = static_cast<const urdf::Cylinder&>(*link->collision->geometry).radius;
    }
    return true;
  }

  JointHandle *rear_wheel_ = nullptr, *front_steer_ = nullptr;
  double separation_ = 0, wheel_radius_ = 0, odometry_separation_ = 0, odometry_radius_ = 0;
  double steer_pos_multiplier_ = 1;
  double wheel_position_ = 0;
  bool has_wheel_position_ = false;
};
}  // namespace

ROS_CONTROLLER_TYPE(ackermann_steering, "ackermann_steering_controller/AckermannSteeringController",
                    controllerFactory<AckermannSteeringController>());

}  // namespace bullet_plant
