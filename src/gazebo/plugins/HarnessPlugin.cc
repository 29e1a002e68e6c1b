// Gazebo's HarnessPlugin (gazebo/plugins/HarnessPlugin.hh): its elements, defaults, messages and
// winch law as Gazebo 11's plugin has them (the velocity PID's force only ever lifts; a target speed
// of 0 holds the joint where it was). Differs where Gazebo's would break: Detach and the targets may
// come from any thread (the transport's, ROS's) and are taken under the physics update mutex; a
// second Detach, or one after the winch's joint is gone, is a warning, where Gazebo's dereferences
// the joint it dropped.
#include "gazebo/plugins/HarnessPlugin.hh"

#include <algorithm>
#include <functional>

#include <ignition/math/Helpers.hh>

#include "gazebo/common/Console.hh"
#include "gazebo/common/Events.hh"
#include "gazebo/physics/Joint.hh"
#include "gazebo/physics/Model.hh"
#include "gazebo/physics/PhysicsEngine.hh"
#include "gazebo/physics/World.hh"
#include "gazebo/transport/transport.hh"

namespace gazebo
{
GZ_REGISTER_MODEL_PLUGIN(HarnessPlugin)

namespace
{
// The physics update mutex of `world`, held: what changes or reads the joints from another thread
// waits for the step in progress to end.
std::unique_lock<boost::recursive_mutex> betweenSteps(const physics::WorldPtr& world)
{
  return world ? std::unique_lock<boost::recursive_mutex>(*world->Physics()->GetPhysicsUpdateMutex())
               : std::unique_lock<boost::recursive_mutex>();
}

// A <pos_pid> or <vel_pid>: p, i, d, i_max, i_min, cmd_max, cmd_min, each 0 where not given.
void loadPid(const sdf::ElementPtr& element, common::PID& pid)
{
  auto gain = [&](const char* name) { return element->HasElement(name) ? element->Get<double>(name) : 0.0; };
  pid.Init(gain("p"), gain("i"), gain("d"), gain("i_max"), gain("i_min"), gain("cmd_max"), gain("cmd_min"));
}
}  // namespace

HarnessPlugin::HarnessPlugin() = default;

HarnessPlugin::~HarnessPlugin()
{
  // No update or message may come to a plugin that is going.
  this->updateConnection.reset();
  this->velocitySub.reset();
  this->detachSub.reset();
}

void HarnessPlugin::Load(physics::ModelPtr _model, sdf::ElementPtr _sdf)
{
  if (!_model || !_sdf)
  {
    gzerr << "HarnessPlugin: loaded without its model or its <plugin> element; the harness plugin will not run.\n";
    return;
  }
  this->world = _model->GetWorld();
  this->node = transport::NodePtr(new transport::Node());
  this->node->Init(this->world->Name());
  this->velocitySub =
      this->node->Subscribe("~/" + _model->GetName() + "/harness/velocity", &HarnessPlugin::OnVelocity, this);
  this->detachSub = this->node->Subscribe("~/" + _model->GetName() + "/harness/detach", &HarnessPlugin::OnDetach, this);

  for (sdf::ElementPtr jointElem = _sdf->HasElement("joint") ? _sdf->GetElement("joint") : sdf::ElementPtr(); jointElem;
       jointElem = jointElem->GetNextElement("joint"))
  {
    const std::string jointName = jointElem->HasAttribute("name") ? jointElem->Get<std::string>("name") : "";
    const std::string jointType = jointElem->HasAttribute("type") ? jointElem->Get<std::string>("type") : "";
    physics::JointPtr joint = this->world->Physics()->CreateJoint(jointType, _model);
    if (!joint)
    {
      gzerr << "Unable to create joint[" << jointName << "]\n";
      continue;
    }
    joint->SetModel(_model);
    joint->Load(jointElem);
    this->joints.push_back(joint);
  }
  if (this->joints.empty())
  {
    gzerr << "No joints specified in the harness plugin.The harness plugin will not run." << std::endl;
    return;
  }

  // A joint named by `element`'s child `child`: its index, or the first joint with Gazebo's warning
  // (`missing` where the child is absent; `invalid`, the name put at its %, where it names no joint).
  auto jointNamed = [this](const sdf::ElementPtr& element, const char* child, const std::string& missing,
                           const std::string& invalid) {
    if (!element->HasElement(child))
    {
      gzwarn << missing << std::endl;
      return 0;
    }
    const std::string name = element->Get<std::string>(child);
    const int index = this->JointIndex(name);
    if (index < 0)
      gzwarn << "Invalid " << invalid.substr(0, invalid.find('%')) << name << invalid.substr(invalid.find('%') + 1)
             << std::endl;
    return std::max(index, 0);
  };
  this->detachIndex = jointNamed(_sdf, "detach",
                                 "A <detach> element is missing from the harness plugin. The first joint will be "
                                 "used as the detach joint.",
                                 "<detach> joint name[%] in the harness plugin. The first joint will be used as "
                                 "the detach joint.");
  if (!_sdf->HasElement("winch"))
  {
    gzwarn << "A <winch> element is missing from the harness plugin. The first joint will be used as the winch."
           << std::endl;
    return;
  }
  const sdf::ElementPtr winchElem = _sdf->GetElement("winch");
  this->winchIndex = jointNamed(winchElem, "joint",
                                "A <winch><joint>joint_name</joint></winch> element is missing from the harness "
                                "plugin.\nThe first joint will be used as the winch.",
                                "<joint> name[%] in the <winch> element of the harness plugin.\nThe first joint "
                                "will be used as the winch.");
  if (winchElem->HasElement("pos_pid"))
    loadPid(winchElem->GetElement("pos_pid"), this->winchPosPID);
  if (winchElem->HasElement("vel_pid"))
    loadPid(winchElem->GetElement("vel_pid"), this->winchVelPID);
}

void HarnessPlugin::Init()
{
  for (const physics::JointPtr& joint : this->joints)
    joint->Init();
  if (!this->joints.empty())
    this->updateConnection =
        event::Events::ConnectWorldUpdateBegin(std::bind(&HarnessPlugin::OnUpdate, this, std::placeholders::_1));
}

void HarnessPlugin::OnUpdate(const common::UpdateInfo& _info)
{
  std::lock_guard<std::recursive_mutex> lock(this->mutex);
  // The first update only starts the clock, as Gazebo's.
  if (this->prevSimTime == common::Time::Zero)
  {
    this->prevSimTime = _info.simTime;
    return;
  }
  const common::Time dt = _info.simTime - this->prevSimTime;
  this->prevSimTime = _info.simTime;
  if (this->winchIndex < 0 || !this->joints[this->winchIndex])
    return;
  const physics::JointPtr& winch = this->joints[this->winchIndex];
  // Hold the position where the target speed is 0; always follow the target speed.
  const double pError = ignition::math::equal(this->winchTargetVel, 0.0f) ? winch->Position(0) - this->winchTargetPos : 0.0;
  const double vError = winch->GetVelocity(0) - this->winchTargetVel;
  const double winchPosForce = this->winchPosPID.Update(pError, dt);
  // The velocity's force only lifts, as Gazebo's (its cmd_min and cmd_max can say the same).
  const double winchVelForce = std::max(0.0, this->winchVelPID.Update(vError, dt));
  winch->SetForce(0, winchVelForce + winchPosForce);
}

void HarnessPlugin::SetWinchVelocity(const float _value)
{
  const auto between_steps = betweenSteps(this->world);
  std::lock_guard<std::recursive_mutex> lock(this->mutex);
  this->winchTargetVel = _value;
  if (ignition::math::equal(_value, 0.0f) && this->winchIndex >= 0 &&
      this->winchIndex < static_cast<int>(this->joints.size()) && this->joints[this->winchIndex])
  {
    // A speed of 0 holds the winch where it is now.
    this->winchTargetPos = static_cast<float>(this->joints[this->winchIndex]->Position(0));
    this->winchPosPID.Reset();
  }
}

double HarnessPlugin::WinchVelocity() const
{
  std::lock_guard<std::recursive_mutex> lock(this->mutex);
  if (this->winchIndex < 0 || this->winchIndex >= static_cast<int>(this->joints.size()) ||
      !this->joints[this->winchIndex])
    return 0.0;
  return this->joints[this->winchIndex]->GetVelocity(0);
}

void HarnessPlugin::Detach()
{
  // Between steps: the joint's constraint leaves the physics, which a step must not see happen.
  const auto between_steps = betweenSteps(this->world);
  std::lock_guard<std::recursive_mutex> lock(this->mutex);
  if (this->detachIndex < 0 || this->detachIndex >= static_cast<int>(this->joints.size()) ||
      !this->joints[this->detachIndex])
  {
    gzwarn << "HarnessPlugin: nothing to detach (the <detach> joint is gone already)" << std::endl;
    return;
  }
  this->joints[this->detachIndex]->Detach();
  this->joints[this->detachIndex].reset();
  // The winch stops with it, as Gazebo's (whose updates end here).
  this->updateConnection.reset();
  this->winchIndex = -1;
}

int HarnessPlugin::JointIndex(const std::string& _name) const
{
  for (size_t i = 0; i < this->joints.size(); ++i)
    if (this->joints[i] && this->joints[i]->GetName() == _name)
      return static_cast<int>(i);
  return -1;
}

void HarnessPlugin::OnVelocity(ConstGzStringPtr& _msg)
{
  try
  {
    this->SetWinchVelocity(std::stof(_msg->data()));
  }
  catch (...)
  {
    gzerr << "Invalid velocity data[" << _msg->data() << "]\n";
  }
}

void HarnessPlugin::OnDetach(ConstGzStringPtr& _msg)
{
  if (_msg->data() == "true" || _msg->data() == "TRUE" || _msg->data() == "True")
    this->Detach();
}
}  // namespace gazebo
