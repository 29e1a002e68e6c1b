#include "physics/multibody_dynamics.h"

#include <algorithm>
#include <cmath>

#include <BulletDynamics/Featherstone/btMultiBody.h>

namespace bullet_plant
{
namespace
{
using BodyKinematics = MultibodyState::BodyKinematics;
using Composite = MultibodyState::Composite;
using DofMotion = MultibodyState::DofMotion;

void copy(const btVector3& in, double* out)
{
  for (int a = 0; a < 3; ++a)
    out[a] = in[a];
}

void copy(const btMatrix3x3& in, double* out)
{
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c)
      out[3 * r + c] = in[r][c];
}
}  // namespace

void linkKinematics(const btMultiBody& body, MultibodyState& state)
{
  const int links = body.getNumLinks();
  state.n = body.getNumDofs() + 6;
  state.first = body.hasFixedBase() ? 6 : 0;
  state.bodies.resize(links + 1);
  state.dofs.resize(state.n);

  BodyKinematics& base = state.bodies[0];
  base.parent = -1;
  base.first_dof = 0;
  base.dof_count = 0;
  copy(btMatrix3x3(body.getWorldToBaseRot()), base.rotation);
  copy(body.getBasePos(), base.com);
  for (int i = 0; i < links; ++i)
  {
    const btMultibodyLink& link = body.getLink(i);
    const BodyKinematics& from = state.bodies[link.m_parent + 1];
    BodyKinematics& to = state.bodies[i + 1];
    to.parent = link.m_parent + 1;
    to.first_dof = 6 + link.m_dofOffset;
    to.dof_count = link.m_dofCount;
    copy(btMatrix3x3(link.m_cachedRotParentToThis), to.from_parent);
    copy(link.m_cachedRVector, to.offset);  // parent's centre of mass to this one's, in this frame
    const double* R = to.from_parent;
    for (int a = 0; a < 3; ++a)
      for (int c = 0; c < 3; ++c)
        to.rotation[3 * a + c] = R[3 * a] * from.rotation[c] + R[3 * a + 1] * from.rotation[3 + c] +
                                 R[3 * a + 2] * from.rotation[6 + c];
    inverseRotate(to.rotation, to.offset, to.com);
    for (int a = 0; a < 3; ++a)
      to.com[a] += from.com[a];
    // The joint's motions in world axes, at the link's centre of mass.
    for (int d = 0; d < link.m_dofCount; ++d)
    {
      DofMotion& dof = state.dofs[to.first_dof + d];
      double top[3], bottom[3];
      copy(link.getAxisTop(d), top);
      copy(link.getAxisBottom(d), bottom);
      inverseRotate(to.rotation, top, dof.angular);
      inverseRotate(to.rotation, bottom, dof.linear);
      dof.body = i + 1;
    }
  }
}

