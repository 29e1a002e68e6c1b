// A robot from its URDF description into the world: rigid bodies (links fixed together), their
// mass properties and collision shapes, the Bullet multibody and its joints, gazebo_ros_control's
// joint handles and controller manager, the sensors. And the way back out of the world.
#pragma once

#include <map>
#include <string>

#include "simulation/internals.h"

namespace bullet_plant
{
// Throws DescriptionError naming the offending element (no root link, a transmission naming a
// missing or fixed joint); what was added to the world by then is taken back by removeRobot.
// The seed of a noise generator that is the same on every run and machine (FNV-1a of `text`,
// "robot/sensor" or "robot/plugin").
uint32_t seedFor(const std::string& text);

// A collision's SDF <surface> as the solver takes it (ContactSurface), its fdir1 turned into the
// collider's frame by `frame` (the collision's rotation there). A value that means nothing (a
// negative or NaN mu, a kp not above 0, a negative kd, max_vel or min_depth, an fdir1 not finite)
// is said as a warning naming `where` and left out (a mu taken as 0). `plain`: false where the
// surface asks for more than the plant's own contact with one friction coefficient (mu2 apart from
// mu, an fdir1, any of <contact><ode>).
ContactSurface contactSurface(const SurfaceDescription& surface, const btMatrix3x3& frame, const std::string& where,
                              Log& log, bool& plain);

void buildRobot(Robot::Internals& robot, const urdf::Pose& pose, const std::map<std::string, double>& initial_joints);
// Its model plugins, once the robot is in the world, as Gazebo loads a model's plugins (so that they
// find their model by name and may make joints on it), and whether it may sleep (one with plugins
// never does).
void loadModelPlugins(Robot::Internals& robot);
void removeRobot(Robot::Internals& robot);
// A movable joint's constraint rows as its dynamics need them now: the drive, an implicit damper or
// spring where an explicit one would be unstable, the dry friction motor, the limits (disabled when
// it has none). At build, and after set_joint_properties or a mass change.
void updateJointRows(Robot::Internals& robot, MovableJoint& joint);
// After the URDF inertials of one of the body's links changed (set_link_properties): the body's mass
// and inertia from its links', taken about the centre of mass and along the axes it was built with
// (Bullet's body frame, which its colliders, visuals and sensor mounts hang from, stays; what that
// leaves out is said in `note`, a sentence each), its joint's rows, and the gravity its links feel.
void updateBodyMass(Robot::Internals& robot, int body, std::string& note);
// After which links feel gravity changed (LinkPhysics::gravity): the multibody's partial gravity.
void updatePartialGravity(Robot::Internals& robot);
// Takes the robot's multibody, colliders and rows out of the dynamics world, leaving the rest (its
// controller manager, handles, last state) in place; removeRobot may follow.
void detachFromPhysics(Robot::Internals& robot);

}  // namespace bullet_plant
