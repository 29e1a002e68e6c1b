// sensors::ForceTorqueSensor (gazebo/sensors/ForceTorqueSensor.hh).
#include "gazebo/sensors/ForceTorqueSensor.hh"

#include <boost/algorithm/string/replace.hpp>

#include "gazebo/common/Console.hh"
#include "gazebo/msgs/msgs.hh"
#include "gazebo/physics/Joint.hh"
#include "gazebo/physics/Model.hh"
#include "gazebo/physics/World.hh"
#include "gazebo/transport/Node.hh"
#include "gazebo/transport/Publisher.hh"

namespace gazebo
{
namespace sensors
{
namespace
{
// MODEL::JOINT's joint in the world; null where there is none (the model says why).
physics::JointPtr jointNamed(const physics::WorldPtr& world, const std::string& scoped)
{
  const size_t scope = scoped.rfind("::");
  if (!world || scope == std::string::npos)
    return nullptr;
  const physics::ModelPtr model = world->ModelByName(scoped.substr(0, scope));
  return model ? model->GetJoint(scoped.substr(scope + 2)) : nullptr;
}
}  // namespace

ForceTorqueSensor::ForceTorqueSensor() : Sensor(OTHER) {}

ForceTorqueSensor::~ForceTorqueSensor() = default;

std::string ForceTorqueSensor::Topic() const
{
  std::string topic = "~/" + ParentName() + "/" + Name() + "/wrench";
  boost::replace_all(topic, "::", "/");
  return topic;
}

void ForceTorqueSensor::Load(const std::string& _worldName)
{
  Sensor::Load(_worldName);
  joint_ = jointNamed(world, ParentName());
  if (!joint_)
  {
    gzerr << "Parent of a force torque sensor[" << Name() << "] Must be a joint\n";
    return;
  }
  pub_ = node->Advertise<msgs::WrenchStamped>(Topic());
}

void ForceTorqueSensor::Load(const std::string& _worldName, sdf::ElementPtr _sdf)
{
  Sensor::Load(_worldName, _sdf);
  // (sensor.sdf gives it, with its defaults, where the <sensor> has none)
  const sdf::ElementPtr element = sdf->GetElement("force_torque");
  const std::string frame = element->Get<std::string>("frame");
  if (frame == "parent")
    frame_ = MeasureFrame::PARENT_LINK;
  else if (frame == "child")
    frame_ = MeasureFrame::CHILD_LINK;
  else if (frame == "sensor")
    frame_ = MeasureFrame::SENSOR;
  else
  {
    gzwarn << "ignoring unknown force_torque frame '" << frame << "', using default value\n";
    frame_ = MeasureFrame::CHILD_LINK;
  }
  const std::string direction = element->Get<std::string>("measure_direction");
  if (direction == "parent_to_child" || direction == "child_to_parent")
    parent_to_child_ = direction == "parent_to_child";
  else
  {
    gzwarn << "ignoring unknown force_torque measure_direction \"" << direction << "\", using default value\n";
    parent_to_child_ = false;
  }
  // the sensor's axes in the child link's: its pose in the joint's frame, that in the child's
  if (joint_)
    rotation_sensor_child_ = ignition::math::Matrix3d((pose + joint_->InitialAnchorPose()).Rot().Inverse());
}

void ForceTorqueSensor::Init()
{
  Sensor::Init();
  if (joint_)
    joint_->SetProvideFeedback(true);
}

void ForceTorqueSensor::Fini()
{
  pub_.reset();
  joint_.reset();
  Sensor::Fini();
}

physics::JointPtr ForceTorqueSensor::Joint() const { return joint_; }

ignition::math::Vector3d ForceTorqueSensor::Force() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return msgs::ConvertIgn(message_.wrench().force());
}

ignition::math::Vector3d ForceTorqueSensor::Torque() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return msgs::ConvertIgn(message_.wrench().torque());
}

bool ForceTorqueSensor::UpdateImpl(const bool /*_force*/)
{
  if (!joint_)
    return false;
  const physics::JointWrench wrench = joint_->GetForceTorque(0u);
  // Gazebo's JointWrench: body2 what the child passes to the joint, in the child's axes; body1 what
  // the joint passes to the child, in the parent's
  const double sign = parent_to_child_ ? -1.0 : 1.0;
  ignition::math::Vector3d force, torque;
  switch (frame_)
  {
    case MeasureFrame::PARENT_LINK:
      force = -sign * wrench.body1Force;
      torque = -sign * wrench.body1Torque;
      break;
    case MeasureFrame::CHILD_LINK:
      force = sign * wrench.body2Force;
      torque = sign * wrench.body2Torque;
      break;
    case MeasureFrame::SENSOR:
      force = rotation_sensor_child_ * (sign * wrench.body2Force);
      torque = rotation_sensor_child_ * (sign * wrench.body2Torque);
      break;
  }
  msgs::WrenchStamped message;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    lastMeasurementTime = world->SimTime();
    msgs::Set(message_.mutable_time(), lastMeasurementTime);
    msgs::Set(message_.mutable_wrench()->mutable_force(), force);
    msgs::Set(message_.mutable_wrench()->mutable_torque(), torque);
    message = message_;
  }
  update_(message);
  if (pub_)
    pub_->Publish(message);
  return true;
}

bool ForceTorqueSensor::IsActive() const { return Sensor::IsActive() || (pub_ && pub_->HasConnections()); }

event::ConnectionPtr ForceTorqueSensor::ConnectUpdate(std::function<void(msgs::WrenchStamped)> _subscriber)
{
  return update_.Connect(_subscriber);
}
}  // namespace sensors
}  // namespace gazebo
