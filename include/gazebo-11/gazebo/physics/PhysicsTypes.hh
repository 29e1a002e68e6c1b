// The physics classes' names and handle types, as Gazebo 11 declares them (boost::shared_ptr
// handles): what a plugin's header needs to name a ModelPtr before including physics.hh.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include <boost/shared_ptr.hpp>

namespace gazebo
{
namespace physics
{
class Base;
class Entity;
class World;
class Model;
class Link;
class Joint;
class JointController;
class Inertial;
class PhysicsEngine;
class Collision;
class Shape;
class BoxShape;
class CylinderShape;
class SphereShape;
class MeshShape;
class MultiRayShape;
class SurfaceParams;
class FrictionPyramid;

typedef boost::shared_ptr<Base> BasePtr;
typedef boost::shared_ptr<Entity> EntityPtr;
typedef boost::shared_ptr<World> WorldPtr;
typedef boost::shared_ptr<Model> ModelPtr;
typedef boost::shared_ptr<Link> LinkPtr;
typedef boost::shared_ptr<Joint> JointPtr;
typedef boost::shared_ptr<JointController> JointControllerPtr;
typedef boost::shared_ptr<Inertial> InertialPtr;
typedef boost::shared_ptr<PhysicsEngine> PhysicsEnginePtr;
typedef boost::shared_ptr<Collision> CollisionPtr;
typedef boost::shared_ptr<Shape> ShapePtr;
typedef boost::shared_ptr<BoxShape> BoxShapePtr;
typedef boost::shared_ptr<CylinderShape> CylinderShapePtr;
typedef boost::shared_ptr<SphereShape> SphereShapePtr;
typedef boost::shared_ptr<MeshShape> MeshShapePtr;
typedef boost::shared_ptr<MultiRayShape> MultiRayShapePtr;
typedef boost::shared_ptr<SurfaceParams> SurfaceParamsPtr;
typedef std::shared_ptr<FrictionPyramid> FrictionPyramidPtr;

typedef std::vector<WorldPtr> World_V;
typedef std::vector<ModelPtr> Model_V;
typedef std::vector<LinkPtr> Link_V;
typedef std::vector<JointPtr> Joint_V;
typedef std::vector<CollisionPtr> Collision_V;
}  // namespace physics
}  // namespace gazebo
