#include "joint_space_inertia.h"

#include <cmath>

#include <BulletDynamics/Featherstone/btMultiBody.h>

namespace bullet_plant
{
namespace
{
// Bullet's parent-to-child motion transform: w' = R w, v' = R v + w' x r, with r the vector from
// the parent's centre of mass to the child's, in the child's frame.
JointSpaceInertia::Motion toChild(const btMatrix3x3& rotation, const btVector3& r, const JointSpaceInertia::Motion& m)
{
  JointSpaceInertia::Motion out;
  for (int a = 0; a < 3; ++a)
  {
    out.w[a] = rotation[a][0] * m.w[0] + rotation[a][1] * m.w[1] + rotation[a][2] * m.w[2];
    out.v[a] = rotation[a][0] * m.v[0] + rotation[a][1] * m.v[1] + rotation[a][2] * m.v[2];
  }
  out.v[0] += out.w[1] * r.z() - out.w[2] * r.y();
  out.v[1] += out.w[2] * r.x() - out.w[0] * r.z();
  out.v[2] += out.w[0] * r.y() - out.w[1] * r.x();
  return out;
}
}  // namespace

bool JointSpaceInertia::update(const btMultiBody& body)
{
  const int links = body.getNumLinks();
  n_ = body.getNumDofs() + 6;
  fixed_base_ = body.hasFixedBase();
  // Body b's Jacobian has non-zero columns only for the base and the joints between b and the
  // base: columns_[b] lists them, motions_ holds those columns, body after body.
  motions_.clear();
  columns_.clear();
  first_column_.assign(1, 0);
  inertia_.assign(size_t(n_) * n_, 0.0);
  std::vector<double>& m = inertia_;

  // Adds J_b^T diag(inertia, mass) J_b to M (lower triangle) over b's columns.
  auto addBody = [&](int b, const btVector3& inertia, double mass) {
    const int begin = first_column_[b], end = first_column_[b + 1];
    for (int p = begin; p < end; ++p)
    {
      const Motion& cp = motions_[p];
      const double wp[3] = {inertia.x() * cp.w[0], inertia.y() * cp.w[1], inertia.z() * cp.w[2]};
      for (int q = begin; q < end; ++q)
      {
        const int i = columns_[p], j = columns_[q];
        if (j > i)
          continue;
        const Motion& cq = motions_[q];
        m[size_t(i) * n_ + j] += wp[0] * cq.w[0] + wp[1] * cq.w[1] + wp[2] * cq.w[2] +
                                 mass * (cp.v[0] * cq.v[0] + cp.v[1] * cq.v[1] + cp.v[2] * cq.v[2]);
      }
    }
  };

  // The base: its spatial velocity is the world-frame angular and linear velocity, rotated in.
  if (!fixed_base_)
  {
    const btMatrix3x3 world_to_base(body.getWorldToBaseRot());
    for (int a = 0; a < 6; ++a)
    {
      Motion c{};
      for (int r = 0; r < 3; ++r)
        (a < 3 ? c.w : c.v)[r] = world_to_base[r][a % 3];
      motions_.push_back(c);
      columns_.push_back(a);
    }
  }
  first_column_.push_back(int(columns_.size()));
  addBody(0, body.getBaseInertia(), body.getBaseMass());
  for (int i = 0; i < links; ++i)
  {
    const btMultibodyLink& link = body.getLink(i);
    const int parent = link.m_parent + 1;  // body index: 0 is the base
    const btMatrix3x3 rotation(link.m_cachedRotParentToThis);
    for (int p = first_column_[parent]; p < first_column_[parent + 1]; ++p)
    {
      const Motion child = toChild(rotation, link.m_cachedRVector, motions_[p]);
      motions_.push_back(child);
      columns_.push_back(columns_[p]);
    }
    for (int d = 0; d < link.m_dofCount; ++d)
    {
      const btVector3& top = link.getAxisTop(d);
      const btVector3& bottom = link.getAxisBottom(d);
      motions_.push_back(Motion{{top.x(), top.y(), top.z()}, {bottom.x(), bottom.y(), bottom.z()}});
      columns_.push_back(6 + link.m_dofOffset + d);
    }
    first_column_.push_back(int(columns_.size()));
    addBody(i + 1, link.m_inertiaLocal, link.m_mass);
  }
  // A fixed base does not move: its six entries are decoupled (and ignored by the solves).
  if (fixed_base_)
    for (int a = 0; a < 6; ++a)
    {
      for (int j = 0; j < n_; ++j)
        m[size_t(a) * n_ + j] = m[size_t(j) * n_ + a] = 0;
      m[size_t(a) * n_ + a] = 1;
    }

  // Cholesky, M = L L^T (lower triangle of m is filled).
  lower_.assign(size_t(n_) * n_, 0.0);
  for (int j = 0; j < n_; ++j)
  {
    double diagonal = m[size_t(j) * n_ + j];
    for (int k = 0; k < j; ++k)
      diagonal -= lower_[size_t(j) * n_ + k] * lower_[size_t(j) * n_ + k];
    if (!(diagonal > 0))
      return false;
    const double ljj = std::sqrt(diagonal);
    lower_[size_t(j) * n_ + j] = ljj;
    for (int i = j + 1; i < n_; ++i)
    {
      double s = m[size_t(i) * n_ + j];
      for (int k = 0; k < j; ++k)
        s -= lower_[size_t(i) * n_ + k] * lower_[size_t(j) * n_ + k];
      lower_[size_t(i) * n_ + j] = s / ljj;
    }
  }
  upper_.resize(lower_.size());
  inverse_diagonal_.resize(n_);
  for (int i = 0; i < n_; ++i)
  {
    inverse_diagonal_[i] = 1.0 / lower_[size_t(i) * n_ + i];
    for (int k = 0; k < n_; ++k)
      upper_[size_t(i) * n_ + k] = lower_[size_t(k) * n_ + i];
  }
  scratch_.resize(n_);
  half_.resize(n_);
  return true;
}

void JointSpaceInertia::halfSolve(const btScalar* f, double* half) const
{
  const int first = fixed_base_ ? 6 : 0;
  for (int i = 0; i < first; ++i)
    half[i] = 0;
  const double* L = lower_.data();
  for (int i = first; i < n_; ++i)
  {
    const double* Li = L + size_t(i) * n_;
    double s = f[i];
    for (int k = first; k < i; ++k)
      s -= Li[k] * half[k];
    half[i] = s * inverse_diagonal_[i];
  }
}

void JointSpaceInertia::finishSolve(const double* half, btScalar* out) const
{
  const int first = fixed_base_ ? 6 : 0;
  double* x = scratch_.data();
  const double* U = upper_.data();  // L^T, row-major
  for (int i = n_ - 1; i >= first; --i)
  {
    const double* Ui = U + size_t(i) * n_;
    double s = half[i];
    for (int k = i + 1; k < n_; ++k)
      s -= Ui[k] * x[k];
    x[i] = s * inverse_diagonal_[i];
  }
  for (int i = 0; i < first; ++i)
    out[i] = 0;
  for (int i = first; i < n_; ++i)
    out[i] = btScalar(x[i]);
}

void JointSpaceInertia::solve(const btScalar* f, btScalar* out) const
{
  halfSolve(f, half_.data());
  finishSolve(half_.data(), out);
}

}  // namespace bullet_plant
