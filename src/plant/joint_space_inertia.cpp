#include "joint_space_inertia.h"

#include <algorithm>
#include <cmath>

#include <BulletDynamics/Featherstone/btMultiBody.h>

namespace bullet_plant
{
namespace
{
void cross(const double* a, const double* b, double* out)
{
  out[0] = a[1] * b[2] - a[2] * b[1];
  out[1] = a[2] * b[0] - a[0] * b[2];
  out[2] = a[0] * b[1] - a[1] * b[0];
}

// y = R x and y = R^T x for a row-major 3 x 3 R.
void rotate(const double* R, const double* x, double* y)
{
  for (int a = 0; a < 3; ++a)
    y[a] = R[3 * a] * x[0] + R[3 * a + 1] * x[1] + R[3 * a + 2] * x[2];
}

void rotateBack(const double* R, const double* x, double* y)
{
  for (int a = 0; a < 3; ++a)
    y[a] = R[a] * x[0] + R[3 + a] * x[1] + R[6 + a] * x[2];
}

double norm(const double* x) { return std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]); }
}  // namespace

bool JointSpaceInertia::update(const btMultiBody& body)
{
  const int links = body.getNumLinks();
  n_ = body.getNumDofs() + 6;
  first_ = body.hasFixedBase() ? 6 : 0;
  frames_.resize(links + 1);
  composites_.resize(links + 1);
  dofs_.resize(n_);
  inertia_.assign(size_t(n_) * n_, 0.0);
  double* m = inertia_.data();

  // Where the bodies are: rotations from the world and centres of mass, base outwards.
  const btMatrix3x3 world_to_base(body.getWorldToBaseRot());
  Frame& base = frames_[0];
  base.parent = -1;
  base.first_dof = 0;
  base.dof_count = 0;
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
      base.rotation[3 * r + c] = world_to_base[r][c];
    base.com[r] = body.getBasePos()[r];
  }
  for (int i = 0; i < links; ++i)
  {
    const btMultibodyLink& link = body.getLink(i);
    const Frame& from = frames_[link.m_parent + 1];
    Frame& to = frames_[i + 1];
    to.parent = link.m_parent + 1;
    to.first_dof = 6 + link.m_dofOffset;
    to.dof_count = link.m_dofCount;
    const btMatrix3x3 rotation(link.m_cachedRotParentToThis);
    const btVector3& r = link.m_cachedRVector;  // parent's centre of mass to this one's, in this frame
    for (int a = 0; a < 3; ++a)
    {
      for (int c = 0; c < 3; ++c)
        to.from_parent[3 * a + c] = rotation[a][c];
      to.offset[a] = r[a];
    }
    const double* R = to.from_parent;
    for (int a = 0; a < 3; ++a)
      for (int c = 0; c < 3; ++c)
        to.rotation[3 * a + c] = R[3 * a] * from.rotation[c] + R[3 * a + 1] * from.rotation[3 + c] +
                                 R[3 * a + 2] * from.rotation[6 + c];
    rotateBack(to.rotation, to.offset, to.com);
    for (int a = 0; a < 3; ++a)
      to.com[a] += from.com[a];
    // The joint's motions in world axes, at the link's centre of mass.
    for (int d = 0; d < link.m_dofCount; ++d)
    {
      Dof& dof = dofs_[to.first_dof + d];
      const double top[3] = {link.getAxisTop(d).x(), link.getAxisTop(d).y(), link.getAxisTop(d).z()};
      const double bottom[3] = {link.getAxisBottom(d).x(), link.getAxisBottom(d).y(), link.getAxisBottom(d).z()};
      rotateBack(to.rotation, top, dof.angular);
      rotateBack(to.rotation, bottom, dof.linear);
      dof.body = i + 1;
    }
  }

  // Composite rigid bodies: each body with everything beyond it, as mass, first moment and
  // rotational inertia about the body's centre of mass, in world axes (leaves inwards).
  for (int b = 0; b <= links; ++b)
  {
    Composite& c = composites_[b];
    const btVector3 own = b == 0 ? body.getBaseInertia() : body.getLink(b - 1).m_inertiaLocal;
    c.mass = b == 0 ? body.getBaseMass() : body.getLink(b - 1).m_mass;
    c.moment[0] = c.moment[1] = c.moment[2] = 0;
    const double* R = frames_[b].rotation;  // world to body: I_world = R^T diag(own) R
    for (int a = 0; a < 3; ++a)
      for (int e = 0; e < 3; ++e)
        c.inertia[3 * a + e] = R[a] * own.x() * R[e] + R[3 + a] * own.y() * R[3 + e] + R[6 + a] * own.z() * R[6 + e];
  }
  for (int b = links; b >= 1; --b)
  {
    const Composite& child = composites_[b];
    Composite& parent = composites_[frames_[b].parent];
    double d[3];  // the child's reference point from the parent's
    for (int a = 0; a < 3; ++a)
      d[a] = frames_[b].com[a] - frames_[frames_[b].parent].com[a];
    // Moved from the child's point to the parent's: I += I_c + 2 (h.d) E - h d^T - d h^T + m (|d|^2 E - d d^T).
    const double hd = child.moment[0] * d[0] + child.moment[1] * d[1] + child.moment[2] * d[2];
    const double dd = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    for (int a = 0; a < 3; ++a)
      for (int e = 0; e < 3; ++e)
        parent.inertia[3 * a + e] += child.inertia[3 * a + e] - child.moment[a] * d[e] - d[a] * child.moment[e] -
                                     child.mass * d[a] * d[e] + (a == e ? 2 * hd + child.mass * dd : 0.0);
    for (int a = 0; a < 3; ++a)
      parent.moment[a] += child.moment[a] + child.mass * d[a];
    parent.mass += child.mass;
  }

  // M, lower triangle. A unit motion (w, v at point P) of a composite with first moment h and
  // rotational inertia I about P meets the momentum (I w + h x v, m v - h x w).
  if (!first_)
  {
    const Composite& all = composites_[0];
    for (int k = 0; k < 3; ++k)
    {
      double e[3] = {0, 0, 0}, eh[3];
      e[k] = 1;
      cross(e, all.moment, eh);  // base angular column k: linear momentum e_k x h
      for (int a = 0; a <= k; ++a)
        m[size_t(a) * n_ + k] = m[size_t(k) * n_ + a] = all.inertia[3 * a + k];
      for (int a = 0; a < 3; ++a)
        m[size_t(3 + a) * n_ + k] = eh[a];
      m[size_t(3 + k) * n_ + 3 + k] = all.mass;
    }
  }
  for (int j = 6; j < n_; ++j)
  {
    const Dof& dof = dofs_[j];
    const Composite& c = composites_[dof.body];
    const double* com = frames_[dof.body].com;
    double hv[3], hw[3], L[3], p[3];
    cross(c.moment, dof.linear, hv);
    cross(c.moment, dof.angular, hw);
    rotate(c.inertia, dof.angular, L);
    for (int a = 0; a < 3; ++a)
    {
      L[a] += hv[a];
      p[a] = c.mass * dof.linear[a] - hw[a];
    }
    double* row = m + size_t(j) * n_;
    // This joint and the ones between its body and the base (lower indices): their motions of
    // the point com.
    for (int b = dof.body; b > 0; b = frames_[b].parent)
    {
      const Frame& frame = frames_[b];
      double d[3];
      for (int a = 0; a < 3; ++a)
        d[a] = com[a] - frame.com[a];
      for (int i = frame.first_dof; i < frame.first_dof + frame.dof_count && i <= j; ++i)
      {
        const Dof& other = dofs_[i];
        double wd[3];
        cross(other.angular, d, wd);
        row[i] = other.angular[0] * L[0] + other.angular[1] * L[1] + other.angular[2] * L[2] +
                 (other.linear[0] + wd[0]) * p[0] + (other.linear[1] + wd[1]) * p[1] + (other.linear[2] + wd[2]) * p[2];
      }
    }
    if (!first_)
    {
      // Base angular column k moves the point com by e_k x (com - base com): L + d x p.
      double d[3], dp[3];
      for (int a = 0; a < 3; ++a)
        d[a] = com[a] - frames_[0].com[a];
      cross(d, p, dp);
      for (int a = 0; a < 3; ++a)
      {
        row[a] = L[a] + dp[a];
        row[3 + a] = p[a];
      }
    }
  }

  // Cholesky, M = L L^T, over the velocities that move.
  lower_.assign(size_t(n_) * n_, 0.0);
  inverse_diagonal_.assign(n_, 0.0);
  for (int j = first_; j < n_; ++j)
  {
    const double* Lj = &lower_[size_t(j) * n_];
    double diagonal = m[size_t(j) * n_ + j];
    for (int k = first_; k < j; ++k)
      diagonal -= Lj[k] * Lj[k];
    if (!(diagonal > 0))
      return false;
    const double ljj = std::sqrt(diagonal);
    lower_[size_t(j) * n_ + j] = ljj;
    inverse_diagonal_[j] = 1.0 / ljj;
    for (int i = j + 1; i < n_; ++i)
    {
      double* Li = &lower_[size_t(i) * n_];
      double s = m[size_t(i) * n_ + j];
      for (int k = first_; k < j; ++k)
        s -= Li[k] * Lj[k];
      Li[j] = s * inverse_diagonal_[j];
    }
  }
  lower_scalar_.assign(lower_.begin(), lower_.end());
  inverse_diagonal_scalar_.assign(inverse_diagonal_.begin(), inverse_diagonal_.end());
  return true;
}


