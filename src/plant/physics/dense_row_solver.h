// Bullet's multibody sequential impulse solver with the iterations done on a precomputed
// Delassus matrix A = J M^-1 J^T, one dense block per group of rows that share a multibody.
//
// btMultiBodyConstraintSolver visits a row with three passes over its multibody's degrees of
// freedom (J.dv, then dv += M^-1 J^T di, once into the solver's buffer and once into the
// multibody): for the car (12 dof, 16 rows, 20 passes) that was a third of a step. With A, each
// visit is one axpy over the rows of its group.
//
// A group of more than kMaxDenseRows rows (a pile of boxes, whose contacts join every box into one
// group) keeps Bullet's sparse form instead: its block would cost (rows)^2 entries to build and a
// visit would cost a pass over all of its rows, where J.dv and dv += M^-1 J^T di touch only the
// degrees of freedom of the row's two multibodies (12 for two free boxes).
//
// Same rows, same order, same clamping, friction bounds and residual as Bullet's iterations;
// only the arithmetic is regrouped, but for one thing: a friction row whose contact lets go in a
// pass (normal impulse 0) loses its impulse, as ODE's bounds (mu times the normal force) have it.
// Bullet skips such a row and keeps what an earlier pass gave it, friction without a normal force:
// a block sliding down a 35 deg incline on 2 or 3 points, whose normal forces jump from step to
// step, was held back by 4 % more than mu N (1.445 m/s^2 for g (sin - mu cos) = 1.607). Setup and
// write-back (forces, impulses kept for the next step) are Bullet's. Where the dense form does not
// apply (rigid bodies that move, cone friction), the iterations are Bullet's own.
//
// Contacts between a multibody and the static world, contacts between two multibodies and
// JointDrive rows are built here, from the multibodies' states of the step (MultibodyState, which
// DynamicsWorld builds and hands out through MultibodyStates): their J, and their responses
// M^-1 J^T for all of a multibody's rows at once, with its block of A where all of its rows have
// their other side static. Other rows are Bullet's, with its articulated-body pass per row and
// side; A's entries between them and the others are dot products of J and M^-1 J^T.
//
// One addition: with SOLVER_USE_WARMSTARTING (Bullet's default) every row starts from its impulse
// of the previous step times m_warmstartingFactor, friction included. Bullet's multibody solver
// starts friction and joint motor rows from zero each step, so a wheel's traction and a drive's
// torque had to be rebuilt from nothing by the iterations of every step.
#pragma once

#include <unordered_map>
#include <vector>

#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyConstraintSolver.h>

#include "physics/contact_surfaces.h"
#include "physics/multibody_dynamics.h"

