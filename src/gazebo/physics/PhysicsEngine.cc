// physics::PhysicsEngine (gazebo/physics/PhysicsEngine.hh), over the simulator's WorldBridge.
#include "gazebo/physics/PhysicsEngine.hh"

#include <algorithm>
#include <iterator>

#include "gazebo/common/Console.hh"
#include "gazebo/msgs/msgs.hh"
#include "gazebo/physics/Joint.hh"
#include "gazebo/physics/PlantBridge.hh"
#include "gazebo/transport/Node.hh"

namespace gazebo
{
namespace physics
{
PhysicsEngine::PhysicsEngine(std::shared_ptr<WorldBridge> bridge) : bridge_(std::move(bridge))
{
  node_.reset(new transport::Node());
  node_->Init(bridge_->name());
  physics_sub_ = node_->Subscribe("~/physics", &PhysicsEngine::OnPhysicsMsg, this);
}

PhysicsEngine::~PhysicsEngine()
{
  physics_sub_.reset();  // no message may come to an engine that is going
  node_->Fini();
}

ignition::math::Vector3d PhysicsEngine::GetGravity() const { return bridge_->gravity(); }

void PhysicsEngine::SetGravity(const ignition::math::Vector3d& gravity) { bridge_->setGravity(gravity); }

void PhysicsEngine::OnPhysicsMsg(const boost::shared_ptr<const msgs::Physics>& msg)
{
  // From the transport's thread: between two steps.
  boost::recursive_mutex::scoped_lock lock(update_mutex_);
  if (msg->has_gravity())
    SetGravity(msgs::ConvertIgn(msg->gravity()));
  if (msg->has_max_step_size())
    SetMaxStepSize(msg->max_step_size());
  if (msg->has_enable_physics())
    bridge_->setPhysicsEnabled(msg->enable_physics());
  std::string untaken;
  const struct
  {
    bool given;
    const char* name;
  } others[] = {{msg->has_solver_type(), "solver_type"},
                {msg->has_min_step_size(), "min_step_size"},
                {msg->has_precon_iters(), "precon_iters"},
                {msg->has_iters(), "iters"},
                {msg->has_sor(), "sor"},
                {msg->has_cfm(), "cfm"},
                {msg->has_erp(), "erp"},
                {msg->has_contact_max_correcting_vel(), "contact_max_correcting_vel"},
                {msg->has_contact_surface_layer(), "contact_surface_layer"},
                {msg->has_real_time_factor(), "real_time_factor"},
                {msg->has_real_time_update_rate(), "real_time_update_rate"},
                {msg->has_magnetic_field(), "magnetic_field"}};
  for (const auto& other : others)
    if (other.given)
      untaken += std::string(untaken.empty() ? "" : ", ") + other.name;
  if (!untaken.empty())
    gzwarn << "~/physics on world [" << bridge_->name() << "]: " << untaken
           << " not taken from the message (gravity, max_step_size and enable_physics are; gazebo_ros's "
           << "set_physics_properties sets the solver's)" << std::endl;
}

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
