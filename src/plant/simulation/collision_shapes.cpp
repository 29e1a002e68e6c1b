#include "simulation/collision_shapes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <mutex>
#include <vector>

#include <BulletCollision/CollisionDispatch/btCollisionObjectWrapper.h>
#include <BulletCollision/CollisionDispatch/btInternalEdgeUtility.h>
#include <BulletCollision/CollisionDispatch/btManifoldResult.h>
#include <BulletCollision/CollisionShapes/btTriangleShape.h>
#include <BulletCollision/Gimpact/btGImpactShape.h>
#include <LinearMath/btConvexHullComputer.h>

#include "bullet_plant/robot_description.h"
#include "description/resource_uri.h"
#include "physics/bullet_conversions.h"

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

// A moving box's faces, so that Bullet's SAT clips its face against a static mesh's triangle and
// it rests flat there (dispatchInfo.m_enableSatConvex). Only moving boxes: Bullet clips a pair only
// where both have faces, a static box needs none against a triangle, and finding a box's faces costs
// Bullet up to two thousand containment tests (btConvexPolyhedron::initialize), two thirds of a
// reset of a track of 232 walls.
btCollisionShape* withFaces(btCollisionShape* shape, Shape::Kind kind)
{
  if (shape && kind == Shape::Kind::Box)
    static_cast<btBoxShape*>(shape)->initializePolyhedralFeatures();
  return shape;
}

// An ellipsoid by its support function, exact in every direction: the point of the ellipsoid with
// radii a - m, b - m, c - m farthest along d is (a'^2 dx, b'^2 dy, c'^2 dz) / |(a' dx, b' dy, c' dz)|,
// and Bullet adds the margin m around it, so the outer surface is the ellipsoid's along its axes and
// within m (a - c)^2 / (2 a c) of it elsewhere (a fraction of a micrometre for the margin's half
// millimetre). Bullet's scaled shapes do not serve: a btMultiSphereShape with non-uniform local
// scaling gives the scaled sphere's point along d, not the ellipsoid's farthest one, so a tilted
// ellipsoid would rest too low, and a hull of sampled points has facets that bump as it rolls.
class EllipsoidShape : public btConvexInternalShape
{
public:
  explicit EllipsoidShape(const std::array<double, 3>& radii)
  {
    m_shapeType = CUSTOM_CONVEX_SHAPE_TYPE;
    // Each inner radius keeps at least half the smallest: an ellipsoid thinner than twice the margin
    // takes a margin of a quarter of its least radius.
    const double least = std::min({radii[0], radii[1], radii[2]});
    const btScalar margin = btScalar(std::min(double(kCollisionMargin), least / 4));
    for (int i = 0; i < 3; ++i)
      inner_[i] = btScalar(radii[i]) - margin;
    setMargin(margin);
    m_implicitShapeDimensions = inner_;
  }
  btVector3 localGetSupportingVertexWithoutMargin(const btVector3& d) const override
  {
    const btVector3 scaled = inner_ * d;  // (a dx, b dy, c dz)
    const btScalar length = scaled.length();
    if (!(length > SIMD_EPSILON))
      return btVector3(inner_.x(), 0, 0);
    return inner_ * scaled / length;
  }
  void batchedUnitVectorGetSupportingVertexWithoutMargin(const btVector3* directions, btVector3* out,
                                                         int count) const override
  {
    for (int i = 0; i < count; ++i)
      out[i] = localGetSupportingVertexWithoutMargin(directions[i]);
  }
  void calculateLocalInertia(btScalar mass, btVector3& inertia) const override
  {
    const btVector3 r = inner_ + btVector3(getMargin(), getMargin(), getMargin());
    inertia.setValue(mass / 5 * (r.y() * r.y() + r.z() * r.z()), mass / 5 * (r.x() * r.x() + r.z() * r.z()),
                     mass / 5 * (r.x() * r.x() + r.y() * r.y()));
  }
  void getAabb(const btTransform& t, btVector3& min, btVector3& max) const override
  {
    // The extent along world axis i: the support's, sqrt(sum_k (R_ik r_k)^2), plus the margin.
    const btMatrix3x3& basis = t.getBasis();
    btVector3 half;
    for (int i = 0; i < 3; ++i)
      half[i] = (basis[i] * inner_).length() + getMargin();
    min = t.getOrigin() - half;
    max = t.getOrigin() + half;
  }
  void setLocalScaling(const btVector3&) override {}  // the radii are the shape's own
  const char* getName() const override { return "Ellipsoid"; }
  int getNumPreferredPenetrationDirections() const override { return 0; }
  void getPreferredPenetrationDirection(int, btVector3&) const override {}

private:
  btVector3 inner_;
};

