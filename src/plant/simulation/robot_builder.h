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

void buildRobot(Robot::Internals& robot, const urdf::Pose& pose, const std::map<std::string, double>& initial_joints);
void removeRobot(Robot::Internals& robot);
// Takes the robot's multibody, colliders and rows out of the dynamics world, leaving the rest (its
// controller manager, handles, last state) in place; removeRobot may follow.
void detachFromPhysics(Robot::Internals& robot);

}  // namespace bullet_plant