namespace
{
// Each body with everything beyond it, as mass, first moment and rotational inertia about the
// body's centre of mass, in world axes (leaves inwards).
void compositeBodies(const btMultiBody& body, MultibodyState& state)
{
  const int links = body.getNumLinks();
  state.composites.resize(links + 1);
  for (int b = 0; b <= links; ++b)
  {
    Composite& c = state.composites[b];
    const btVector3 own = b == 0 ? body.getBaseInertia() : body.getLink(b - 1).m_inertiaLocal;
    c.mass = b == 0 ? body.getBaseMass() : body.getLink(b - 1).m_mass;
    c.moment[0] = c.moment[1] = c.moment[2] = 0;
    const double* R = state.bodies[b].rotation;  // world to body: I_world = R^T diag(own) R
    for (int a = 0; a < 3; ++a)
      for (int e = 0; e < 3; ++e)
        c.inertia[3 * a + e] = R[a] * own.x() * R[e] + R[3 + a] * own.y() * R[3 + e] + R[6 + a] * own.z() * R[6 + e];
  }
  for (int b = links; b >= 1; --b)
  {
    const Composite& child = state.composites[b];
    const int p = state.bodies[b].parent;
    Composite& parent = state.composites[p];
    double d[3];  // the child's reference point from the parent's
    for (int a = 0; a < 3; ++a)
      d[a] = state.bodies[b].com[a] - state.bodies[p].com[a];
    // Moved from the child's point to the parent's: I += I_c + 2 (h.d) E - h d^T - d h^T + m (|d|^2 E - d d^T).
    const double hd = dot(child.moment, d);
    const double dd = dot(d, d);
    for (int a = 0; a < 3; ++a)
      for (int e = 0; e < 3; ++e)
        parent.inertia[3 * a + e] += child.inertia[3 * a + e] - child.moment[a] * d[e] - d[a] * child.moment[e] -
                                     child.mass * d[a] * d[e] + (a == e ? 2 * hd + child.mass * dd : 0.0);
    for (int a = 0; a < 3; ++a)
      parent.moment[a] += child.moment[a] + child.mass * d[a];
    parent.mass += child.mass;
  }
}

// M's base block: the whole multibody's composite (floating base only).
void baseInertia(MultibodyState& state)
{
  const int n = state.n;
  double* m = state.inertia.data();
  const Composite& all = state.composites[0];
  for (int k = 0; k < 3; ++k)
  {
    double e[3] = {0, 0, 0}, eh[3];
    e[k] = 1;
    cross(e, all.moment, eh);  // base angular column k: linear momentum e_k x h
    for (int a = 0; a <= k; ++a)
      m[size_t(a) * n + k] = m[size_t(k) * n + a] = all.inertia[3 * a + k];
    for (int a = 0; a < 3; ++a)
      m[size_t(3 + a) * n + k] = eh[a];
    m[size_t(3 + k) * n + 3 + k] = all.mass;
  }
}

// M's row j (a joint's velocity), left of the diagonal. A unit motion (w, v at point P) of a
// composite with first moment h and rotational inertia I about P meets the momentum
// (I w + h x v, m v - h x w).
void jointInertiaRow(MultibodyState& state, int j)
{
  const DofMotion& dof = state.dofs[j];
  const Composite& c = state.composites[dof.body];
  const double* com = state.bodies[dof.body].com;
  double hv[3], hw[3], L[3], p[3];
  cross(c.moment, dof.linear, hv);
  cross(c.moment, dof.angular, hw);
  rotate(c.inertia, dof.angular, L);
  for (int a = 0; a < 3; ++a)
  {
    L[a] += hv[a];
    p[a] = c.mass * dof.linear[a] - hw[a];
  }
  double* row = state.inertia.data() + size_t(j) * state.n;
  // This joint and the ones between its body and the base (lower indices): their motions of the
  // point com.
  for (int b = dof.body; b > 0; b = state.bodies[b].parent)
  {
    const BodyKinematics& frame = state.bodies[b];
    double d[3];
    for (int a = 0; a < 3; ++a)
      d[a] = com[a] - frame.com[a];
    for (int i = frame.first_dof; i < frame.first_dof + frame.dof_count && i <= j; ++i)
    {
      const DofMotion& other = state.dofs[i];
      double wd[3];
      cross(other.angular, d, wd);
      row[i] = other.angular[0] * L[0] + other.angular[1] * L[1] + other.angular[2] * L[2] +
               (other.linear[0] + wd[0]) * p[0] + (other.linear[1] + wd[1]) * p[1] + (other.linear[2] + wd[2]) * p[2];
    }
  }
  if (!state.first)
  {
    // Base angular column k moves the point com by e_k x (com - base com): L + d x p.
    double d[3], dp[3];
    for (int a = 0; a < 3; ++a)
      d[a] = com[a] - state.bodies[0].com[a];
    cross(d, p, dp);
    for (int a = 0; a < 3; ++a)
    {
      row[a] = L[a] + dp[a];
      row[3 + a] = p[a];
    }
  }
}
}  // namespace

void compositeRigidBodyInertia(const btMultiBody& body, MultibodyState& state)
{
  state.inertia.assign(size_t(state.n) * state.n, 0.0);
  compositeBodies(body, state);
  if (!state.first)
    baseInertia(state);
  for (int j = 6; j < state.n; ++j)
    jointInertiaRow(state, j);
}

