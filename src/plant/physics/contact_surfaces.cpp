#include "physics/contact_surfaces.h"

#include <algorithm>

#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>

namespace bullet_plant
{
namespace
{
// SDF's defaults for a surface that gives no <kp>, <kd> (sdformat's surface.sdf).
constexpr btScalar kDefaultKp = 1e12;
constexpr btScalar kDefaultKd = 1;

// Whether an object without surfaces is a body of its own: not a static object, nor the base of a
// multibody fixed in the world (a <static> model's link, which Gazebo gives no ODE body).
bool movesOnItsOwn(const btCollisionObject& object)
{
  if (object.isStaticObject())
    return false;
  const auto* collider = btMultiBodyLinkCollider::upcast(&object);
  return !(collider && collider->m_link < 0 && collider->m_multiBody->hasFixedBase());
}

// A side of a contact: its surface (one of its own, or one that holds only its Bullet friction) and
// whether it counts for the per-body max_vel and min_depth.
struct Side
{
  ContactSurface own;
  const ContactSurface* surface;
  bool moving;
};
}  // namespace

void ContactSurfaces::set(const btCollisionObject& object, std::vector<ContactSurface> children, bool moving)
{
  if (children.empty())
  {
    objects_.erase(&object);
    return;
  }
  Entry& entry = objects_[&object];
  entry.children = std::move(children);
  entry.moving = moving;
}

std::vector<ContactSurface>& ContactSurfaces::edit(const btCollisionObject& object, size_t children,
                                                  const ContactSurface& plain, bool moving)
{
  auto found = objects_.find(&object);
  if (found != objects_.end())
    return found->second.children;
  Entry& entry = objects_[&object];
  entry.children.assign(std::max<size_t>(children, 1), plain);
  entry.moving = moving;
  return entry.children;
}

bool ContactSurfaces::apply(btPersistentManifold& manifold, PointSurface* points) const
{
  const btCollisionObject* objects[2] = {manifold.getBody0(), manifold.getBody1()};
  const Entry* entries[2] = {nullptr, nullptr};
  for (int s = 0; s < 2; ++s)
  {
    auto found = objects_.find(objects[s]);
    if (found != objects_.end())
      entries[s] = &found->second;
  }
  if (!entries[0] && !entries[1])
    return false;
  Side sides[2];
  for (int s = 0; s < 2; ++s)
  {
    sides[s].own.mu1 = sides[s].own.mu2 = objects[s]->getFriction();
    sides[s].surface = &sides[s].own;
    sides[s].moving = entries[s] ? entries[s]->moving : movesOnItsOwn(*objects[s]);
  }
  for (int j = 0; j < manifold.getNumContacts(); ++j)
  {
    btManifoldPoint& point = manifold.getContactPoint(j);
    const int child[2] = {point.m_index0, point.m_index1};
    for (int s = 0; s < 2; ++s)
      if (entries[s])
      {
        const std::vector<ContactSurface>& children = entries[s]->children;
        // One surface for the whole shape; else the compound's child (a triangle mesh inside a
        // compound reports its triangle there: the first child's surface then).
        const size_t k = children.size() > 1 && child[s] >= 0 && size_t(child[s]) < children.size() ? size_t(child[s]) : 0;
        sides[s].surface = &children[k];
      }
    const ContactSurface& a = *sides[0].surface;
    const ContactSurface& b = *sides[1].surface;

    // Friction: ODE's pyramid, mu along the first direction and mu2 along the second.
    point.m_combinedFriction = std::min(a.mu1, b.mu1);
    points[j].mu2 = std::min(a.mu2, b.mu2);
    points[j].slip1 = std::max(a.slip1, b.slip1);
    points[j].slip2 = std::max(a.slip2, b.slip2);
    btVector3 fdir(0, 0, 0);
    if (!a.fdir1.isZero())
      fdir = objects[0]->getWorldTransform().getBasis() * a.fdir1;
    if (!b.fdir1.isZero() && (a.fdir1.isZero() || a.mu1 > b.mu1))
      fdir = objects[1]->getWorldTransform().getBasis() * b.fdir1;
    const btVector3& normal = point.m_normalWorldOnB;
    // ODE takes fdir1 as it is, meant to lie in the contact plane; the plant takes its part that
    // does. One along the normal leaves ODE's default, as ODE does.
    const btVector3 tangent = fdir - normal * normal.dot(fdir);
    if (!fdir.isZero() && tangent.length2() > btScalar(1e-12) * fdir.length2())
    {
      point.m_lateralFrictionDir1 = tangent.normalized();
      point.m_lateralFrictionDir2 = normal.cross(point.m_lateralFrictionDir1);
    }
    else
    {
      btPlaneSpace1(normal, point.m_lateralFrictionDir1, point.m_lateralFrictionDir2);
      point.m_lateralFrictionDir1.normalize();
      point.m_lateralFrictionDir2.normalize();
    }

    // Contact stiffness: ODE's erp = dt kp / (dt kp + kd), cfm = 1 / (dt kp + kd), from Bullet's
    // fields (normalRowSoftness and Bullet's own rows compute exactly those).
    const bool spring = a.kp > 0 || a.kd >= 0 || b.kp > 0 || b.kd >= 0;
    if (spring)
    {
      const btScalar kp_a = a.kp > 0 ? a.kp : kDefaultKp, kp_b = b.kp > 0 ? b.kp : kDefaultKp;
      point.m_combinedContactStiffness1 = 1 / (1 / kp_a + 1 / kp_b);
      point.m_combinedContactDamping1 = (a.kd >= 0 ? a.kd : kDefaultKd) + (b.kd >= 0 ? b.kd : kDefaultKd);
      point.m_contactPointFlags |= BT_CONTACT_FLAG_CONTACT_STIFFNESS_DAMPING;
    }
    else
    {
      point.m_contactPointFlags &= ~BT_CONTACT_FLAG_CONTACT_STIFFNESS_DAMPING;
    }

    // min_depth and max_vel: the smaller of the moving bodies'. A body that does not give
    // min_depth has SDF's 0; one that does not give max_vel, the world's cap (the solver's).
    btScalar min_depth = BT_LARGE_FLOAT, max_vel = BT_LARGE_FLOAT;
    for (const Side& side : sides)
      if (side.moving)
      {
        min_depth = std::min(min_depth, side.surface->min_depth > 0 ? side.surface->min_depth : btScalar(0));
        if (side.surface->max_vel >= 0)
          max_vel = std::min(max_vel, side.surface->max_vel);
      }
    // ODE pushes a contact out by its depth less min_depth, and not at all above that: the
    // solver's rows (Bullet's and the plant's) read the point's distance, which the manifold
    // measures again at the next step.
    const btScalar distance = point.getDistance();
    if (min_depth > 0 && min_depth < BT_LARGE_FLOAT && distance < 0)
      point.m_distance1 = std::min(distance + min_depth, btScalar(0));
    points[j].max_vel = spring ? BT_LARGE_FLOAT : max_vel;
  }
  return true;
}

}  // namespace bullet_plant
