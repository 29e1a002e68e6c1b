// Gazebo's physics library, as a plugin includes it whole: the world, its physics engine, models, links and joints.
#pragma once

// Gazebo 11's physics headers bring the world's events in: plugins that include no more than
// physics.hh and Plugin.hh connect to event::Events (roboticsgroup's mimic joint plugin does).
#include "gazebo/common/Events.hh"

#include "gazebo/physics/Base.hh"
#include "gazebo/physics/Collision.hh"
#include "gazebo/physics/Entity.hh"
#include "gazebo/physics/Inertial.hh"
#include "gazebo/physics/Joint.hh"
#include "gazebo/physics/JointController.hh"
#include "gazebo/physics/Link.hh"
#include "gazebo/physics/Model.hh"
#include "gazebo/physics/MultiRayShape.hh"
#include "gazebo/physics/PhysicsEngine.hh"
#include "gazebo/physics/PhysicsIface.hh"
#include "gazebo/physics/PhysicsTypes.hh"
#include "gazebo/physics/Shape.hh"
#include "gazebo/physics/SurfaceParams.hh"
#include "gazebo/physics/World.hh"
