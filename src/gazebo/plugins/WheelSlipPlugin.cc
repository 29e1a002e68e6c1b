// Gazebo's WheelSlipPlugin (gazebo/plugins/WheelSlipPlugin.hh): its elements, errors, topics and
// slip law as Gazebo 11's plugin has them. The slips go to the wheel's collision's ODESurfaceParams,
// which the plant's solver takes at the start of each step (docs/gazebo_api.md, Collision).
#include "gazebo/plugins/WheelSlipPlugin.hh"

#include <cmath>
#include <functional>
#include <mutex>
#include <vector>

#include "gazebo/common/Console.hh"
#include "gazebo/common/Events.hh"
#include "gazebo/physics/Collision.hh"
#include "gazebo/physics/Joint.hh"
#include "gazebo/physics/Link.hh"
#include "gazebo/physics/Model.hh"
#include "gazebo/physics/Shape.hh"
#include "gazebo/physics/World.hh"
#include "gazebo/physics/ode/ODESurfaceParams.hh"
#include "gazebo/transport/transport.hh"

namespace gazebo
{
GZ_REGISTER_MODEL_PLUGIN(WheelSlipPlugin)

class WheelSlipPluginPrivate
{
public:
  struct Wheel
  {
    boost::weak_ptr<physics::Link> link;
    boost::weak_ptr<physics::Joint> joint;  // its spin joint
    boost::weak_ptr<physics::ODESurfaceParams> surface;
    double slipComplianceLateral = 0.0;
    double slipComplianceLongitudinal = 0.0;
    double wheelNormalForce = 0.0;
    double wheelRadius = 0.0;
    transport::PublisherPtr slipPub;
  };