void JointSpaceInertia::accelerations(const btMultiBody& body, btScalar* qdd)
{
  const int links = body.getNumLinks();
  velocity_.resize(links + 1);
  acceleration_.resize(links + 1);
  force_.resize(links + 1);
  generalized_.assign(n_, 0.0);
  const btScalar* qd = body.getVelocityVector();
  const double linear_damping = body.getLinearDamping(), angular_damping = body.getAngularDamping();
  const bool gyroscopic = body.getUseGyroTerm();

  // f = I a + v x* I v + damping - applied, at the body's centre of mass in its frame (Bullet's
  // "zero-acceleration force" plus the inertial force of the acceleration).
  auto bodyForce = [&](int b, const btVector3& inertia, double mass, const btVector3& applied_torque,
                       const btVector3& applied_force) {
    const Motion& v = velocity_[b];
    const Motion& a = acceleration_[b];
    Motion& f = force_[b];
    const double I[3] = {inertia.x(), inertia.y(), inertia.z()};
    const double Iw[3] = {I[0] * v.w[0], I[1] * v.w[1], I[2] * v.w[2]};
    const double torque_world[3] = {applied_torque.x(), applied_torque.y(), applied_torque.z()};
    const double force_world[3] = {applied_force.x(), applied_force.y(), applied_force.z()};
    double torque[3], force[3], gyro[3] = {0, 0, 0}, wv[3];
    rotate(frames_[b].rotation, torque_world, torque);
    rotate(frames_[b].rotation, force_world, force);
    if (gyroscopic)
      cross(v.w, Iw, gyro);
    cross(v.w, v.v, wv);
    const double angular = angular_damping * (1 + norm(v.w)), linear = linear_damping * (1 + norm(v.v));
    for (int k = 0; k < 3; ++k)
    {
      f.w[k] = I[k] * a.w[k] + gyro[k] + Iw[k] * angular - torque[k];
      f.v[k] = mass * (a.v[k] + wv[k] + v.v[k] * linear) - force[k];
    }
  };

  // Outward: velocities, and accelerations with qdd = 0 in Bullet's coordinates. For the base
  // that is a constant world-frame angular and centre-of-mass velocity, i.e. a body-frame
  // spatial acceleration (0, -w x v).
  Motion& v0 = velocity_[0];
  Motion& a0 = acceleration_[0];
  v0 = a0 = Motion{};
  if (!first_)
  {
    const double w_world[3] = {qd[0], qd[1], qd[2]}, v_world[3] = {qd[3], qd[4], qd[5]};
    rotate(frames_[0].rotation, w_world, v0.w);
    rotate(frames_[0].rotation, v_world, v0.v);
    cross(v0.v, v0.w, a0.v);
  }
  bodyForce(0, body.getBaseInertia(), body.getBaseMass(), body.getBaseTorque(), body.getBaseForce());
  for (int i = 0; i < links; ++i)
  {
    const btMultibodyLink& link = body.getLink(i);
    const int b = i + 1, p = link.m_parent + 1;
    const Frame& frame = frames_[b];
    // Parent to link: w' = R w, v' = R v + w' x r (the same for accelerations).
    auto transform = [&](const Motion& in, Motion& out) {
      rotate(frame.from_parent, in.w, out.w);
      rotate(frame.from_parent, in.v, out.v);
      double wr[3];
      cross(out.w, frame.offset, wr);
      for (int k = 0; k < 3; ++k)
        out.v[k] += wr[k];
    };
    Motion joint{};  // the joint's own velocity S qd
    for (int d = 0; d < link.m_dofCount; ++d)
    {
      const double rate = qd[6 + link.m_dofOffset + d];
      const btVector3& top = link.getAxisTop(d);
      const btVector3& bottom = link.getAxisBottom(d);
      for (int k = 0; k < 3; ++k)
      {
        joint.w[k] += top[k] * rate;
        joint.v[k] += bottom[k] * rate;
      }
    }
    Motion& v = velocity_[b];
    Motion& a = acceleration_[b];
    transform(velocity_[p], v);
    transform(acceleration_[p], a);
    for (int k = 0; k < 3; ++k)
    {
      v.w[k] += joint.w[k];
      v.v[k] += joint.v[k];
    }
    // The velocity-product acceleration v x S qd.
    double ww[3], vw[3], wv[3];
    cross(v.w, joint.w, ww);
    cross(v.v, joint.w, vw);
    cross(v.w, joint.v, wv);
    for (int k = 0; k < 3; ++k)
    {
      a.w[k] += ww[k];
      a.v[k] += vw[k] + wv[k];
    }
    bodyForce(b, link.m_inertiaLocal, link.m_mass, body.getLinkTorque(i), body.getLinkForce(i));
  }

  // Inward: each joint's share of the forces beyond it, and those forces moved to the parent:
  // f_p += (R^T (n + r x f), R^T f).
  for (int i = links - 1; i >= 0; --i)
  {
    const btMultibodyLink& link = body.getLink(i);
    const int b = i + 1, p = link.m_parent + 1;
    const Motion& f = force_[b];
    for (int d = 0; d < link.m_dofCount; ++d)
    {
      const btVector3& top = link.getAxisTop(d);
      const btVector3& bottom = link.getAxisBottom(d);
      generalized_[6 + link.m_dofOffset + d] = top.x() * f.w[0] + top.y() * f.w[1] + top.z() * f.w[2] +
                                               bottom.x() * f.v[0] + bottom.y() * f.v[1] + bottom.z() * f.v[2];
    }
    const Frame& frame = frames_[b];
    double rf[3], moment[3], n[3], lin[3];
    cross(frame.offset, f.v, rf);
    for (int k = 0; k < 3; ++k)
      moment[k] = f.w[k] + rf[k];
    rotateBack(frame.from_parent, moment, n);
    rotateBack(frame.from_parent, f.v, lin);
    for (int k = 0; k < 3; ++k)
    {
      force_[p].w[k] += n[k];
      force_[p].v[k] += lin[k];
    }
  }
  if (!first_)
  {
    rotateBack(frames_[0].rotation, force_[0].w, &generalized_[0]);
    rotateBack(frames_[0].rotation, force_[0].v, &generalized_[3]);
  }

  // qdd = M^-1 (tau - C)
  for (int i = 0; i < n_; ++i)
    generalized_[i] = -generalized_[i];
  for (int i = 0; i < links; ++i)
  {
    const btMultibodyLink& link = body.getLink(i);
    const btScalar* torque = const_cast<btMultiBody&>(body).getJointTorqueMultiDof(i);
    for (int d = 0; d < link.m_dofCount; ++d)
      generalized_[6 + link.m_dofOffset + d] += torque[d];
  }
  solve(generalized_.data());
  for (int i = 0; i < n_; ++i)
    qdd[i] = btScalar(generalized_[i]);
}

