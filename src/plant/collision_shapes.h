// Where the plant's shapes become Bullet collision shapes: one switch over Shape::Kind for the world
// and the robots, one margin rule, and the URDF geometry each collision is read from.
#pragma once

#include <string>

#include <btBulletCollisionCommon.h>
#include <urdf_model/link.h>

#include "bullet_plant/geometry.h"
#include "bullet_plant/log.h"

namespace bullet_plant
{
// Bullet keeps a box's or cylinder's outer size and rounds its edges by the margin. Its 4 cm default
// is larger than this car's wheels; half a millimetre keeps contacts on the true surface. A sphere's
// margin is its radius and a plane has none: Bullet's own.
constexpr btScalar kCollisionMargin = btScalar(0.0005);

// The shape in its own frame (a cylinder along its z axis). The caller owns it.
btCollisionShape* makeCollisionShape(const Shape& shape);

// The shape as Bullet's axis-aligned primitive where its pose in a body frame is one of its
// symmetries (no offset; for a box a rotation that permutes its axes, for a cylinder one that puts
// its axis on a body axis, for a sphere any): then the body's collider needs no compound, which
// costs every contact pair a tree walk and a transform per step. Null where a compound is needed.
btCollisionShape* makeAlignedCollisionShape(const Shape& shape, const btTransform& pose);

// A URDF <collision>'s geometry as a Shape, and the offset of the Shape's frame in the collision's
// (non-zero for a mesh, which stands in as its bounding box). False, with a warning naming the link,
// where the geometry cannot be simulated (unreadable mesh, zero or negative size).
bool shapeFromUrdf(const urdf::Geometry& geometry, const std::string& link, const Log& log, Shape& shape,
                   btTransform& offset);

}  // namespace bullet_plant
