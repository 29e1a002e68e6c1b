// physics::MeshShape (Shape.hh holds the shapes).
#pragma once

#include "gazebo/physics/Shape.hh"
