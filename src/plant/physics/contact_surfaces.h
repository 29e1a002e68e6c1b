// SDF's <surface> per collision, combined for each contact point as Gazebo's ODE combines two
// surfaces (ODEPhysics::Collide and ODE's contact joint): friction mu along the first friction
// direction and mu2 across it, each the smaller of the two surfaces'; the first direction fdir1 of
// the surface that gives one (the one with the smaller mu where both do), else ODE's default
// (dPlaneSpace of the normal, Bullet's btPlaneSpace1: the same vectors); ODE's force-dependent
// slip (slip1 along the first direction, slip2 across it) the larger of the two surfaces', so that
// a wheel's slip is felt on a ground that gives none (Gazebo's WheelSlipPlugin sets the wheel's);
// kp and kd as a
// spring-damper, kp in series (1 / (1/kp1 + 1/kp2)) and kd summed, a surface that does not say
// taking SDF's defaults (1e12, 1); min_depth (the depth a contact is not pushed out of) and max_vel
// (the speed it pushes out at most) the smaller of the two bodies' that move, as ODE keeps them per
// body. The solver asks before it builds a manifold's rows (DenseRowSolver::convertContacts); objects
// without surfaces keep the plant's own contact (their Bullet friction, a rigid row), so a world
// without any costs one empty() a step.
#pragma once

#include <unordered_map>
#include <vector>

#include <BulletCollision/CollisionDispatch/btCollisionObject.h>
#include <BulletCollision/NarrowPhaseCollision/btPersistentManifold.h>
#include <BulletDynamics/ConstraintSolver/btContactSolverInfo.h>

namespace bullet_plant
{
// One collision's surface, in the plant's units; negative for what the SDF does not give.
struct ContactSurface
{
  btScalar mu1 = 1, mu2 = 1;
  btVector3 fdir1{0, 0, 0};  // in the collision object's frame; zero: none
  // ODE's force-dependent slip (m/s per N of friction) along fdir1 and across it; 0: none.
  btScalar slip1 = 0, slip2 = 0;
  btScalar kp = -1, kd = -1;
  btScalar max_vel = -1, min_depth = -1;
};

// What a contact point gets from its two surfaces beyond what the point itself holds (its first
// friction coefficient in m_combinedFriction, its directions, stiffness and damping).
struct PointSurface
{
  btScalar mu2 = 0;
  // The slip of its friction rows along the first direction and the second (ContactSurface).
  btScalar slip1 = 0, slip2 = 0;
  // The largest speed its depth is corrected at (max_vel): BT_LARGE_FLOAT where no body gives one,
  // and for a spring-damper contact, whose push its own law bounds (docs/sdf.md).
  btScalar max_vel = BT_LARGE_FLOAT;
};

class ContactSurfaces
{
public:
  // The surfaces of an object: one for all of its shape, or one per child of its compound shape
  // (Bullet's child index, which a manifold point keeps in m_index0 / m_index1). `moving`: the
  // object is a body of its own (ODE keeps max_vel and min_depth per body; a static model has none).
  void set(const btCollisionObject& object, std::vector<ContactSurface> children, bool moving);
  void forget(const btCollisionObject* object) { objects_.erase(object); }
  // The surfaces of an object, to change from the next step on (a plugin's SurfaceParams): its
  // own, or, for an object that has none, `children` copies of `plain` made now.
  std::vector<ContactSurface>& edit(const btCollisionObject& object, size_t children, const ContactSurface& plain,
                                    bool moving);
  bool empty() const { return objects_.empty(); }

  // For every point of the manifold: its friction coefficient along the first direction
  // (m_combinedFriction), its two friction directions, its stiffness and damping (Bullet's
  // BT_CONTACT_FLAG_CONTACT_STIFFNESS_DAMPING, which Bullet's rows and the plant's read alike), its
  // depth less min_depth, and `points[j]`. False, touching nothing, where neither object has
  // surfaces. `points` holds the manifold's number of points.
  bool apply(btPersistentManifold& manifold, PointSurface* points) const;

private:
  struct Entry
  {
    std::vector<ContactSurface> children;
    bool moving = true;
  };
  std::unordered_map<const btCollisionObject*, Entry> objects_;
};

}  // namespace bullet_plant