// Cholesky, M = L L^T, over the velocities that move.
namespace
{
// A body without links on a floating base whose M is diag(I, m) (its base frame at its centre of
// mass): I^-1 and 1 / m, false if M is not that or not positive definite.
bool invertFreeBody(MultibodyState& state)
{
  if (state.bodies.size() != 1 || state.first != 0 || state.n != 6)
    return false;
  const double* m = state.inertia.data();
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b)
      if (m[(3 + a) * 6 + b] != 0 || m[(3 + a) * 6 + 3 + b] != (a == b ? m[21] : 0.0))
        return false;
  const double I[9] = {m[0], m[1], m[2], m[6], m[7], m[8], m[12], m[13], m[14]};
  const double c00 = I[4] * I[8] - I[5] * I[7], c01 = I[5] * I[6] - I[3] * I[8], c02 = I[3] * I[7] - I[4] * I[6];
  const double determinant = I[0] * c00 + I[1] * c01 + I[2] * c02;
  // Positive definite: the leading minors positive (Sylvester), as the Cholesky factor needs.
  if (!(I[0] > 0 && I[0] * I[4] - I[1] * I[3] > 0 && determinant > 0 && m[21] > 0))
    return false;
  const double inverse[9] = {c00, I[2] * I[7] - I[1] * I[8], I[1] * I[5] - I[2] * I[4],
                             c01, I[0] * I[8] - I[2] * I[6], I[2] * I[3] - I[0] * I[5],
                             c02, I[1] * I[6] - I[0] * I[7], I[0] * I[4] - I[1] * I[3]};
  for (int k = 0; k < 9; ++k)
    state.inverse_inertia[k] = inverse[k] / determinant;
  state.inverse_mass = 1 / m[21];
  return true;
}
}  // namespace

bool factorInertia(MultibodyState& state)
{
  const int n = state.n, first = state.first;
  const double* m = state.inertia.data();
  state.free = invertFreeBody(state);
  if (state.free)
    return true;
  state.lower.assign(size_t(n) * n, 0.0);
  state.inverse_diagonal.assign(n, 0.0);
  double* lower = state.lower.data();
  for (int j = first; j < n; ++j)
  {
    const double* Lj = lower + size_t(j) * n;
    double diagonal = m[size_t(j) * n + j];
    for (int k = first; k < j; ++k)
      diagonal -= Lj[k] * Lj[k];
    if (!(diagonal > 0))
      return false;
    const double ljj = std::sqrt(diagonal);
    lower[size_t(j) * n + j] = ljj;
    state.inverse_diagonal[j] = 1.0 / ljj;
    for (int i = j + 1; i < n; ++i)
    {
      double* Li = lower + size_t(i) * n;
      double s = m[size_t(i) * n + j];
      for (int k = first; k < j; ++k)
        s -= Li[k] * Lj[k];
      Li[j] = s * state.inverse_diagonal[j];
    }
  }
  state.lower_scalar.assign(state.lower.begin(), state.lower.end());
  state.inverse_diagonal_scalar.assign(state.inverse_diagonal.begin(), state.inverse_diagonal.end());
  return true;
}

bool buildMultibodyState(const btMultiBody& body, MultibodyState& state)
{
  linkKinematics(body, state);
  compositeRigidBodyInertia(body, state);
  return factorInertia(state);
}