// A capsule along the body axis `axis` (0 x, 1 y, 2 z): Bullet's margin is its radius, so its
// surface is the capsule's own.
btCollisionShape* capsuleAlong(int axis, double radius, double length)
{
  const btScalar r = btScalar(radius), h = btScalar(length);
  switch (axis)
  {
    case 0:
      return new btCapsuleShapeX(r, h);
    case 1:
      return new btCapsuleShape(r, h);
    default:
      return new btCapsuleShapeZ(r, h);
  }
}

// Bullet's triangle mesh over the loaded file's arrays, which it keeps alive (copies of a mesh share
// them). The arrays come first so they exist when the BVH is built.
struct MeshArrays
{
  std::shared_ptr<const MeshData> mesh;
  btTriangleIndexVertexArray triangles;
  explicit MeshArrays(const std::shared_ptr<const MeshData>& m)
    : mesh(m),
      triangles(m->triangleCount(), const_cast<int*>(m->indices.data()), 3 * sizeof(int), m->vertexCount(),
                const_cast<btScalar*>(m->vertices.data()), 3 * sizeof(btScalar))
  {
  }
};

// With the angles between neighbouring faces (btGenerateInternalEdgeInfo) that correctInternalEdges
// reads.
class StaticMeshShape : private MeshArrays, public btBvhTriangleMeshShape  // margin: collision_shapes.h
{
public:
  explicit StaticMeshShape(const std::shared_ptr<const MeshData>& m)
    : MeshArrays(m), btBvhTriangleMeshShape(&triangles, true, true)
  {
    setMargin(kCollisionMargin);
    btGenerateInternalEdgeInfo(this, &edges_);
  }

private:
  btTriangleInfoMap edges_;
};

// A moving body's mesh as its exact triangles: Bullet's GImpact (a BVH over the triangles, refitted
// as the body moves), for a mesh that no convex shapes make up exactly (movingMeshShape).
class MovingMeshShape : private MeshArrays, public btGImpactMeshShape
{
public:
  explicit MovingMeshShape(const std::shared_ptr<const MeshData>& m) : MeshArrays(m), btGImpactMeshShape(&triangles)
  {
    setMargin(kCollisionMargin);
    updateBound();
  }
};

// The convex hulls of a mesh made of several convex pieces (a track's wall segments), which the
// compound keeps alive.
class HullCompound : public btCompoundShape
{
public:
  void add(btConvexHullShape* hull)
  {
    hulls_.emplace_back(hull);
    addChildShape(btTransform::getIdentity(), hull);
  }

private:
  std::vector<std::unique_ptr<btConvexHullShape>> hulls_;
};

bool holdsStaticMesh(const btCollisionShape& shape)
{
  if (shape.getShapeType() == TRIANGLE_MESH_SHAPE_PROXYTYPE)
    return true;
  if (shape.getShapeType() != COMPOUND_SHAPE_PROXYTYPE)
    return false;
  const auto& compound = static_cast<const btCompoundShape&>(shape);
  for (int k = 0; k < compound.getNumChildShapes(); ++k)
    if (holdsStaticMesh(*compound.getChildShape(k)))
      return true;
  return false;
}

// The static mesh a contact's triangle belongs to: the shape of the wrapper it was cut from (the
// collision object's own shape, or a compound's child).
const btBvhTriangleMeshShape* meshOf(const btCollisionObjectWrapper* side)
{
  if (side->getCollisionShape()->getShapeType() != TRIANGLE_SHAPE_PROXYTYPE || !side->m_parent ||
      side->m_parent->getCollisionShape()->getShapeType() != TRIANGLE_MESH_SHAPE_PROXYTYPE)
    return nullptr;
  return static_cast<const btBvhTriangleMeshShape*>(side->m_parent->getCollisionShape());
}