void JointSpaceInertia::solve(double* x) const
{
  const double* L = lower_.data();
  for (int i = first_; i < n_; ++i)
  {
    double s = x[i];
    for (int j = first_; j < i; ++j)
      s -= L[size_t(i) * n_ + j] * x[j];
    x[i] = s * inverse_diagonal_[i];
  }
  for (int i = n_ - 1; i >= first_; --i)
  {
    double s = x[i];
    for (int j = i + 1; j < n_; ++j)
      s -= L[size_t(j) * n_ + i] * x[j];
    x[i] = s * inverse_diagonal_[i];
  }
  std::fill(x, x + first_, 0.0);
}

void JointSpaceInertia::contactJacobian(int link, const btVector3& point, const btVector3& direction, btScalar* row) const
{
  const double n[3] = {direction.x(), direction.y(), direction.z()};
  std::fill(row, row + n_, btScalar(0));
  // A motion (w, v at the centre of mass c) moves the point by v + w x (point - c); along n that
  // is n . v + w . ((point - c) x n).
  auto lever = [&](const double* com, double* out) {
    const double arm[3] = {point.x() - com[0], point.y() - com[1], point.z() - com[2]};
    cross(arm, n, out);
  };
  for (int b = link + 1; b > 0; b = frames_[b].parent)
  {
    const Frame& frame = frames_[b];
    double l[3];
    lever(frame.com, l);
    for (int i = frame.first_dof; i < frame.first_dof + frame.dof_count; ++i)
    {
      const Dof& dof = dofs_[i];
      row[i] = btScalar(n[0] * dof.linear[0] + n[1] * dof.linear[1] + n[2] * dof.linear[2] + l[0] * dof.angular[0] +
                        l[1] * dof.angular[1] + l[2] * dof.angular[2]);
    }
  }
  if (!first_)
  {
    double l[3];
    lever(frames_[0].com, l);
    for (int a = 0; a < 3; ++a)
    {
      row[a] = btScalar(l[a]);
      row[3 + a] = btScalar(n[a]);
    }
  }
}