namespace
{
struct Damping
{
  double linear, angular;
  bool gyroscopic;
};

// f = I a + v x* I v + damping - applied, at the body's centre of mass in its frame (Bullet's
// "zero-acceleration force" plus the inertial force of the acceleration).
void bodyForce(MultibodyState& state, int b, const btVector3& inertia, double mass, const btVector3& applied_torque,
               const btVector3& applied_force, const Damping& damping)
{
  const SpatialVector& v = state.velocity[b];
  const SpatialVector& a = state.acceleration[b];
  SpatialVector& f = state.force[b];
  const double I[3] = {inertia.x(), inertia.y(), inertia.z()};
  const double Iw[3] = {I[0] * v.w[0], I[1] * v.w[1], I[2] * v.w[2]};
  double torque_world[3], force_world[3];
  copy(applied_torque, torque_world);
  copy(applied_force, force_world);
  double torque[3], force[3], gyro[3] = {0, 0, 0}, wv[3];
  rotate(state.bodies[b].rotation, torque_world, torque);
  rotate(state.bodies[b].rotation, force_world, force);
  if (damping.gyroscopic)
    cross(v.w, Iw, gyro);
  cross(v.w, v.v, wv);
  const double angular = damping.angular * (1 + norm(v.w)), linear = damping.linear * (1 + norm(v.v));
  for (int k = 0; k < 3; ++k)
  {
    f.w[k] = I[k] * a.w[k] + gyro[k] + Iw[k] * angular - torque[k];
    f.v[k] = mass * (a.v[k] + wv[k] + v.v[k] * linear) - force[k];
  }
}

// Parent to link: w' = R w, v' = R v + w' x r (velocities and accelerations alike).
void motionToLink(const BodyKinematics& link, const SpatialVector& in, SpatialVector& out)
{
  rotate(link.from_parent, in.w, out.w);
  rotate(link.from_parent, in.v, out.v);
  double wr[3];
  cross(out.w, link.offset, wr);
  for (int k = 0; k < 3; ++k)
    out.v[k] += wr[k];
}

// Outward: velocities, and accelerations with qdd = 0 in Bullet's coordinates, and each body's
// force for them. For the base that is a constant world-frame angular and centre-of-mass
// velocity, i.e. a body-frame spatial acceleration (0, -w x v).
void outwardPass(const btMultiBody& body, MultibodyState& state, const Damping& damping)
{
  const btScalar* qd = body.getVelocityVector();
  SpatialVector& v0 = state.velocity[0];
  SpatialVector& a0 = state.acceleration[0];
  v0 = a0 = SpatialVector{};
  if (!state.first)
  {
    const double w_world[3] = {qd[0], qd[1], qd[2]}, v_world[3] = {qd[3], qd[4], qd[5]};
    rotate(state.bodies[0].rotation, w_world, v0.w);
    rotate(state.bodies[0].rotation, v_world, v0.v);
    cross(v0.v, v0.w, a0.v);
  }
  bodyForce(state, 0, body.getBaseInertia(), body.getBaseMass(), body.getBaseTorque(), body.getBaseForce(), damping);
  for (int i = 0; i < body.getNumLinks(); ++i)
  {
    const btMultibodyLink& link = body.getLink(i);
    const int b = i + 1, p = link.m_parent + 1;
    SpatialVector joint{};  // the joint's own velocity S qd
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
    SpatialVector& v = state.velocity[b];
    SpatialVector& a = state.acceleration[b];
    motionToLink(state.bodies[b], state.velocity[p], v);
    motionToLink(state.bodies[b], state.acceleration[p], a);
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
    bodyForce(state, b, link.m_inertiaLocal, link.m_mass, body.getLinkTorque(i), body.getLinkForce(i), damping);
  }
}

// Inward: each joint's share of the forces beyond it, and those forces moved to the parent:
// f_p += (R^T (n + r x f), R^T f).
void inwardPass(const btMultiBody& body, MultibodyState& state)
{
  for (int i = body.getNumLinks() - 1; i >= 0; --i)
  {
    const btMultibodyLink& link = body.getLink(i);
    const int b = i + 1, p = link.m_parent + 1;
    const SpatialVector& f = state.force[b];
    for (int d = 0; d < link.m_dofCount; ++d)
    {
      const btVector3& top = link.getAxisTop(d);
      const btVector3& bottom = link.getAxisBottom(d);
      state.bias[6 + link.m_dofOffset + d] = top.x() * f.w[0] + top.y() * f.w[1] + top.z() * f.w[2] +
                                             bottom.x() * f.v[0] + bottom.y() * f.v[1] + bottom.z() * f.v[2];
    }
    const BodyKinematics& frame = state.bodies[b];
    double rf[3], moment[3], n[3], lin[3];
    cross(frame.offset, f.v, rf);
    for (int k = 0; k < 3; ++k)
      moment[k] = f.w[k] + rf[k];
    inverseRotate(frame.from_parent, moment, n);
    inverseRotate(frame.from_parent, f.v, lin);
    for (int k = 0; k < 3; ++k)
    {
      state.force[p].w[k] += n[k];
      state.force[p].v[k] += lin[k];
    }
  }
  if (!state.first)
  {
    inverseRotate(state.bodies[0].rotation, state.force[0].w, &state.bias[0]);
    inverseRotate(state.bodies[0].rotation, state.force[0].v, &state.bias[3]);
  }
}
}  // namespace