// Whether `p` (in the triangle's frame) lies over the triangle at least `distance` inside each of its
// edges (never for a triangle without area: it has no inside, nor a normal).
bool insideBy(const btTriangleShape& triangle, const btVector3& p, btScalar distance)
{
  const btVector3* v = triangle.m_vertices1;
  const btVector3 normal = (v[1] - v[0]).cross(v[2] - v[0]);
  if (normal.fuzzyZero())
    return false;
  for (int i = 0; i < 3; ++i)
  {
    const btVector3 edge = v[(i + 1) % 3] - v[i];
    const btVector3 inward = normal.cross(edge);  // in the face's plane, towards the third vertex
    if ((p - v[i]).dot(inward) < distance * inward.length())
      return false;
  }
  return true;
}

// btAdjustInternalEdgeContacts on a new contact point with a static mesh's triangle, on either side
// of the point. Bullet's function takes the mesh as the point's side B and finds it as the shape of
// the triangle's collision object; a robot's fixed link holds its meshes in a compound, so the mesh
// is handed over on a collision object of its own, and a mesh on side A is turned to side B and back.
void adjustAtInternalEdge(btManifoldPoint& point, const btCollisionObjectWrapper* triangle,
                          const btCollisionObjectWrapper* other, int part, int index, bool mesh_is_b)
{
  const btBvhTriangleMeshShape* mesh = meshOf(triangle);
  if (!mesh || !mesh->getTriangleInfoMap())
    return;
  btCollisionObject holder;
  holder.setCollisionShape(const_cast<btBvhTriangleMeshShape*>(mesh));
  holder.setWorldTransform(triangle->getWorldTransform());
  const btCollisionObjectWrapper on_mesh(triangle->m_parent, triangle->getCollisionShape(), &holder,
                                         triangle->getWorldTransform(), part, index);
  const auto swapSides = [](btManifoldPoint& p) {
    std::swap(p.m_positionWorldOnA, p.m_positionWorldOnB);
    std::swap(p.m_localPointA, p.m_localPointB);
    p.m_normalWorldOnB = -p.m_normalWorldOnB;
  };
  if (!mesh_is_b)
    swapSides(point);
  btAdjustInternalEdgeContacts(point, &on_mesh, other, part, index);
  // Bullet corrects the normals of points near an edge (within the map's edge distance). It leaves
  // two kinds of wrong normal, which push out of the face's front instead: one that points behind
  // the face (the margin's rounded edge, reached from above where two faces meet; the faces are
  // one-sided, as ODE's trimesh collides), and one off the face's normal at a point farther inside
  // the face than that distance (its cylinder-triangle test gave a wheel on the mesh race track's
  // floor normals up to 90 degrees off, 0.1-0.2 m from any edge), where a convex shape can touch
  // the face along its normal only.
  const auto& face_shape = *static_cast<const btTriangleShape*>(triangle->getCollisionShape());
  btVector3 face;
  face_shape.calcNormal(face);
  face = triangle->getWorldTransform().getBasis() * face;
  if (point.m_normalWorldOnB.dot(face) < 0 ||
      insideBy(face_shape, triangle->getWorldTransform().invXform(point.m_positionWorldOnB),
               mesh->getTriangleInfoMap()->m_edgeDistanceThreshold))
  {
    point.m_normalWorldOnB = face;
    point.m_positionWorldOnB = point.m_positionWorldOnA - face * point.m_distance1;
    point.m_localPointB = triangle->getWorldTransform().invXform(point.m_positionWorldOnB);
  }
  if (!mesh_is_b)
    swapSides(point);
}

bool correctInternalEdgeContact(btManifoldPoint& point, const btCollisionObjectWrapper* a, int part_a, int index_a,
                                const btCollisionObjectWrapper* b, int part_b, int index_b)
{
  adjustAtInternalEdge(point, b, a, part_b, index_b, true);
  adjustAtInternalEdge(point, a, b, part_a, index_a, false);
  return false;  // Bullet ignores it
}

