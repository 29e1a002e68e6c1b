// A movable URDF joint and the Bullet constraint rows that act on it: what the joint layer
// (hardware/) drives and the simulation builds, steps and restores.
#pragma once

#include <memory>
#include <string>

#include "bullet_plant/joint_limits.h"
#include "bullet_plant/log.h"
#include "physics/joint_drive.h"

namespace bullet_plant
{
// Bullet clamps every joint rate to this (btMultiBody::setMaxCoordinateVelocity), rad/s or m/s; the
// joint layer holds velocity commands to it too.
constexpr double kMaxJointSpeed = 1e4;

// A movable URDF joint and the Bullet pieces that act on it.
struct MovableJoint
{
  std::string name;
  JointType type = JointType::Revolute;
  int link = -1;                 // Bullet link index (= body index - 1)
  JointLimits limits;
  double damping = 0.0, friction = 0.0;
  std::unique_ptr<JointDrive> drive;           // the joint layer's motor / implicit PID
  std::unique_ptr<JointDrive> damper;          // URDF <dynamics damping> where an explicit torque would be unstable
  // SDF's <dynamics><spring_stiffness>, <spring_reference>: an effort -stiffness * (q - reference).
  double spring_stiffness = 0.0, spring_reference = 0.0;
  std::unique_ptr<JointDrive> spring;          // the spring where an explicit effort would not do (robot_builder.cpp)
  std::unique_ptr<JointDrive> dry_friction;    // URDF <dynamics friction>
  std::unique_ptr<JointDrive> lower_limit, upper_limit;  // rows only while the joint is at a limit
  double axis_inertia = 0.0;                   // the child body's inertia about the joint axis
  double explicit_effort = 0.0;                // actuator torque applied explicitly this step
  double initial_position = 0.0;
};

// q held to the joint's URDF position limits, with a warning naming `what` (initial position,
// position), the joint and the robot when it was outside.
double positionWithinLimits(const MovableJoint& j, double q, Log& log, const std::string& robot, const std::string& what);

}  // namespace bullet_plant
