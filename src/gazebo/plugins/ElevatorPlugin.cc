// Gazebo's ElevatorPlugin (gazebo/plugins/ElevatorPlugin.hh): its parameters, defaults, gains and
// steps as Gazebo 11's plugin has them. Differs in two places, both said in docs/gazebo_api.md: the
// door's wait is counted in simulated time (Gazebo's counts the wall clock), and each PID's time
// step is the world's step (Gazebo's door PID is given the time since its first update).
#include "gazebo/plugins/ElevatorPlugin.hh"

#include <cmath>
#include <deque>
#include <functional>
#include <mutex>
#include <string>

#include "gazebo/common/Console.hh"
#include "gazebo/common/Events.hh"
#include "gazebo/common/PID.hh"
#include "gazebo/physics/Joint.hh"
#include "gazebo/physics/Model.hh"
#include "gazebo/physics/World.hh"
#include "gazebo/transport/transport.hh"

namespace gazebo
{
GZ_REGISTER_MODEL_PLUGIN(ElevatorPlugin)

namespace
{
// Drives a joint to a position by force through a PID, each world update; stationary within
// `tolerance` of it.
struct JointDrive
{
  JointDrive(double p, double i, double d, double tolerance) : pid(p, i, d), tolerance(tolerance) {}

  void update(const common::Time& simTime)
  {
    if (!joint)
      return;
    if (previous == common::Time::Zero)  // the first update only starts the clock, as Gazebo's
    {
      previous = simTime;
      return;
    }
    const double error = joint->Position() - target;
    joint->SetForce(0, pid.Update(error, simTime - previous));
    previous = simTime;
    stationary = std::abs(error) < tolerance;
  }

  void reset()
  {
    previous = common::Time::Zero;
    pid.Reset();
  }

  physics::JointPtr joint;
  common::PID pid;
  double tolerance;
  double target = 0.0;
  bool stationary = true;
  common::Time previous;
};

// One step of a trip: done once it returns true.
enum class Step
{
  CloseDoor,
  MoveCar,
  OpenDoor,
  WaitOpen
};
}  // namespace

class ElevatorPluginPrivate
{
public:
  // Gazebo's gains and tolerances: the door (p 2, d 1; within 0.05 of open = 1 or closed = 0), the
  // lift (p 100000, d 100000; within 0.15 m of its floor's height).
  JointDrive door{ 2.0, 0.0, 1.0, 0.05 };
  JointDrive lift{ 100000.0, 0.0, 100000.0, 0.15 };
  double floorHeight = 3.0;
  common::Time doorWaitTime{ 5, 0 };

  std::mutex stateMutex;
  std::deque<Step> steps;
  int floor = 0;
  bool stepStarted = false;
  common::Time waitUntil;

  event::ConnectionPtr updateConnection;
  transport::NodePtr node;
  transport::SubscriberPtr elevatorSub;

  // Starts the front step, or says whether it is done.
  bool advance(const common::Time& simTime)
  {
    const Step step = steps.front();
    if (!stepStarted)
    {
      stepStarted = true;
      if (step == Step::CloseDoor)
        door.target = 0.0;
      else if (step == Step::OpenDoor)
        door.target = 1.0;
      else if (step == Step::MoveCar)
        lift.target = floor * floorHeight;
      else
        waitUntil = simTime + doorWaitTime;
      return false;
    }
    if (step == Step::WaitOpen)
      return simTime >= waitUntil;
    return step == Step::MoveCar ? lift.stationary : door.stationary;
  }
};

ElevatorPlugin::ElevatorPlugin() : dataPtr(new ElevatorPluginPrivate) {}

ElevatorPlugin::~ElevatorPlugin()
{
  // No update or message may come to a plugin that is going.
  this->dataPtr->updateConnection.reset();
  this->dataPtr->elevatorSub.reset();
}

void ElevatorPlugin::Load(physics::ModelPtr _model, sdf::ElementPtr _sdf)
{
  if (!_model || !_sdf)
  {
    gzerr << "ElevatorPlugin: loaded without its model or its <plugin> element; the elevator plugin is disabled.\n";
    return;
  }
  ElevatorPluginPrivate& d = *this->dataPtr;
  if (_sdf->HasElement("door_wait_time"))
    d.doorWaitTime = common::Time(_sdf->Get<double>("door_wait_time"));
  const std::string topic = _sdf->HasElement("topic") ? _sdf->Get<std::string>("topic") : "~/elevator";
  if (_sdf->HasElement("floor_height"))
    d.floorHeight = _sdf->Get<double>("floor_height");
  else
    gzwarn << "No <floor_height> specified for elevator plugin. Using a height of 3 meters. This value may cause "
              "the elevator to move incorrectly.\n";

  const std::string liftJointName = _sdf->HasElement("lift_joint") ? _sdf->Get<std::string>("lift_joint") : "";
  d.lift.joint = _model->GetJoint(liftJointName);
  if (!d.lift.joint)
  {
    gzerr << "Unable to find lift joint[" << liftJointName << "].\nThe elevator plugin is disabled.\n";
    return;
  }
  const std::string doorJointName = _sdf->HasElement("door_joint") ? _sdf->Get<std::string>("door_joint") : "";
  d.door.joint = _model->GetJoint(doorJointName);
  if (!d.door.joint)
  {
    gzerr << "Unable to find door joint[" << doorJointName << "].\nThe elevator plugin is disabled.\n";
    return;
  }

  d.updateConnection =
      event::Events::ConnectWorldUpdateBegin(std::bind(&ElevatorPlugin::Update, this, std::placeholders::_1));
  d.node = transport::NodePtr(new transport::Node());
  d.node->Init(_model->GetWorld()->Name());
  d.elevatorSub = d.node->Subscribe(topic, &ElevatorPlugin::OnElevator, this);
}

void ElevatorPlugin::OnElevator(ConstGzStringPtr& _msg)
{
  try
  {
    this->MoveToFloor(std::stoi(_msg->data()));
  }
  catch (...)
  {
    gzerr << "Unable to process elevator message[" << _msg->data() << "]\n";
  }
}

void ElevatorPlugin::MoveToFloor(const int _floor)
{
  ElevatorPluginPrivate& d = *this->dataPtr;
  std::lock_guard<std::mutex> lock(d.stateMutex);
  if (!d.steps.empty())
    return;  // busy: ignored, as Gazebo's
  d.floor = _floor;
  d.stepStarted = false;
  d.steps = { Step::CloseDoor, Step::MoveCar, Step::OpenDoor, Step::WaitOpen, Step::CloseDoor };
}

void ElevatorPlugin::Update(const common::UpdateInfo& _info)
{
  ElevatorPluginPrivate& d = *this->dataPtr;
  std::lock_guard<std::mutex> lock(d.stateMutex);
  if (!d.steps.empty() && d.advance(_info.simTime))
  {
    d.steps.pop_front();
    d.stepStarted = false;
  }
  d.door.update(_info.simTime);
  d.lift.update(_info.simTime);
}

void ElevatorPlugin::Reset()
{
  ElevatorPluginPrivate& d = *this->dataPtr;
  std::lock_guard<std::mutex> lock(d.stateMutex);
  d.steps.clear();
  d.stepStarted = false;
  d.door.reset();
  d.lift.reset();
}
}  // namespace gazebo
