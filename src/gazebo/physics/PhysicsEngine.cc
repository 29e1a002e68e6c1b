// physics::PhysicsEngine (gazebo/physics/PhysicsEngine.hh), over the simulator's WorldBridge.
#include "gazebo/physics/PhysicsEngine.hh"

#include "gazebo/common/Console.hh"
#include "gazebo/physics/Joint.hh"
#include "gazebo/physics/PlantBridge.hh"

namespace gazebo
{
namespace physics
{
PhysicsEngine::PhysicsEngine(std::shared_ptr<WorldBridge> bridge) : bridge_(std::move(bridge)) {}

PhysicsEngine::~PhysicsEngine() = default;

std::string PhysicsEngine::GetType() const { return "bullet"; }

double PhysicsEngine::GetMaxStepSize() const { return bridge_->stepSize(); }

void PhysicsEngine::SetMaxStepSize(double step)
{
  if (!bridge_->setStepSize(step))
    gzerr << "PhysicsEngine::SetMaxStepSize(" << step << "): not a step the simulator takes; the step stays "
          << bridge_->stepSize() << " s" << std::endl;
}

double PhysicsEngine::GetRealTimeUpdateRate() const { return bridge_->realTimeUpdateRate(); }

double PhysicsEngine::GetTargetRealTimeFactor() const { return bridge_->realTimeFactor(); }

JointPtr PhysicsEngine::CreateJoint(const std::string& type, ModelPtr parent)
{
  // The types the plant makes at run time (the simulator's RunTimeJoint); Gazebo's ODE makes
  // revolute2, universal, screw and gearbox joints as well.
  if (type != "fixed" && type != "prismatic" && type != "revolute" && type != "ball")
  {
    gzerr << "PhysicsEngine::CreateJoint(\"" << type << "\"): the plant makes fixed, prismatic, revolute and ball "
          << "joints at run time; no joint is made" << std::endl;
    return JointPtr();
  }
  return JointPtr(new Joint(type, std::move(parent), bridge_));
}

boost::recursive_mutex* PhysicsEngine::GetPhysicsUpdateMutex() const { return &update_mutex_; }
}  // namespace physics
}  // namespace gazebo
