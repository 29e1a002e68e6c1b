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
  motions_.clear();
  columns_.clear();
  first_column_.assign(1, 0);
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
      Motion c{};
      for (int r = 0; r < 3; ++r)
        (a < 3 ? c.w : c.v)[r] = base.rotation[3 * r + a % 3];
      motions_.push_back(c);
      columns_.push_back(a);
    }
  first_column_.push_back(int(columns_.size()));
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
    for (int a = 0; a < 3; ++a)
      for (int c = 0; c < 3; ++c)
        to.rotation[3 * a + c] = R[3 * a] * from.rotation[c] + R[3 * a + 1] * from.rotation[3 + c] +
                                 R[3 * a + 2] * from.rotation[6 + c];
    for (int a = 0; a < 3; ++a)
      to.com[a] = from.com[a] + to.rotation[a] * r.x() + to.rotation[3 + a] * r.y() + to.rotation[6 + a] * r.z();

    // The parent's columns seen from this body: w' = R w, v' = R v + w' x r.
    for (int p = first_column_[parent]; p < first_column_[parent + 1]; ++p)
    {
      const Motion& in = motions_[p];
      Motion out;
      for (int a = 0; a < 3; ++a)
      {
        out.w[a] = R[3 * a] * in.w[0] + R[3 * a + 1] * in.w[1] + R[3 * a + 2] * in.w[2];
        out.v[a] = R[3 * a] * in.v[0] + R[3 * a + 1] * in.v[1] + R[3 * a + 2] * in.v[2];
      }
      out.v[0] += out.w[1] * r.z() - out.w[2] * r.y();
      out.v[1] += out.w[2] * r.x() - out.w[0] * r.z();
      out.v[2] += out.w[0] * r.y() - out.w[1] * r.x();
      motions_.push_back(out);
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
  return true;
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
// Two right-hand sides side by side: one SSE2 register (GCC/Clang vector extension; loads and
// stores through it need only a double's alignment).
typedef double Pair __attribute__((vector_size(2 * sizeof(double)), aligned(sizeof(double)), may_alias));
}  // namespace

// The solves step through the degrees of freedom with a block of four sides (two Pairs) held in
// registers, so each step is four multiply-adds and no stores.
void JointSpaceInertia::solveColumns(double* x, int count, double* gram) const
{
  static_assert(kSides == 4, "the loops below hold four sides as two Pairs");
  const int k = count;
  const double* L = lower_.data();
  auto at = [&](int i, int r) { return reinterpret_cast<Pair*>(x + size_t(i) * k + r); };
  for (int r = 0; r < k; r += kSides)
  {
    // Forward substitution, y = L^-1 x.
    for (int i = first_; i < n_; ++i)
    {
      const double* Li = L + size_t(i) * n_;
      Pair low = at(i, r)[0], high = at(i, r)[1];
      for (int j = first_; j < i; ++j)
      {
        low -= Li[j] * at(j, r)[0];
        high -= Li[j] * at(j, r)[1];
      }
      at(i, r)[0] = low * inverse_diagonal_[i];
      at(i, r)[1] = high * inverse_diagonal_[i];
    }
  }
  // x^T M^-1 x = y^T y, block by block of its upper triangle.
  for (int r = 0; r < k; r += kSides)
    for (int s = r; s < k; s += kSides)
    {
      Pair low[kSides] = {}, high[kSides] = {};
      for (int i = first_; i < n_; ++i)
      {
        const double* yr = x + size_t(i) * k + r;
        const Pair ys_low = at(i, s)[0], ys_high = at(i, s)[1];
        for (int u = 0; u < kSides; ++u)
        {
          low[u] += yr[u] * ys_low;
          high[u] += yr[u] * ys_high;
        }
      }
      for (int u = 0; u < kSides; ++u)
        for (int t = 0; t < kSides; ++t)
        {
          const double value = t < 2 ? low[u][t] : high[u][t - 2];
          gram[size_t(r + u) * k + s + t] = value;
          gram[size_t(s + t) * k + r + u] = value;
        }
    }
  for (int r = 0; r < k; r += kSides)
  {
    // Back substitution, x = L^-T y.
    for (int i = n_ - 1; i >= first_; --i)
    {
      Pair low = at(i, r)[0], high = at(i, r)[1];
      for (int j = i + 1; j < n_; ++j)
      {
        const double l = L[size_t(j) * n_ + i];
        low -= l * at(j, r)[0];
        high -= l * at(j, r)[1];
      }
      at(i, r)[0] = low * inverse_diagonal_[i];
      at(i, r)[1] = high * inverse_diagonal_[i];
    }
  }
  std::fill(x, x + size_t(first_) * k, 0.0);
}

}  // namespace bullet_plant
