#include "joint_space_inertia.h"

#include <algorithm>
#include <cmath>

#include <BulletDynamics/Featherstone/btMultiBody.h>

namespace bullet_plant
{
bool JointSpaceInertia::update(const btMultiBody& body)
{
  const int links = body.getNumLinks();
  n_ = body.getNumDofs() + 6;
  first_ = body.hasFixedBase() ? 6 : 0;
  // Body b's Jacobian has non-zero columns only for the base and the joints between b and the
  // base: columns_[b] lists them, motions_ holds those columns, body after body.
  first_column_.resize(links + 2);
  first_column_[0] = 0;
  first_column_[1] = first_ ? 0 : 6;
  for (int i = 0; i < links; ++i)
  {
    const btMultibodyLink& link = body.getLink(i);
    const int parent = link.m_parent + 1;
    first_column_[i + 2] =
        first_column_[i + 1] + first_column_[parent + 1] - first_column_[parent] + link.m_dofCount;
  }
  motions_.resize(first_column_[links + 1]);
  columns_.resize(first_column_[links + 1]);
  frames_.resize(links + 1);
  inertia_.assign(size_t(n_) * n_, 0.0);
  double* m = inertia_.data();

  // Adds J_b^T diag(inertia, mass) J_b to M (lower triangle) over b's columns.
  auto addBody = [&](int b, const btVector3& inertia, double mass) {
    const int begin = first_column_[b], end = first_column_[b + 1];
    for (int p = begin; p < end; ++p)
    {
      const Motion& cp = motions_[p];
      const double wp[3] = {inertia.x() * cp.w[0], inertia.y() * cp.w[1], inertia.z() * cp.w[2]};
      const double vp[3] = {mass * cp.v[0], mass * cp.v[1], mass * cp.v[2]};
      double* row = m + size_t(columns_[p]) * n_;
      // A body's columns are in increasing generalized index: q <= p is the lower triangle.
      for (int q = begin; q <= p; ++q)
      {
        const Motion& cq = motions_[q];
        row[columns_[q]] += wp[0] * cq.w[0] + wp[1] * cq.w[1] + wp[2] * cq.w[2] + vp[0] * cq.v[0] + vp[1] * cq.v[1] +
                            vp[2] * cq.v[2];
      }
    }
  };

  // The base: its spatial velocity is the world-frame angular and linear velocity, rotated in.
  const btMatrix3x3 world_to_base(body.getWorldToBaseRot());
  Frame& base = frames_[0];
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
      base.rotation[3 * r + c] = world_to_base[r][c];
    base.com[r] = body.getBasePos()[r];
  }
  if (!first_)
    for (int a = 0; a < 6; ++a)
    {
      Motion& c = motions_[a];
      for (int r = 0; r < 3; ++r)
      {
        c.w[r] = a < 3 ? base.rotation[3 * r + a] : 0.0;
        c.v[r] = a < 3 ? 0.0 : base.rotation[3 * r + a - 3];
      }
      columns_[a] = a;
    }
  addBody(0, body.getBaseInertia(), body.getBaseMass());

  for (int i = 0; i < links; ++i)
  {
    const btMultibodyLink& link = body.getLink(i);
    const int parent = link.m_parent + 1;  // body index: 0 is the base
    const btMatrix3x3 rotation(link.m_cachedRotParentToThis);
    const btVector3& r = link.m_cachedRVector;  // parent's centre of mass to this one's, in this frame
    double R[9];
    for (int a = 0; a < 3; ++a)
      for (int c = 0; c < 3; ++c)
        R[3 * a + c] = rotation[a][c];

    const Frame& from = frames_[parent];
    Frame& to = frames_[i + 1];
    std::copy(R, R + 9, to.from_parent);
    to.offset[0] = r.x();
    to.offset[1] = r.y();
    to.offset[2] = r.z();
    for (int a = 0; a < 3; ++a)
      for (int c = 0; c < 3; ++c)
        to.rotation[3 * a + c] = R[3 * a] * from.rotation[c] + R[3 * a + 1] * from.rotation[3 + c] +
                                 R[3 * a + 2] * from.rotation[6 + c];
    for (int a = 0; a < 3; ++a)
      to.com[a] = from.com[a] + to.rotation[a] * r.x() + to.rotation[3 + a] * r.y() + to.rotation[6 + a] * r.z();

    // The parent's columns seen from this body: w' = R w, v' = R v + w' x r.
    int column = first_column_[i + 1];
    for (int p = first_column_[parent]; p < first_column_[parent + 1]; ++p, ++column)
    {
      const Motion& in = motions_[p];
      Motion& out = motions_[column];
      for (int a = 0; a < 3; ++a)
      {
        out.w[a] = R[3 * a] * in.w[0] + R[3 * a + 1] * in.w[1] + R[3 * a + 2] * in.w[2];
        out.v[a] = R[3 * a] * in.v[0] + R[3 * a + 1] * in.v[1] + R[3 * a + 2] * in.v[2];
      }
      out.v[0] += out.w[1] * r.z() - out.w[2] * r.y();
      out.v[1] += out.w[2] * r.x() - out.w[0] * r.z();
      out.v[2] += out.w[0] * r.y() - out.w[1] * r.x();
      columns_[column] = columns_[p];
    }
    for (int d = 0; d < link.m_dofCount; ++d, ++column)
    {
      const btVector3& top = link.getAxisTop(d);
      const btVector3& bottom = link.getAxisBottom(d);
      Motion& axis = motions_[column];
      for (int a = 0; a < 3; ++a)
      {
        axis.w[a] = top[a];
        axis.v[a] = bottom[a];
      }
      columns_[column] = 6 + link.m_dofOffset + d;
    }
    addBody(i + 1, link.m_inertiaLocal, link.m_mass);
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
  const int b = link + 1;
  const Frame& frame = frames_[b];
  const double* R = frame.rotation;
  const double arm[3] = {point.x() - frame.com[0], point.y() - frame.com[1], point.z() - frame.com[2]};
  const double d[3] = {direction.x(), direction.y(), direction.z()};
  double r[3], n[3];  // the arm and the direction in the body's frame
  for (int a = 0; a < 3; ++a)
  {
    r[a] = R[3 * a] * arm[0] + R[3 * a + 1] * arm[1] + R[3 * a + 2] * arm[2];
    n[a] = R[3 * a] * d[0] + R[3 * a + 1] * d[1] + R[3 * a + 2] * d[2];
  }
  // n . (v + w x r) = n . v + w . (r x n)
  const double lever[3] = {r[1] * n[2] - r[2] * n[1], r[2] * n[0] - r[0] * n[2], r[0] * n[1] - r[1] * n[0]};
  std::fill(row, row + n_, btScalar(0));
  for (int p = first_column_[b]; p < first_column_[b + 1]; ++p)
  {
    const Motion& c = motions_[p];
    row[columns_[p]] = btScalar(n[0] * c.v[0] + n[1] * c.v[1] + n[2] * c.v[2] + lever[0] * c.w[0] +
                                lever[1] * c.w[1] + lever[2] * c.w[2]);
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