  // The gravity's direction in the model's frame at Load: what "down" is for the rolling direction.
  ignition::math::Vector3d initialGravityDirection;
  boost::weak_ptr<physics::Model> model;
  // Guards the wheels' compliances and friction, which transport and ROS callbacks change.
  mutable std::mutex mutex;
  std::map<std::string, Wheel> wheels;  // by link name
  transport::NodePtr node;
  transport::SubscriberPtr lateralComplianceSub;
  transport::SubscriberPtr longitudinalComplianceSub;
  event::ConnectionPtr updateConnection;
};

namespace
{
// The wheel's radius from its collision's shape (a cylinder's or a sphere's), 0 for another shape.
double shapeRadius(const physics::CollisionPtr& collision)
{
  const physics::ShapePtr shape = collision->GetShape();
  if (shape->HasType(physics::Base::CYLINDER_SHAPE))
    return boost::dynamic_pointer_cast<physics::CylinderShape>(shape)->GetRadius();
  if (shape->HasType(physics::Base::SPHERE_SHAPE))
    return boost::dynamic_pointer_cast<physics::SphereShape>(shape)->GetRadius();
  return 0.0;
}
}  // namespace

WheelSlipPlugin::WheelSlipPlugin() : dataPtr(new WheelSlipPluginPrivate) {}

WheelSlipPlugin::~WheelSlipPlugin() { Fini(); }

void WheelSlipPlugin::Fini()
{
  this->dataPtr->updateConnection.reset();
  this->dataPtr->lateralComplianceSub.reset();
  this->dataPtr->longitudinalComplianceSub.reset();
  for (auto& wheel : this->dataPtr->wheels)
    wheel.second.slipPub.reset();
  if (this->dataPtr->node)
    this->dataPtr->node->Fini();
}

void WheelSlipPlugin::Load(physics::ModelPtr _model, sdf::ElementPtr _sdf)
{
  if (!_model || !_sdf)
  {
    gzerr << "WheelSlipPlugin: loaded without its model or its <plugin> element, plugin is disabled" << std::endl;
    return;
  }
  this->dataPtr->model = _model;
  const physics::WorldPtr world = _model->GetWorld();
  this->dataPtr->initialGravityDirection =
      _model->WorldPose().Rot().RotateVectorReverse(world->Gravity().Normalized());

  if (!_sdf->HasElement("wheel"))
  {
    gzerr << "No wheel tags specified, plugin is disabled" << std::endl;
    return;
  }
  const std::string scoped = _model->GetScopedName();
  for (sdf::ElementPtr element = _sdf->GetElement("wheel"); element; element = element->GetNextElement("wheel"))
  {
    if (!element->HasAttribute("link_name"))
    {
      gzerr << "wheel element missing link_name attribute" << std::endl;
      continue;
    }
    const std::string linkName = element->Get<std::string>("link_name");
    WheelSlipPluginPrivate::Wheel wheel;
    auto number = [&](const char* name, double& value) {
      if (element->HasElement(name))
        value = element->Get<double>(name);
    };
    number("slip_compliance_lateral", wheel.slipComplianceLateral);
    number("slip_compliance_longitudinal", wheel.slipComplianceLongitudinal);
    number("wheel_normal_force", wheel.wheelNormalForce);
    number("wheel_radius", wheel.wheelRadius);

    const physics::LinkPtr link = _model->GetLink(linkName);
    if (!link)
    {
      gzerr << "Could not find link named [" << linkName << "] in model [" << scoped << "]" << std::endl;
      continue;
    }
    const physics::Collision_V collisions = link->GetCollisions();
    if (collisions.size() != 1)
    {
      gzerr << "There should be 1 collision in link named [" << linkName << "] in model [" << scoped << "], but "
            << collisions.size() << " were found" << std::endl;
      continue;
    }
    const physics::CollisionPtr collision = collisions.front();
    const auto surface = boost::dynamic_pointer_cast<physics::ODESurfaceParams>(collision->GetSurface());
    if (!surface)
    {
      gzerr << "Could not find ODE Surface in collision named [" << collision->GetName() << "] in link named ["
            << linkName << "] in model [" << scoped << "]" << std::endl;
      continue;
    }
    wheel.surface = surface;
    const physics::Joint_V joints = link->GetParentJoints();
    if (joints.size() != 1)
    {
      gzerr << "There should be 1 parent joint for link named [" << linkName << "] in model [" << scoped
            << "], but " << joints.size() << " were found" << std::endl;
      continue;
    }
    wheel.joint = joints.front();
    if (wheel.wheelRadius <= 0)
      wheel.wheelRadius = shapeRadius(collision);
    if (wheel.wheelRadius <= 0)
    {
      gzerr << "Found wheel radius [" << wheel.wheelRadius << "], which is not positive in link named [" << linkName
            << "] in model [" << scoped << "]" << std::endl;
      continue;
    }
    if (wheel.wheelNormalForce <= 0)
    {
      gzerr << "Found wheel normal force [" << wheel.wheelNormalForce << "], which is not positive in link named ["
            << linkName << "] in model [" << scoped << "]" << std::endl;
      continue;
    }
    wheel.link = link;
    this->dataPtr->wheels[linkName] = wheel;
  }
  if (this->dataPtr->wheels.empty())
  {
    gzerr << "No ODE links and surfaces found, plugin is disabled" << std::endl;
    return;
  }

  this->dataPtr->node = transport::NodePtr(new transport::Node());
  this->dataPtr->node->Init(world->Name());
  const std::string prefix = "~/" + _model->GetName() + "/wheel_slip/";
  for (auto& wheel : this->dataPtr->wheels)
    wheel.second.slipPub = this->dataPtr->node->Advertise<msgs::Vector3d>(prefix + wheel.first);
  this->dataPtr->lateralComplianceSub =
      this->dataPtr->node->Subscribe(prefix + "lateral_compliance", &WheelSlipPlugin::OnLateralCompliance, this);
  this->dataPtr->longitudinalComplianceSub = this->dataPtr->node->Subscribe(
      prefix + "longitudinal_compliance", &WheelSlipPlugin::OnLongitudinalCompliance, this);
  this->dataPtr->updateConnection = event::Events::ConnectWorldUpdateBegin(std::bind(&WheelSlipPlugin::Update, this));
}

physics::ModelPtr WheelSlipPlugin::GetParentModel() const { return this->dataPtr->model.lock(); }

void WheelSlipPlugin::GetSlips(std::map<std::string, ignition::math::Vector3d>& _out) const
{
  const physics::ModelPtr model = GetParentModel();
  if (!model)
  {
    gzerr << "Parent model does not exist" << std::endl;
    return;
  }
  const ignition::math::Quaterniond modelRot = model->WorldPose().Rot();
  std::lock_guard<std::mutex> lock(this->dataPtr->mutex);
  for (const auto& entry : this->dataPtr->wheels)
  {
    const physics::LinkPtr link = entry.second.link.lock();
    const physics::JointPtr joint = entry.second.joint.lock();
    if (!link || !joint)
      continue;
    // In the model's frame: the wheel's velocity, its spin axis, and the rolling direction (down
    // crossed with the axis).
    const ignition::math::Vector3d velocity = modelRot.RotateVectorReverse(link->WorldLinearVel());
    const ignition::math::Vector3d axis = modelRot.RotateVectorReverse(joint->GlobalAxis(0).Normalized());
    const ignition::math::Vector3d rolling = this->dataPtr->initialGravityDirection.Cross(axis);
    const double spinSpeed = entry.second.wheelRadius * joint->GetVelocity(0);
    _out[entry.first] = {rolling.Dot(velocity) - spinSpeed, axis.Dot(velocity), spinSpeed};
  }
}

void WheelSlipPlugin::OnLateralCompliance(ConstGzStringPtr& _msg)
{
  try
  {
    SetSlipComplianceLateral(std::stod(_msg->data()));
  }
  catch (...)
  {
    gzerr << "Invalid slip compliance data[" << _msg->data() << "]\n";
  }
}

void WheelSlipPlugin::OnLongitudinalCompliance(ConstGzStringPtr& _msg)
{
  try
  {
    SetSlipComplianceLongitudinal(std::stod(_msg->data()));
  }
  catch (...)
  {
    gzerr << "Invalid slip compliance data[" << _msg->data() << "]\n";
  }
}

void WheelSlipPlugin::SetSlipComplianceLateral(const double _compliance)
{
  std::lock_guard<std::mutex> lock(this->dataPtr->mutex);
  for (auto& wheel : this->dataPtr->wheels)
    wheel.second.slipComplianceLateral = _compliance;
}

void WheelSlipPlugin::SetSlipComplianceLateral(std::string _wheel_name, const double _compliance)
{
  std::lock_guard<std::mutex> lock(this->dataPtr->mutex);
  auto wheel = this->dataPtr->wheels.find(_wheel_name);
  if (wheel != this->dataPtr->wheels.end())
    wheel->second.slipComplianceLateral = _compliance;
}

void WheelSlipPlugin::SetSlipComplianceLongitudinal(const double _compliance)
{
  std::lock_guard<std::mutex> lock(this->dataPtr->mutex);
  for (auto& wheel : this->dataPtr->wheels)
    wheel.second.slipComplianceLongitudinal = _compliance;
}

void WheelSlipPlugin::SetSlipComplianceLongitudinal(std::string _wheel_name, const double _compliance)
{
  std::lock_guard<std::mutex> lock(this->dataPtr->mutex);
  auto wheel = this->dataPtr->wheels.find(_wheel_name);
  if (wheel != this->dataPtr->wheels.end())
    wheel->second.slipComplianceLongitudinal = _compliance;
}

std::map<std::string, ignition::math::Vector2d> WheelSlipPlugin::GetFrictionCoefficients()
{
  std::map<std::string, ignition::math::Vector2d> out;
  std::lock_guard<std::mutex> lock(this->dataPtr->mutex);
  for (const auto& wheel : this->dataPtr->wheels)
    if (const auto surface = wheel.second.surface.lock())
      out[wheel.first] = {surface->FrictionPyramid()->MuPrimary(), surface->FrictionPyramid()->MuSecondary()};
  return out;
}

bool WheelSlipPlugin::SetMuPrimary(const std::string& _wheel_name, double _mu)
{
  std::lock_guard<std::mutex> lock(this->dataPtr->mutex);
  auto wheel = this->dataPtr->wheels.find(_wheel_name);
  const auto surface = wheel != this->dataPtr->wheels.end() ? wheel->second.surface.lock() : nullptr;
  if (!surface)
    return false;
  surface->FrictionPyramid()->SetMuPrimary(_mu);
  return true;
}

bool WheelSlipPlugin::SetMuSecondary(const std::string& _wheel_name, double _mu)
{
  std::lock_guard<std::mutex> lock(this->dataPtr->mutex);
  auto wheel = this->dataPtr->wheels.find(_wheel_name);
  const auto surface = wheel != this->dataPtr->wheels.end() ? wheel->second.surface.lock() : nullptr;
  if (!surface)
    return false;
  surface->FrictionPyramid()->SetMuSecondary(_mu);
  return true;
}

void WheelSlipPlugin::Update()
{
  std::map<std::string, ignition::math::Vector3d> slips;
  GetSlips(slips);
  std::lock_guard<std::mutex> lock(this->dataPtr->mutex);
  for (auto& entry : this->dataPtr->wheels)
  {
    const WheelSlipPluginPrivate::Wheel& wheel = entry.second;
    const physics::LinkPtr link = wheel.link.lock();
    const physics::JointPtr joint = wheel.joint.lock();
    const auto surface = wheel.surface.lock();
    if (surface && link && joint)
    {
      // ODE's slips are m/s per N: the unitless compliances scaled by the rolling speed (r |w|, the
      // slip ratio's denominator when driving, tamer at rest than the braking form) over the
      // normal force the wheel is said to carry.
      const double spin = link->WorldAngularVel().Dot(joint->GlobalAxis(0));
      const double speed = wheel.wheelRadius * std::abs(spin);
      surface->slip1 = speed / wheel.wheelNormalForce * wheel.slipComplianceLateral;
      surface->slip2 = speed / wheel.wheelNormalForce * wheel.slipComplianceLongitudinal;
    }
    if (link && wheel.slipPub)
      wheel.slipPub->Publish(msgs::Convert(slips[entry.first]));
  }
}
}  // namespace gazebo