// The convex hull of the vertices, each face moved in by the margin (Bullet adds it back outside).
// Where it has more than kMaxHullVertices vertices it keeps its support points in that many
// directions spread evenly over the sphere (a Fibonacci lattice): the extremes in every direction.
btConvexHullShape* makeHull(const float* vertices, int count)
{
  btConvexHullComputer hull;
  float extent = 1e30f;
  for (int i = 0; i < 3; ++i)
  {
    float low = 1e30f, high = -1e30f;
    for (int v = 0; v < count; ++v)
    {
      low = std::min(low, vertices[3 * v + i]);
      high = std::max(high, vertices[3 * v + i]);
    }
    extent = std::min(extent, high - low);
  }
  // A flat mesh keeps its plane: shrinking it would turn it inside out.
  const btScalar shrink = extent > 4 * kCollisionMargin ? kCollisionMargin : btScalar(0);
  hull.compute(vertices, 3 * sizeof(float), count, shrink, btScalar(0.25));
  const int n = hull.vertices.size();
  std::vector<bool> keep(n, n <= kMaxHullVertices);
  if (n > kMaxHullVertices)
  {
    const double golden = M_PI * (3.0 - std::sqrt(5.0));
    for (int k = 0; k < kMaxHullVertices; ++k)
    {
      const double z = 1.0 - (2.0 * k + 1.0) / kMaxHullVertices, r = std::sqrt(1.0 - z * z);
      const btVector3 d(btScalar(r * std::cos(golden * k)), btScalar(r * std::sin(golden * k)), btScalar(z));
      int best = 0;
      for (int v = 1; v < n; ++v)
        if (d.dot(hull.vertices[v]) > d.dot(hull.vertices[best]))
          best = v;
      keep[best] = true;
    }
  }
  auto* shape = new btConvexHullShape();
  for (int v = 0; v < n; ++v)
    if (keep[v])
      shape->addPoint(hull.vertices[v], false);
  shape->recalcLocalAabb();
  shape->setMargin(shrink > 0 ? kCollisionMargin : btScalar(0.0));
  shape->initializePolyhedralFeatures();  // faces for mesh contacts: makeCollider
  return shape;
}
}  // namespace

// The mesh's pieces: its triangles joined where they share a corner (the same position), each a
// list of its vertex positions, x y z.
std::vector<std::vector<float>> connectedPieces(const MeshData& mesh)
{
  std::map<std::array<float, 3>, int> at;  // a position's first vertex
  std::vector<int> same(size_t(mesh.vertexCount()));
  for (int v = 0; v < mesh.vertexCount(); ++v)
  {
    const float* p = &mesh.vertices[size_t(3 * v)];
    same[size_t(v)] = at.emplace(std::array<float, 3>{{p[0], p[1], p[2]}}, v).first->second;
  }
  std::vector<int> parent(same.size());  // union-find over the vertices
  for (size_t v = 0; v < parent.size(); ++v)
    parent[v] = int(v);
  const auto find = [&parent](int v) {
    while (parent[size_t(v)] != v)
      v = parent[size_t(v)] = parent[size_t(parent[size_t(v)])];
    return v;
  };
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3)
    for (int k = 1; k < 3; ++k)
      parent[size_t(find(same[size_t(mesh.indices[t + size_t(k)])]))] = find(same[size_t(mesh.indices[t])]);
  std::map<int, std::vector<float>> pieces;
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3)
  {
    std::vector<float>& piece = pieces[find(same[size_t(mesh.indices[t])])];
    for (size_t k = 0; k < 3; ++k)
    {
      const float* p = &mesh.vertices[size_t(3 * mesh.indices[t + k])];
      piece.insert(piece.end(), p, p + 3);
    }
  }
  std::vector<std::vector<float>> out;
  for (auto& piece : pieces)
    out.push_back(std::move(piece.second));
  return out;
}

// Area and enclosed volume of triangles (three corners each, x y z), the volume by the divergence
// theorem (meaningful for a closed surface).
void areaAndVolume(const std::vector<btVector3>& corners, double& area, double& volume)
{
  area = volume = 0;
  for (size_t t = 0; t + 2 < corners.size(); t += 3)
  {
    const btVector3 &a = corners[t], &b = corners[t + 1], &c = corners[t + 2];
    area += 0.5 * double((b - a).cross(c - a).length());
    volume += double(a.dot(b.cross(c))) / 6.0;
  }
  volume = std::abs(volume);
}