void biasForces(const btMultiBody& body, MultibodyState& state)
{
  const int links = body.getNumLinks();
  state.velocity.resize(links + 1);
  state.acceleration.resize(links + 1);
  state.force.resize(links + 1);
  state.bias.assign(state.n, 0.0);
  const Damping damping{body.getLinearDamping(), body.getAngularDamping(), body.getUseGyroTerm()};
  outwardPass(body, state, damping);
  inwardPass(body, state);
}

void solveInertia(const MultibodyState& state, double* x)
{
  if (state.free)
  {
    const double* I = state.inverse_inertia;
    const double w[3] = {x[0], x[1], x[2]};
    for (int a = 0; a < 3; ++a)
    {
      x[a] = I[3 * a] * w[0] + I[3 * a + 1] * w[1] + I[3 * a + 2] * w[2];
      x[3 + a] *= state.inverse_mass;
    }
    return;
  }
  const int n = state.n, first = state.first;
  const double* L = state.lower.data();
  for (int i = first; i < n; ++i)
  {
    double s = x[i];
    for (int j = first; j < i; ++j)
      s -= L[size_t(i) * n + j] * x[j];
    x[i] = s * state.inverse_diagonal[i];
  }
  for (int i = n - 1; i >= first; --i)
  {
    double s = x[i];
    for (int j = i + 1; j < n; ++j)
      s -= L[size_t(j) * n + i] * x[j];
    x[i] = s * state.inverse_diagonal[i];
  }
  std::fill(x, x + first, 0.0);
}

void forwardDynamics(const btMultiBody& body, MultibodyState& state, btScalar* qdd)
{
  biasForces(body, state);
  std::vector<double>& tau = state.generalized;
  tau.resize(state.n);
  for (int i = 0; i < state.n; ++i)
    tau[i] = -state.bias[i];
  for (int i = 0; i < body.getNumLinks(); ++i)
  {
    const btMultibodyLink& link = body.getLink(i);
    const btScalar* torque = const_cast<btMultiBody&>(body).getJointTorqueMultiDof(i);
    for (int d = 0; d < link.m_dofCount; ++d)
      tau[6 + link.m_dofOffset + d] += torque[d];
  }
  solveInertia(state, tau.data());
  for (int i = 0; i < state.n; ++i)
    qdd[i] = btScalar(tau[i]);
}

void contactJacobianRow(const MultibodyState& state, int link, const btVector3& point, const btVector3& direction,
                        btScalar* row)
{
  double n[3];
  copy(direction, n);
  std::fill(row, row + state.n, btScalar(0));
  // A motion (w, v at the centre of mass c) moves the point by v + w x (point - c); along n that
  // is n . v + w . ((point - c) x n).
  auto lever = [&](const double* com, double* out) {
    const double arm[3] = {point.x() - com[0], point.y() - com[1], point.z() - com[2]};
    cross(arm, n, out);
  };
  for (int b = link + 1; b > 0; b = state.bodies[b].parent)
  {
    const BodyKinematics& frame = state.bodies[b];
    double l[3];
    lever(frame.com, l);
    for (int i = frame.first_dof; i < frame.first_dof + frame.dof_count; ++i)
    {
      const DofMotion& dof = state.dofs[i];
      row[i] = btScalar(n[0] * dof.linear[0] + n[1] * dof.linear[1] + n[2] * dof.linear[2] + l[0] * dof.angular[0] +
                        l[1] * dof.angular[1] + l[2] * dof.angular[2]);
    }
  }
  if (!state.first)
  {
    double l[3];
    lever(state.bodies[0].com, l);
    for (int a = 0; a < 3; ++a)
    {
      row[a] = btScalar(l[a]);
      row[3 + a] = btScalar(n[a]);
    }
  }
}