namespace bullet_plant
{
// What the solver asks of the step's multibody dynamics (DynamicsWorld answers).
class MultibodyStates
{
public:
  // The multibody's state of this step (kinematics, M and its factor), built when first asked
  // for; null where Bullet's own passes must answer for it (M not positive definite).
  virtual const MultibodyState* stateOf(btMultiBody& body) = 0;
  // Bullet's own rows of the multibody (of every multibody) are about to be built: they read the
  // caches of Bullet's articulated-body pass, which must then have run this step.
  virtual void needArticulatedPass(btMultiBody& body) = 0;
  virtual void needArticulatedPasses() = 0;
  // The multibodies are numbered 0 .. multibodyCount() - 1, each in its user index, so that tables
  // of them are indexed rather than searched (a pile of 100 free boxes is 100 multibodies).
  virtual int multibodyCount() const = 0;
  static int numberOf(const btMultiBody& body) { return body.getUserIndex(); }

protected:
  ~MultibodyStates() = default;
};

class DenseRowSolver : public btMultiBodyConstraintSolver
{
public:
  // Where the rows of a multibody get its state from. Without (the default), every row is
  // Bullet's own and only the iterations are dense.
  void useStates(MultibodyStates* states) { states_ = states; }
  // ODE's contact_max_correcting_vel (m/s): the largest speed at which a contact's penetration is
  // corrected (the world sets its SDF value). Without a cap a link spawned deep inside a static box
  // leaves it at depth * erp / dt (km/s for 2 cm at 1 ms).
  void setMaxCorrectingVelocity(btScalar v) { max_correcting_velocity_ = v; }
  // SDF's <bounce> on a collision object: its restitution (Bullet's field, which the world combines
  // as Gazebo does, the smaller of a pair's) and the speed it bounces above. Gazebo's ODE takes the
  // smaller of a pair's speeds; Bullet keeps one for the world (m_restitutionVelocityThreshold),
  // which its own rows (a multibody against another) go on using. The world forgets an object's
  // speed as it removes the object (DynamicsWorld).
  void setBounce(btCollisionObject& object, btScalar restitution, btScalar threshold);
  // SDF's <surface> of a collision object, one per child of its compound or one for the whole
  // (contact_surfaces.h): anisotropic friction, contact stiffness and damping, min_depth, max_vel.
  // Bullet's rows (a multibody against another) get the same as the plant's own.
  void setSurfaces(const btCollisionObject& object, std::vector<ContactSurface> children, bool moving)
  {
    surfaces_.set(object, std::move(children), moving);
  }
  // An object's surfaces to change from the next step on (ContactSurfaces::edit).
  std::vector<ContactSurface>& editSurfaces(const btCollisionObject& object, size_t children,
                                            const ContactSurface& plain, bool moving)
  {
    return surfaces_.edit(object, children, plain, moving);
  }
  // The world forgets what the solver keeps of an object (its bounce and surfaces) as it removes it.
  void forget(const btCollisionObject* object)
  {
    bounce_thresholds_.erase(object);
    surfaces_.forget(object);
  }

protected:
  void convertContacts(btPersistentManifold** manifolds, int numManifolds, const btContactSolverInfo& info) override;
  btScalar solveGroupCacheFriendlyIterations(btCollisionObject** bodies, int numBodies,
                                             btPersistentManifold** manifolds, int numManifolds,
                                             btTypedConstraint** constraints, int numConstraints,
                                             const btContactSolverInfo& info, btIDebugDraw* debugDrawer) override;
  // For a subclass that checks the solve: A's entry between rows i and j of the last dense solve,
  // the rows numbered through Bullet's arrays one after the other (non-contact, normal contact,
  // friction); 0 between rows of different groups.
  btScalar delassusEntry(int i, int j) const;

private:
  // kLanes scalars side by side (GCC/Clang vector extension: one SSE register of floats); a
  // group's rows are padded to whole Lanes.
  static constexpr int kLanes = 4;
  // The largest group solved on a dense block: where a multibody with joints has rows in it, and
  // where all its multibodies are free bodies (0 links). A dense visit costs stride / kLanes vector
  // multiply-adds, a sparse one (n_A + n_B) / kLanes each way (4 for two free boxes, each padded to
  // two Lanes, a box against the ground alike) plus its indexing; the block costs stride^2 / 2
  // entries to build, so the block pays longer where rows share many degrees of freedom. Measured
  // on bench/box_pile_vs_mujoco.py's falling pile (callgrind, its first second), when the sparse
  // visit was Bullet's scalar loops: 5.27M, 5.35M, 6.02M and 6.45M instructions a step with caps of
  // 16, 32, 64 and 128 rows, 8.02M with none; with the two-Lanes visit, 3.64M, 3.56M and 3.53M with
  // free-body caps of 32, 12 and 0. At 12 a box alone on the ground (4 points, 12 rows) keeps its
  // block: with none test_sdf_physics.py's block on a 35 deg incline slides 4.9 % short of
  // g (sin - mu cos) instead of 5.4 %, inside the test's 5 % (its strict xfail). The car on a mesh
  // floor has more than 32 rows (its wheels meet several triangles); at 64 its solve stays dense as
  // before (test_track_world.py's rolling over a mesh's inner edges, a 1 mm bound, fails with its
  // arithmetic regrouped).
  static constexpr int kMaxDenseRows = 64;
  static constexpr int kMaxDenseFreeRows = 12;
  typedef btScalar Lanes __attribute__((vector_size(kLanes * sizeof(btScalar)), aligned(sizeof(btScalar)), may_alias));