// A convex piece thinner than this share of its length (a track's floor slab, a long wall) collides as
// its triangles: Bullet's convex contact (GJK, then EPA for the depth) loses precision on such a hull
// and put a wheel rolling on a 12 x 6 x 0.02 m slab's top face in touch with the slab's far corner,
// with a sideways normal (a crash where there was none), at 0.02 m thick and at 0.2 m alike.
constexpr double kThinnestHull = 0.1;

// What a moving mesh's piece (connectedPieces) collides as.
enum class Piece
{
  CompactConvex,  // its triangles are its convex hull's surface, and the hull is not thin: the hull
  ThinConvex,     // convex, thinner than kThinnestHull of its length (or flat): its triangles
  Concave,        // its triangles
};

// A piece is convex where its triangles are its hull's surface: a closed convex solid (the same area
// and volume within 1 %), or a flat convex polygon (the same area as one side of its flat hull).
// Then the hull collides exactly where the triangles would.
Piece classifyPiece(const std::vector<float>& piece)
{
  std::vector<btVector3> corners;
  for (size_t i = 0; i + 2 < piece.size(); i += 3)
    corners.emplace_back(piece[i], piece[i + 1], piece[i + 2]);
  double area = 0, volume = 0;
  areaAndVolume(corners, area, volume);
  btConvexHullComputer hull;
  hull.compute(piece.data(), 3 * sizeof(float), int(corners.size()), 0, 0);
  std::vector<btVector3> hull_corners;  // its faces as fans of triangles
  for (int f = 0; f < hull.faces.size(); ++f)
  {
    const btConvexHullComputer::Edge* first = &hull.edges[hull.faces[f]];
    const btVector3& origin = hull.vertices[first->getSourceVertex()];
    for (const btConvexHullComputer::Edge* e = first->getNextEdgeOfFace(); e->getTargetVertex() != first->getSourceVertex();
         e = e->getNextEdgeOfFace())
      hull_corners.insert(hull_corners.end(), {origin, hull.vertices[e->getSourceVertex()],
                                               hull.vertices[e->getTargetVertex()]});
  }
  double hull_area = 0, hull_volume = 0;
  areaAndVolume(hull_corners, hull_area, hull_volume);
  constexpr double kTolerance = 0.01;
  const auto near = [](double a, double b) { return std::abs(a - b) <= kTolerance * std::max(a, b); };
  if (hull_area <= 0)
    return Piece::Concave;  // a line or a point: nothing to collide with
  // Flat: its hull's volume is that of a slab thinner than a micrometre over its area.
  if (hull_volume <= 1e-6 * hull_area)
    return near(area, hull_area / 2) ? Piece::ThinConvex : Piece::Concave;
  if (!(near(area, hull_area) && near(volume, hull_volume)))
    return Piece::Concave;
  // Its thickness: the narrowest of its widths across its faces; its length: its box's diagonal.
  btVector3 low(1e30f, 1e30f, 1e30f), high(-1e30f, -1e30f, -1e30f);
  for (int v = 0; v < hull.vertices.size(); ++v)
  {
    low.setMin(hull.vertices[v]);
    high.setMax(hull.vertices[v]);
  }
  double thickness = 1e30;
  for (size_t t = 0; t + 2 < hull_corners.size(); t += 3)
  {
    const btVector3 normal = (hull_corners[t + 1] - hull_corners[t]).cross(hull_corners[t + 2] - hull_corners[t]);
    if (normal.length2() <= 0)
      continue;
    double lowest = 1e30, highest = -1e30;
    for (int v = 0; v < hull.vertices.size(); ++v)
    {
      const double along = double(normal.normalized().dot(hull.vertices[v]));
      lowest = std::min(lowest, along);
      highest = std::max(highest, along);
    }
    thickness = std::min(thickness, highest - lowest);
  }
  return thickness >= kThinnestHull * double((high - low).length()) ? Piece::CompactConvex : Piece::ThinConvex;
}