namespace
{
// kInertiaSides right-hand sides side by side: one SSE register of floats (GCC/Clang vector
// extension; loads and stores through it need only a scalar's alignment).
typedef btScalar Sides __attribute__((vector_size(kInertiaSides * sizeof(btScalar)), aligned(sizeof(btScalar)), may_alias));
}  // namespace

// The solves step through the degrees of freedom with one block of sides in a register: each step
// is a multiply-add of the block and no store. In the solver's precision (float), as Bullet's
// own articulated-body pass: against the double solve the responses and the block differ by
// 1.4e-7 of their largest entry (the car driving, steering and tumbling).
void solveInertiaColumns(const MultibodyState& state, btScalar* x, int count, btScalar* gram)
{
  if (state.free)
  {
    const int k = count;
    std::vector<btScalar> original(x, x + size_t(6) * k);
    for (int r = 0; r < k; ++r)
    {
      for (int a = 0; a < 3; ++a)
      {
        x[size_t(a) * k + r] = btScalar(state.inverse_inertia[3 * a] * original[r] +
                                        state.inverse_inertia[3 * a + 1] * original[size_t(k) + r] +
                                        state.inverse_inertia[3 * a + 2] * original[size_t(2) * k + r]);
        x[size_t(3 + a) * k + r] = btScalar(original[size_t(3 + a) * k + r] * state.inverse_mass);
      }
    }
    for (int r = 0; gram && r < k; ++r)
      for (int t = 0; t < k; ++t)
      {
        btScalar sum = 0;
        for (int i = 0; i < 6; ++i)
          sum += original[size_t(i) * k + r] * x[size_t(i) * k + t];
        gram[size_t(r) * k + t] = sum;
      }
    return;
  }
  const int k = count, n = state.n, first = state.first;
  const btScalar* L = state.lower_scalar.data();
  const btScalar* inverse_diagonal = state.inverse_diagonal_scalar.data();
  auto at = [&](int i, int r) { return reinterpret_cast<Sides*>(x + size_t(i) * k + r); };
  for (int r = 0; r < k; r += kInertiaSides)
  {
    // Forward substitution, y = L^-1 x.
    for (int i = first; i < n; ++i)
    {
      const btScalar* Li = L + size_t(i) * n;
      Sides acc = *at(i, r);
      for (int j = first; j < i; ++j)
        acc -= Li[j] * *at(j, r);
      *at(i, r) = acc * inverse_diagonal[i];
    }
  }
  // x^T M^-1 x = y^T y, block by block of its upper triangle.
  for (int r = 0; gram && r < k; r += kInertiaSides)
    for (int s = r; s < k; s += kInertiaSides)
    {
      Sides acc[kInertiaSides] = {};
      for (int i = first; i < n; ++i)
      {
        const btScalar* yr = x + size_t(i) * k + r;
        const Sides ys = *at(i, s);
        for (int u = 0; u < kInertiaSides; ++u)
          acc[u] += yr[u] * ys;
      }
      for (int u = 0; u < kInertiaSides; ++u)
        for (int t = 0; t < kInertiaSides; ++t)
        {
          gram[size_t(r + u) * k + s + t] = acc[u][t];
          gram[size_t(s + t) * k + r + u] = acc[u][t];
        }
    }
  for (int r = 0; r < k; r += kInertiaSides)
  {
    // Back substitution, x = L^-T y.
    for (int i = n - 1; i >= first; --i)
    {
      Sides acc = *at(i, r);
      for (int j = i + 1; j < n; ++j)
        acc -= L[size_t(j) * n + i] * *at(j, r);
      *at(i, r) = acc * inverse_diagonal[i];
    }
  }
  std::fill(x, x + size_t(first) * k, btScalar(0));
}

}  // namespace bullet_plant