  // A row during the iterations: Bullet's numbers, copied from its constraint and back.
  struct Row
  {
    btMultiBodySolverConstraint* constraint;
    int group;
    int local;     // index in the group's block
    int deferred;  // index in deferred_, or -1
    int velocity;  // the group's first entry in row_velocity_
    int column;    // the row's column of the group's block in delassus_
    int stride;    // the group's padded size
    int normal;    // friction rows: the rows_ index of their contact's normal row; others -1
    bool sparse;   // its group has no dense block: J.dv from dof_velocity_
    // The sparse form's sides (A, B): the multibody's velocities in dof_velocity_, the row's J
    // then M^-1 J^T in sparse_data_, each `lanes` Lanes long (the side's degrees of freedom,
    // padded); lanes 0 where the side has no multibody.
    btScalar* dof[2];
    const btScalar* jacobian[2];
    int lanes[2];
    // Both sides two Lanes (free bodies, 6 degrees of freedom; a side without a multibody points
    // at zeros, sparse_zeros_): J.dv and its update take no branches.
    bool two_lanes;
    btScalar rhs, cfm, inverse_mass, lower, upper, friction;
    btScalar mass;  // 1 / inverse_mass, or 0 for a row Bullet disabled: the residual is delta * mass
    btScalar impulse, start_impulse;
  };
  struct Group
  {
    int size = 0;
    int stride = 0;  // size padded to whole Lanes
    int offset = 0;  // into row_velocity_ and members_
    int block = 0;   // into delassus_
    bool dense = true;
    bool articulated = false;  // a multibody with joints has rows in it
  };
  // One side of a row whose response waits for the other rows of its multibody
  // (finishDeferredRows). A row between two multibodies has one for each: the first holds what
  // the row needs and names the second (partner); the second has partner -2.
  struct DeferredRow
  {
    btMultiBodyConstraintArray* rows;
    int index;     // in rows
    int body;      // in body_rows_
    int position;  // in the body's rows
    int jacobian;  // the side's J in m_data.m_jacobians (its response goes to the same offset)
    int partner;   // the row's other side in deferred_, -1 for none, -2 for the second side itself
    btScalar velocity_error;  // the row's rhs, cfm and relaxation before Bullet's scaling by
    btScalar cfm;             // its inverse effective mass
    btScalar sor;
    btScalar diagonal;  // J M^-1 J^T of this side (finishDeferredRows)
    btScalar other;     // J M^-1 J^T of the row's other side where that side is not deferred, else 0
  };
  // A multibody with rows in this solve: its state, and its deferred rows' responses and Delassus
  // block (gram).
  struct BodyRows
  {
    btMultiBody* body = nullptr;
    int number = -1;  // MultibodyStates::numberOf(body) in this solve
    const MultibodyState* state = nullptr;
    std::vector<int> rows;  // deferred_ indices
    std::vector<btScalar> columns, gram;  // responses (dof by dof) and Delassus block, `stride` rows wide
    int stride = 0;
    // Some of its rows have another multibody on their other side: no gram (a pile's box has
    // dozens of rows, and its group is iterated sparse), only each row's diagonal.
    bool pair_rows = false;
    bool has_gram = false;
    // A free body (no links, a floating base): M is diag(I, m) about its centre of mass, so a
    // row's response is I^-1 J_angular and J_linear / m, computed as the row is set up.
    bool free = false;
    btScalar inverse_inertia[9];  // world axes, row-major
    btScalar inverse_mass = 0;
  };
  // The multibody's slot in body_rows_ for this solve, or -1 where Bullet's passes must answer.
  int bodySlot(btMultiBody* body);
  void deferResponse(btMultiBodyConstraintArray& rows, int index, int slot, btScalar velocity_error, btScalar cfm,
                     btScalar sor);
  // Both sides of a row between two multibodies (slot_b's side after slot_a's).
  void deferPairResponse(btMultiBodyConstraintArray& rows, int index, int slot_a, int slot_b, btScalar velocity_error,
                         btScalar cfm, btScalar sor);
  // One side of a row, its J at `jacobian`; `other` is J M^-1 J^T of the row's other side, found
  // already (a free body's).
  void deferSide(btMultiBodyConstraintArray& rows, int index, int slot, int jacobian, btScalar velocity_error,
                 btScalar cfm, btScalar sor, btScalar other);
  // A free body's M^-1 J^T of the row J (6 entries each); returns J M^-1 J^T.
  static btScalar freeResponse(const BodyRows& slot, const btScalar* jacobian, btScalar* response);
  void finishDeferredRows();
  // Bullet's rows of `body` (none if null) are about to be built.
  void needArticulatedPass(btMultiBody* body);
  // `surfaces`: the manifold's points' (ContactSurfaces::apply), or null where its objects have none.
  void limitCorrectingVelocity(btPersistentManifold& manifold, const btContactSolverInfo& info,
                               const PointSurface* surfaces) const;
  bool contactRowsApply(const btPersistentManifold& manifold, const btContactSolverInfo& info);
  // Plain pyramid friction between two different multibodies whose states answer.
  bool pairRowsApply(const btPersistentManifold& manifold, const btContactSolverInfo& info);
  // One side of a contact point between two free bodies: its body and lever arm.
  struct FreeSide
  {
    const BodyRows* slot;
    btMultiBody* body;
    btVector3 arm;  // from the body's centre of mass to the point
  };
  // What a row between two multibodies gets whichever way its J and M^-1 J^T were found, as Bullet's
  // setupMultiBodyContactConstraint gives it: the coefficient and bounds, and the velocity error to
  // remove (Bullet's restitutionCurve above its threshold, a depth beyond the slop through erp, a gap
  // closed within the step), from the bodies' velocity along the row. Returns that error.
  btScalar finishPairRow(btMultiBodySolverConstraint& row, const btManifoldPoint& point,
                         const btContactSolverInfo& info, bool friction, const btVector3& direction,
                         btScalar relative_velocity, btScalar erp);
  // setupPairRow where both multibodies are free bodies: J, M^-1 J^T and the row's numbers in
  // closed form, from the point's lever arms.
  void setupFreePairRow(btMultiBodyConstraintArray& rows, int index, const btVector3& direction, btManifoldPoint& point,
                        const btContactSolverInfo& info, bool friction, btScalar slip, const FreeSide (&sides)[2]);
  // convertMultiBodyContact's rows for two multibodies, built by setupPairRow; with `surfaces`, along
  // the points' own friction directions, the second direction's rows with the points' mu2.
  void convertPairContact(btPersistentManifold& manifold, const btContactSolverInfo& info,
                          const PointSurface* surfaces);
  // setupMultiBodyContactConstraint for two multibodies: Bullet's rows (its restitution among them),
  // with J and M^-1 J^T from their states.
  void setupPairRow(btMultiBodyConstraintArray& rows, int index, const btVector3& direction, btManifoldPoint& point,
                    const btContactSolverInfo& info, bool friction, btScalar slip, int slot_a, int slot_b);
  // Room in m_data's arrays for the rows of the manifolds' points: Bullet grows them by each row's
  // size exactly, copying them whole, each time a step has more rows than any before.
  void reserveRowData(btPersistentManifold** manifolds, int numManifolds, const btContactSolverInfo& info);
  void convertStaticContact(btPersistentManifold& manifold, const btContactSolverInfo& info,
                            const PointSurface* surfaces);
  // Bullet's convertMultiBodyContact with the points' own friction directions and coefficients.
  void convertMultiBodyContactWithSurfaces(btPersistentManifold& manifold, const btContactSolverInfo& info,
                                           const PointSurface* surfaces);
  // `slip`: a friction row's ODE slip (frictionCfm); the normal row's, 0.
  void setupContactRow(btMultiBodyConstraintArray& rows, int index, const btVector3& direction, btManifoldPoint& point,
                       const btContactSolverInfo& info, bool friction, btScalar slip,
                       btScalar bounce_threshold = BT_LARGE_FLOAT);
  // The speed a manifold's points bounce above: the smaller of its two objects' (setBounce).
  btScalar bounceThreshold(const btPersistentManifold& manifold) const;