void correctInternalEdges(btCollisionObject& object)
{
  if (!object.getCollisionShape() || !holdsStaticMesh(*object.getCollisionShape()))
    return;
  // Bullet calls one process-wide function for the objects flagged; it only touches mesh contacts.
  gContactAddedCallback = correctInternalEdgeContact;
  object.setCollisionFlags(object.getCollisionFlags() | btCollisionObject::CF_CUSTOM_MATERIAL_CALLBACK);
}

namespace
{
// The shape of a mesh on a moving body (Mobility::Moving) and, in `note`, what it became.
std::shared_ptr<btCollisionShape> movingMeshShape(const std::shared_ptr<const MeshData>& mesh, std::string& note)
{
  const std::string triangles = std::to_string(mesh->triangleCount()) + " triangles";
  std::vector<std::vector<float>> pieces = connectedPieces(*mesh);
  std::vector<Piece> kinds;
  for (const std::vector<float>& piece : pieces)
    kinds.push_back(classifyPiece(piece));
  if (std::count(kinds.begin(), kinds.end(), Piece::Concave))
  {
    note = "collides as its " + triangles + " (Bullet's GImpact: no convex shapes make it up exactly)";
    return std::make_shared<MovingMeshShape>(mesh);
  }
  if (std::count(kinds.begin(), kinds.end(), Piece::ThinConvex))
  {
    note = "collides as its " + triangles + " (Bullet's GImpact: a convex piece of it is too thin for an exact "
           "contact with its hull)";
    return std::make_shared<MovingMeshShape>(mesh);
  }
  if (pieces.size() <= 1)
  {
    auto* hull = makeHull(mesh->vertices.data(), mesh->vertexCount());
    note = "is convex: collides as its convex hull (" + triangles + ", " + std::to_string(hull->getNumPoints()) + " vertices)";
    return std::shared_ptr<btCollisionShape>(hull);
  }
  auto compound = std::make_shared<HullCompound>();
  for (const std::vector<float>& piece : pieces)
    compound->add(makeHull(piece.data(), int(piece.size() / 3)));
  note = "is " + std::to_string(pieces.size()) + " convex pieces: collides as their hulls (" + triangles + ")";
  return compound;
}
}  // namespace

std::shared_ptr<btCollisionShape> makeMeshCollisionShape(const std::shared_ptr<const MeshData>& mesh,
                                                         Mobility mobility)
{
  if (mobility == Mobility::Moving)
  {
    std::string note;
    return movingMeshShape(mesh, note);
  }
  static std::mutex mutex;
  static std::map<const MeshData*, std::weak_ptr<btCollisionShape>> shared;
  const std::lock_guard<std::mutex> lock(mutex);
  for (auto held = shared.begin(); held != shared.end();)
    held = held->second.expired() ? shared.erase(held) : std::next(held);
  std::shared_ptr<btCollisionShape> shape = shared[mesh.get()].lock();
  if (!shape)
  {
    shape = std::make_shared<StaticMeshShape>(mesh);  // keeps `mesh`, so its address names it while shared
    shared[mesh.get()] = shape;
  }
  return shape;
}

Collider makeCollider(const Shape& shape, Mobility mobility, const urdf::Pose& pose, const void* owner)
{
  Collider c;
  if (shape.kind != Shape::Kind::Mesh)
  {
    c.shape.reset(makeCollisionShape(shape));
    if (mobility == Mobility::Moving)
      withFaces(c.shape.get(), shape.kind);
    c.ray = RayPrimitive::fromShape(shape, pose, owner);
    return c;
  }
  std::shared_ptr<const MeshData> mesh = loadMesh(shape.mesh_file, shape.scale, c.reason);
  if (!mesh)
    return c;
  c.shape = mobility == Mobility::Moving ? movingMeshShape(mesh, c.note) : makeMeshCollisionShape(mesh, mobility);
  c.ray = RayPrimitive::fromMesh(mesh, pose, owner);
  c.mesh = mesh;
  return c;
}

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
      shape = new btStaticPlaneShape(toBullet(s.normal), 0);
      break;
    case Shape::Kind::Capsule:
      shape = capsuleAlong(2, s.radius, s.length);
      break;
    case Shape::Kind::Ellipsoid:
      shape = new EllipsoidShape(s.radii);
      break;
    case Shape::Kind::Mesh:
      return nullptr;  // makeCollider
  }
  return withMargin(shape, s.kind);
}

