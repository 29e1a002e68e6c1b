#include "joint_space_inertia.h"

#include <cmath>

#include <BulletDynamics/Featherstone/btMultiBody.h>

namespace bullet_plant
{
namespace
{
// A spatial motion vector (angular; linear at the body's centre of mass), in doubles.
struct Motion
{
  double w[3], v[3];
};

// Bullet's parent-to-child motion transform: w' = R w, v' = R v + w' x r, with r the vector from
// the parent's centre of mass to the child's, in the child's frame.
Motion toChild(const btMatrix3x3& rotation, const btVector3& r, const Motion& m)
{
  Motion out;
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
  jacobians_.assign(size_t(links + 1) * 6 * n_, 0.0);
  inertia_.assign(size_t(n_) * n_, 0.0);
  std::vector<double>& m = inertia_;

  auto column = [&](int b, int k) {
    const double* J = &jacobians_[size_t(b) * 6 * n_];
    return Motion{{J[0 * n_ + k], J[1 * n_ + k], J[2 * n_ + k]}, {J[3 * n_ + k], J[4 * n_ + k], J[5 * n_ + k]}};
  };
  auto setColumn = [&](int b, int k, const Motion& c) {
    double* J = &jacobians_[size_t(b) * 6 * n_];
    for (int a = 0; a < 3; ++a)
    {
      J[a * n_ + k] = c.w[a];
      J[(3 + a) * n_ + k] = c.v[a];
    }
  };
  // Adds J_b^T diag(inertia, mass) J_b to M.
  auto addBody = [&](int b, const btVector3& inertia, double mass) {
    const double* J = &jacobians_[size_t(b) * 6 * n_];
    const double weight[6] = {inertia.x(), inertia.y(), inertia.z(), mass, mass, mass};
    for (int row = 0; row < 6; ++row)
    {
      const double* Jr = J + row * n_;
      for (int i = 0; i < n_; ++i)
      {
        if (Jr[i] == 0)
          continue;
        const double wi = weight[row] * Jr[i];
        for (int j = 0; j <= i; ++j)
          m[size_t(i) * n_ + j] += wi * Jr[j];
      }
    }
  };

  // The base: its spatial velocity is the world-frame angular and linear velocity, rotated in.
  if (!fixed_base_)
  {
    const btMatrix3x3 world_to_base(body.getWorldToBaseRot());
    for (int a = 0; a < 3; ++a)
    {
      Motion c{};
      for (int r = 0; r < 3; ++r)
        c.w[r] = world_to_base[r][a];
      setColumn(0, a, c);
      Motion d{};
      for (int r = 0; r < 3; ++r)
        d.v[r] = world_to_base[r][a];
      setColumn(0, 3 + a, d);
    }
    addBody(0, body.getBaseInertia(), body.getBaseMass());
  }
  for (int i = 0; i < links; ++i)
  {
    const btMultibodyLink& link = body.getLink(i);
    const int parent = link.m_parent + 1;  // body index: 0 is the base
    const btMatrix3x3 rotation(link.m_cachedRotParentToThis);
    for (int k = 0; k < n_; ++k)
    {
      const Motion p = column(parent, k);
      bool zero = true;
      for (int a = 0; a < 3 && zero; ++a)
        zero = p.w[a] == 0 && p.v[a] == 0;
      if (!zero)
        setColumn(i + 1, k, toChild(rotation, link.m_cachedRVector, p));
    }
    for (int d = 0; d < link.m_dofCount; ++d)
    {
      const btVector3& top = link.getAxisTop(d);
      const btVector3& bottom = link.getAxisBottom(d);
      setColumn(i + 1, 6 + link.m_dofOffset + d, Motion{{top.x(), top.y(), top.z()}, {bottom.x(), bottom.y(), bottom.z()}});
    }
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
  scratch_.resize(n_);
  half_.resize(n_);
  return true;
}

void JointSpaceInertia::halfSolve(const btScalar* f, double* half) const
{
  for (int i = 0; i < n_; ++i)
  {
    double s = (fixed_base_ && i < 6) ? 0.0 : double(f[i]);
    const double* Li = &lower_[size_t(i) * n_];
    for (int k = 0; k < i; ++k)
      s -= Li[k] * half[k];
    half[i] = s / Li[i];
  }
}

void JointSpaceInertia::finishSolve(const double* half, btScalar* out) const
{
  double* x = scratch_.data();
  for (int i = n_ - 1; i >= 0; --i)
  {
    double s = half[i];
    for (int k = i + 1; k < n_; ++k)
      s -= lower_[size_t(k) * n_ + i] * x[k];
    x[i] = s / lower_[size_t(i) * n_ + i];
  }
  for (int i = 0; i < n_; ++i)
    out[i] = (fixed_base_ && i < 6) ? btScalar(0) : btScalar(x[i]);
}

void JointSpaceInertia::solve(const btScalar* f, btScalar* out) const
{
  halfSolve(f, half_.data());
  finishSolve(half_.data(), out);
}

}  // namespace bullet_plant
