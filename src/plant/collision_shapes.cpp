#include "collision_shapes.h"

#include <algorithm>
#include <cmath>

#include "mesh_bounds.h"

namespace bullet_plant
{
namespace
{
btVector3 halfExtents(double x, double y, double z) { return btVector3(btScalar(x / 2), btScalar(y / 2), btScalar(z / 2)); }

btCollisionShape* withMargin(btCollisionShape* shape, Shape::Kind kind)
{
  if (kind == Shape::Kind::Box || kind == Shape::Kind::Cylinder)
    shape->setMargin(kCollisionMargin);
  return shape;
}
}  // namespace

btCollisionShape* makeCollisionShape(const Shape& s)
{
  btCollisionShape* shape = nullptr;
  switch (s.kind)
  {
    case Shape::Kind::Box:
      shape = new btBoxShape(halfExtents(s.box_size[0], s.box_size[1], s.box_size[2]));
      break;
    case Shape::Kind::Cylinder:
      shape = new btCylinderShapeZ(btVector3(btScalar(s.radius), btScalar(s.radius), btScalar(s.length / 2)));
      break;
    case Shape::Kind::Sphere:
      shape = new btSphereShape(btScalar(s.radius));
      break;
    case Shape::Kind::Plane:
      shape = new btStaticPlaneShape(btVector3(btScalar(s.normal.x), btScalar(s.normal.y), btScalar(s.normal.z)), 0);
      break;
  }
  return withMargin(shape, s.kind);
}

// The tolerances absorb float rounding of the URDF's angles (cos(pi/2) is 4e-8 in float).
btCollisionShape* makeAlignedCollisionShape(const Shape& s, const btTransform& pose)
{
  constexpr btScalar kTolerance = btScalar(1e-6);
  if (pose.getOrigin().length() > kTolerance)
    return nullptr;
  // The body axis that the shape's axis k lies along, or -1.
  auto bodyAxisOf = [&](int k) {
    for (int i = 0; i < 3; ++i)
      if (btFabs(btFabs(pose.getBasis()[i][k]) - 1) < kTolerance)
        return i;
    return -1;
  };
  switch (s.kind)
  {
    case Shape::Kind::Sphere:
      return makeCollisionShape(s);
    case Shape::Kind::Box:
    {
      btVector3 half;
      for (int k = 0; k < 3; ++k)
      {
        const int i = bodyAxisOf(k);
        if (i < 0)
          return nullptr;
        half[i] = btScalar(s.box_size[k] / 2);
      }
      return withMargin(new btBoxShape(half), s.kind);
    }
    case Shape::Kind::Cylinder:
    {
      const btScalar r = btScalar(s.radius), h = btScalar(s.length / 2);
      switch (bodyAxisOf(2))
      {
        case 0:
          return withMargin(new btCylinderShapeX(btVector3(h, r, r)), s.kind);
        case 1:
          return withMargin(new btCylinderShape(btVector3(r, h, r)), s.kind);
        case 2:
          return withMargin(new btCylinderShapeZ(btVector3(r, r, h)), s.kind);
        default:
          return nullptr;
      }
    }
    case Shape::Kind::Plane:
      break;
  }
  return nullptr;
}

bool shapeFromUrdf(const urdf::Geometry& g, const std::string& link, const Log& log, Shape& s, btTransform& offset)
{
  s = Shape();
  offset.setIdentity();
  switch (g.type)
  {
    case urdf::Geometry::BOX:
    {
      const auto& box = static_cast<const urdf::Box&>(g);
      s.kind = Shape::Kind::Box;
      s.box_size = {{box.dim.x, box.dim.y, box.dim.z}};
      break;
    }
    case urdf::Geometry::CYLINDER:
    {
      const auto& c = static_cast<const urdf::Cylinder&>(g);
      s.kind = Shape::Kind::Cylinder;
      s.radius = c.radius;
      s.length = c.length;
      break;
    }
    case urdf::Geometry::SPHERE:
      s.kind = Shape::Kind::Sphere;
      s.radius = static_cast<const urdf::Sphere&>(g).radius;
      break;
    case urdf::Geometry::MESH:
    {
      const auto& mesh = static_cast<const urdf::Mesh&>(g);
      MeshBounds b;
      std::string reason;
      if (!readMeshBounds(mesh.filename, b, reason))
      {
        log.warn("link '" + link + "': mesh collision " + reason + "; the link has no collision there");
        return false;
      }
      s.kind = Shape::Kind::Box;
      double scale[3] = {mesh.scale.x, mesh.scale.y, mesh.scale.z};
      btVector3 centre;
      for (int i = 0; i < 3; ++i)
      {
        s.box_size[i] = std::max(1e-4, (b.max[i] - b.min[i]) * std::abs(scale[i]));
        centre[i] = btScalar((b.max[i] + b.min[i]) / 2.0 * scale[i]);
      }
      offset.setOrigin(centre);
      log.warn("link '" + link + "': mesh collision '" + mesh.filename +
               "' is simulated as its bounding box; use box/cylinder/sphere collisions for accurate contact");
      break;
    }
    default:
      return false;
  }
  bool ok = true;
  for (double v : {s.radius, s.length, s.box_size[0], s.box_size[1], s.box_size[2]})
    if (!std::isfinite(v) || v < 0)
      ok = false;
  if ((s.kind == Shape::Kind::Box && (s.box_size[0] <= 0 || s.box_size[1] <= 0 || s.box_size[2] <= 0)) ||
      (s.kind != Shape::Kind::Box && s.radius <= 0) || (s.kind == Shape::Kind::Cylinder && s.length <= 0))
  {
    log.warn("link '" + link + "': a collision has a zero or negative size; ignored");
    ok = false;
  }
  return ok;
}

}  // namespace bullet_plant