bool fitWheelCylinder(const MeshData& mesh, const btTransform& mesh_pose, const btVector3& axis, Shape& cylinder,
                      btTransform& cylinder_pose)
{
  const btVector3 a = axis.normalized();
  btVector3 u, v;
  btPlaneSpace1(a, u, v);
  constexpr int kDirections = 16;
  btScalar reach[kDirections];
  std::fill(reach, reach + kDirections, btScalar(-1e30));
  btScalar along_lo = btScalar(1e30), along_hi = btScalar(-1e30), radius = 0;
  for (int i = 0; i < mesh.vertexCount(); ++i)
  {
    const btVector3 p = mesh_pose * btVector3(mesh.vertices[3 * i], mesh.vertices[3 * i + 1], mesh.vertices[3 * i + 2]);
    const btScalar along = p.dot(a);
    along_lo = std::min(along_lo, along);
    along_hi = std::max(along_hi, along);
    const btScalar x = p.dot(u), y = p.dot(v);
    radius = std::max(radius, btSqrt(x * x + y * y));
    for (int k = 0; k < kDirections; ++k)
    {
      const btScalar angle = btScalar(2 * M_PI * k / kDirections);
      reach[k] = std::max(reach[k], x * btCos(angle) + y * btSin(angle));
    }
  }
  if (!(radius > 0) || !(along_hi > along_lo))
    return false;
  for (btScalar r : reach)
    if (r < btScalar(0.95) * radius)
      return false;
  cylinder = Shape();
  cylinder.kind = Shape::Kind::Cylinder;
  cylinder.radius = radius;
  cylinder.length = along_hi - along_lo;
  // z onto the axis: the shortest rotation, or a half turn about u where the axis is -z.
  const btVector3 z(0, 0, 1);
  const btVector3 turn = z.cross(a);
  const btQuaternion q = turn.length() > btScalar(1e-6)
                             ? btQuaternion(turn.normalized(), btAcos(btMax(btScalar(-1), btMin(btScalar(1), z.dot(a)))))
                         : z.dot(a) > 0 ? btQuaternion::getIdentity()
                                        : btQuaternion(u, btScalar(M_PI));
  cylinder_pose = btTransform(q, a * ((along_lo + along_hi) / 2));
  return true;
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
      return withFaces(withMargin(new btBoxShape(half), s.kind), s.kind);  // a robot's body
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
    case Shape::Kind::Capsule:
    {
      const int axis = bodyAxisOf(2);
      return axis < 0 ? nullptr : capsuleAlong(axis, s.radius, s.length);
    }
    case Shape::Kind::Ellipsoid:
    {
      std::array<double, 3> radii{{0, 0, 0}};
      for (int k = 0; k < 3; ++k)
      {
        const int i = bodyAxisOf(k);
        if (i < 0)
          return nullptr;
        radii[size_t(i)] = s.radii[size_t(k)];
      }
      return new EllipsoidShape(radii);
    }
    case Shape::Kind::Plane:
    case Shape::Kind::Mesh:
      break;
  }
  return nullptr;
}

bool shapeFromUrdf(const urdf::Geometry& g, const std::string& link, const Log& log, Shape& s)
{
  s = Shape();
  if (const auto* carried = dynamic_cast<const ShapeGeometry*>(&g))
  {
    s = carried->shape;  // checked where it was read (sdf::readGeometry)
    return true;
  }
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
      std::string reason;
      s.kind = Shape::Kind::Mesh;
      s.mesh_uri = mesh.filename;
      s.scale = mesh.scale;
      s.mesh_file = resolveUri(mesh.filename, "", reason);
      if (s.mesh_file.empty())
      {
        log.warn("link '" + link + "': mesh collision '" + mesh.filename + "' not found (" + reason +
                 "); the link has no collision there");
        return false;
      }
      return true;
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
