// physics::PhysicsEngine (gazebo/physics/PhysicsEngine.hh), over the simulator's WorldBridge.
#include "gazebo/physics/PhysicsEngine.hh"

#include <algorithm>
#include <iterator>

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
  // Gazebo's joint types (ODE makes them all); another name is Gazebo's error and no joint.
  static const char* const kGazeboTypes[] = {"fixed", "prismatic", "revolute", "ball",
                                             "revolute2", "universal", "screw", "gearbox"};
  if (std::find(std::begin(kGazeboTypes), std::end(kGazeboTypes), type) == std::end(kGazeboTypes))
  {
    gzerr << "Unable to create joint of type[" << type << "]" << std::endl;
    return JointPtr();
  }
  return JointPtr(new Joint(type, std::move(parent), bridge_));
}

boost::recursive_mutex* PhysicsEngine::GetPhysicsUpdateMutex() const { return &update_mutex_; }
}  // namespace physics
}  // namespace gazebo