  bool denseApplies(const btContactSolverInfo& info) const;
  void collectRows();
  void buildBlocks();
  void loadRows();
  void storeRows();
  void warmStart(const btContactSolverInfo& info);
  void startAt(Row& row, btScalar impulse);
  void addToVelocities(const Row& row, btScalar impulse);
  // The sparse form's J.dv and dv += M^-1 J^T impulse, on dof_velocity_.
  static btScalar sparseVelocity(const Row& row);
  static void addToDofVelocities(const Row& row, btScalar impulse);
  // Bullet's resolveSingleConstraintRowGeneric on the dense block (or, with kSparseRows, on
  // dof_velocity_ for a row whose group has none); returns Bullet's residual.
  template <bool kSparseRows>
  btScalar visit(Row& row);
  // Bullet's iterations over rows_; kSparseRows where some group has no dense block, so that a
  // world of small groups (the car) pays nothing for the choice.
  template <bool kSparseRows>
  void iterate(const btContactSolverInfo& info, btCollisionObject** bodies, int numBodies, int numManifolds);
  void applyVelocityChanges();

  MultibodyStates* states_ = nullptr;
  btScalar max_correcting_velocity_ = BT_LARGE_FLOAT;
  std::unordered_map<const btCollisionObject*, btScalar> bounce_thresholds_;  // objects with a restitution
  ContactSurfaces surfaces_;
  std::vector<PointSurface> point_surfaces_;  // this solve's, manifold by manifold
  std::vector<int> manifold_surfaces_;        // by manifold: its first in point_surfaces_, or -1
  std::vector<BodyRows> body_rows_;  // this solve's first bodies_used_ are current
  size_t bodies_used_ = 0;
  std::vector<int> slot_of_;  // by multibody number: its body_rows_ index in this solve, or -1
  std::vector<DeferredRow> deferred_;
  std::vector<Row> rows_;  // non-contact rows, then normal contacts, then friction, as Bullet's arrays
  std::vector<Group> groups_;
  std::vector<int> members_;  // rows_ indices, group by group in block order
  std::vector<btMultiBody*> bodies_;  // multibodies with rows, and their union-find parents
  std::vector<int> parent_;
  std::vector<int> node_of_;  // by offset in m_data.m_deltaVelocities (a multibody's companion id): its bodies_ index
  std::vector<btScalar> delassus_;           // each group's block, row-major (symmetric)
  std::vector<btScalar> row_velocity_;       // J.dv of each row, kept current
  std::vector<btScalar> velocity_change_;    // per degree of freedom, laid out as m_data.m_deltaVelocities
  // The sparse rows' dv: each multibody of bodies_ at packed_offset_, its degrees of freedom padded
  // to whole Lanes.
  std::vector<btScalar> dof_velocity_;
  std::vector<int> packed_offset_;           // by bodies_ index
  std::vector<char> body_sparse_;            // by bodies_ index: its group is sparse (its dv is in dof_velocity_)
  std::vector<btScalar> sparse_data_;        // the sparse rows' J and M^-1 J^T per side, padded as dof_velocity_
  // A missing side of a two_lanes row: its velocities (added zeros) and its J and M^-1 J^T (zeros).
  btScalar sparse_zero_dof_[2 * kLanes], sparse_zero_data_[4 * kLanes];
  bool any_sparse_ = false;
};

}  // namespace bullet_plant