namespace
{
// kSides right-hand sides side by side: one SSE register of floats (GCC/Clang vector extension;
// loads and stores through it need only a scalar's alignment).
typedef btScalar Sides
    __attribute__((vector_size(JointSpaceInertia::kSides * sizeof(btScalar)), aligned(sizeof(btScalar)), may_alias));
}  // namespace

// The solves step through the degrees of freedom with one block of sides in a register: each step
// is a multiply-add of the block and no store. In the solver's precision (float), as Bullet's
// own articulated-body pass: against the double solve the responses and the block differ by
// 1.4e-7 of their largest entry (the car driving, steering and tumbling).
void JointSpaceInertia::solveColumns(btScalar* x, int count, btScalar* gram) const
{
  const int k = count;
  const btScalar* L = lower_scalar_.data();
  const btScalar* inverse_diagonal = inverse_diagonal_scalar_.data();
  auto at = [&](int i, int r) { return reinterpret_cast<Sides*>(x + size_t(i) * k + r); };
  for (int r = 0; r < k; r += kSides)
  {
    // Forward substitution, y = L^-1 x.
    for (int i = first_; i < n_; ++i)
    {
      const btScalar* Li = L + size_t(i) * n_;
      Sides acc = *at(i, r);
      for (int j = first_; j < i; ++j)
        acc -= Li[j] * *at(j, r);
      *at(i, r) = acc * inverse_diagonal[i];
    }
  }
  // x^T M^-1 x = y^T y, block by block of its upper triangle.
  for (int r = 0; r < k; r += kSides)
    for (int s = r; s < k; s += kSides)
    {
      Sides acc[kSides] = {};
      for (int i = first_; i < n_; ++i)
      {
        const btScalar* yr = x + size_t(i) * k + r;
        const Sides ys = *at(i, s);
        for (int u = 0; u < kSides; ++u)
          acc[u] += yr[u] * ys;
      }
      for (int u = 0; u < kSides; ++u)
        for (int t = 0; t < kSides; ++t)
        {
          gram[size_t(r + u) * k + s + t] = acc[u][t];
          gram[size_t(s + t) * k + r + u] = acc[u][t];
        }
    }
  for (int r = 0; r < k; r += kSides)
  {
    // Back substitution, x = L^-T y.
    for (int i = n_ - 1; i >= first_; --i)
    {
      Sides acc = *at(i, r);
      for (int j = i + 1; j < n_; ++j)
        acc -= L[size_t(j) * n_ + i] * *at(j, r);
      *at(i, r) = acc * inverse_diagonal[i];
    }
  }
  std::fill(x, x + size_t(first_) * k, btScalar(0));
}

}  // namespace bullet_plant
