// The simulator's side of the physics classes: what physics::World, Model, Link and Joint ask of
// the simulation that hosts a plugin. The Bullet plant implements it (src/plant/gazebo_host/); a
// plugin never uses it. Poses and vectors are in the world frame.
#pragma once

#include <limits>
#include <memory>
#include <string>
#include <vector>

#include <ignition/math/Pose3.hh>
#include <ignition/math/Vector3.hh>

#include "gazebo/common/Time.hh"
#include "gazebo/physics/PhysicsTypes.hh"

namespace gazebo
{
namespace physics
{
class ModelBridge;

class JointBridge
{
public:
  virtual ~JointBridge() = default;
  virtual double position() const = 0;
  virtual double velocity() const = 0;
  // False (and one warning naming the joint) where the joint is driven by something else (a
  // gazebo_ros_control transmission): nothing is changed.
  virtual bool setVelocity(double velocity) = 0;
  virtual bool setForce(double effort) = 0;
  // The efforts setForce gave for the coming step (summed), or those of the last step until the
  // next setForce; 0 where the joint is driven by something else.
  virtual double appliedForce() const = 0;
  virtual bool setPosition(double position) = 0;
  // The joint's limits as its model gives them (-inf / inf for none; the effort and velocity
  // limits inf for none).
  virtual double lowerLimit() const = 0;
  virtual double upperLimit() const = 0;
  virtual double effortLimit() const = 0;
  virtual double velocityLimit() const = 0;
  virtual std::string parentLink() const = 0;
  virtual std::string childLink() const = 0;
  // The joint's frame in its child link's frame as its model gives it (Joint::InitialAnchorPose).
  virtual ignition::math::Pose3d anchorPose() const = 0;
  // SetParam("vel") and ("fmax"): a motor that drives the joint to the velocity with at most the
  // force, every step until told otherwise. False as setVelocity.
  virtual bool setMotorVelocity(double velocity) = 0;
  virtual bool setMotorMaxForce(double force) = 0;
  // Its axis as its model gives it (in the joint's frame, which moves with the child link), and in
  // the world now; zero for a joint that has none.
  virtual ignition::math::Vector3d localAxis() const = 0;
  virtual ignition::math::Vector3d globalAxis() const = 0;
  // What the child passed to the joint over the last step (the joint's push on it, negated: Gazebo's
  // body2), in the child link's frame (the torque about the joint's origin), watched from the first
  // call on: zero until a step has run.
  virtual void childWrench(ignition::math::Vector3d& force, ignition::math::Vector3d& torque) = 0;
};

// A link's own <inertial>, as its model gives it: the mass, the centre of mass and the inertia's
// axes in the link frame, and the inertia about it in those axes.
struct LinkInertia
{
  double mass = 0.0;
  ignition::math::Pose3d pose;
  double ixx = 0.0, iyy = 0.0, izz = 0.0, ixy = 0.0, ixz = 0.0, iyz = 0.0;
};

// One <collision> of a link as its model gives it (physics::Collision): its shape and its surface.
struct CollisionSpec
{
  std::string name;
  ignition::math::Pose3d pose;   // in its link
  unsigned int shape_type = 0;   // Base::BOX_SHAPE, CYLINDER_SHAPE, SPHERE_SHAPE, MESH_SHAPE; SHAPE for another
  ignition::math::Vector3d size;  // a box's sides, a mesh's scale
  double radius = 0.0, length = 0.0;
  std::string mesh_uri;
};

class ModelBridge
{
public:
  virtual ~ModelBridge() = default;
  virtual std::string name() const = 0;
  virtual std::string canonicalLink() const = 0;
  virtual std::vector<std::string> linkNames() const = 0;
  virtual std::vector<std::string> jointNames() const = 0;
  virtual ignition::math::Pose3d linkPose(const std::string& link) const = 0;
  virtual ignition::math::Vector3d linkLinearVel(const std::string& link) const = 0;
  virtual ignition::math::Vector3d linkAngularVel(const std::string& link) const = 0;
  // The canonical link's body moves with `linear` and turns with `angular` from now on.
  virtual void setVelocity(const ignition::math::Vector3d& linear, const ignition::math::Vector3d& angular) = 0;
  // A force at the link's centre of mass and a torque, for the coming step.
  virtual void addLinkWrench(const std::string& link, const ignition::math::Vector3d& force,
                             const ignition::math::Vector3d& torque) = 0;
  // What has been added to the link's body for the coming step so far (world axes, the torque about
  // its centre of mass), and where that centre is (world): the link's body holds the links fixed
  // to it, as Gazebo lumps them.
  virtual void addedLinkWrench(const std::string& link, ignition::math::Vector3d& force,
                               ignition::math::Vector3d& torque) const = 0;
  virtual ignition::math::Vector3d bodyCentreOfMass(const std::string& link) const = 0;
  virtual LinkInertia linkInertia(const std::string& link) const = 0;
  // The model's <static>: it never moves but where it is put.
  virtual bool isStatic() const = 0;
  // Whether gravity pulls the link (its model's <gravity>, or what setLinkGravity made it).
  virtual bool linkGravity(const std::string& link) const = 0;
  // From the next step on.
  virtual void setLinkGravity(const std::string& link, bool gravity) = 0;
  // The movable joints whose child (`parent_side` false: whose parent) the link is.
  virtual std::vector<std::string> linkJoints(const std::string& link, bool parent_side) const = 0;
  // The model moved so that `link` is at `pose` (world), joints as they are, at rest.
  virtual void setLinkWorldPose(const std::string& link, const ignition::math::Pose3d& pose) = 0;
  // Null for a joint the model lacks or a fixed one.
  virtual std::unique_ptr<JointBridge> joint(const std::string& name) = 0;
  // The link's own collisions, in its <collision> order.
  virtual std::vector<CollisionSpec> linkCollisions(const std::string& link) const = 0;
  // The surface of `collision` of `link` (an ODESurfaceParams holding the model's <surface>): one
  // object for the model's life, whose friction coefficients and slips the simulator takes as they
  // are when each step starts; null for a collision the link lacks.
  virtual SurfaceParamsPtr collisionSurface(const std::string& link, const std::string& collision) = 0;
};

// A joint made at run time as Joint::Attach asks for it: `child_link` of `child_model` held to
// `parent_link` of `parent_model`, or to the world where `parent_model` is empty, from where they are.
struct RunTimeJointSpec
{
  std::string name;  // for what the simulator says
  std::string type;  // Gazebo's: "fixed", "prismatic", "revolute" or "ball"
  std::string parent_model, parent_link, child_model, child_link;
  ignition::math::Vector3d anchor;          // world
  ignition::math::Vector3d axis{0, 0, 1};   // world, prismatic and revolute
  double lower = -std::numeric_limits<double>::infinity();
  double upper = std::numeric_limits<double>::infinity();
  double damping = 0.0;
  double effort_limit = std::numeric_limits<double>::infinity();
};

class WorldBridge
{
public:
  virtual ~WorldBridge() = default;
  virtual std::string name() const = 0;
  virtual common::Time simTime() const = 0;
  virtual ignition::math::Vector3d gravity() const = 0;
  // From the next step on; a vector that is not finite is refused (the simulator says so).
  virtual void setGravity(const ignition::math::Vector3d& gravity) = 0;
  virtual ignition::math::Vector3d magneticField() const = 0;
  // <spherical_coordinates>: latitude and longitude of the origin (degrees), its elevation (m), the
  // heading of the world's x axis (degrees), on WGS84.
  virtual ignition::math::Vector3d sphericalOrigin() const = 0;  // latitude, longitude, elevation
  virtual double headingDeg() const = 0;
  virtual double stepSize() const = 0;
  // False (the simulator says why) for a step it cannot take.
  virtual bool setStepSize(double seconds) = 0;
  virtual double realTimeUpdateRate() const = 0;
  virtual double realTimeFactor() const = 0;
  virtual uint64_t iterations() const = 0;
  // The models that move, in the order they came, and one by name (null for none).
  virtual std::vector<std::string> modelNames() const = 0;
  virtual std::shared_ptr<ModelBridge> model(const std::string& name) = 0;
  virtual bool paused() const = 0;
  virtual void setPaused(bool paused) = 0;
  virtual bool physicsEnabled() const = 0;
  virtual void setPhysicsEnabled(bool enable) = 0;
  virtual void reset() = 0;
  // A joint made at run time: its bridge, which lets go when destroyed; null (the simulator says
  // why) where it cannot be made.
  virtual std::unique_ptr<JointBridge> attach(const RunTimeJointSpec& joint) = 0;
  // A model from SDF text, added between steps (World::InsertModelString and the others).
  virtual void insertModel(const std::string& sdf_xml) = 0;
};
}  // namespace physics
}  // namespace gazebo
