// Divergence recovery: a robot whose physics produced a non-finite state (bad inertias, limits or
// gains) goes back to its last good state at rest while the world keeps running, and one that
// diverges step after step is taken out of the physics. Its own unit because it is the one
// place that decides a robot's state is broken, and what it logs must not flood the log.
#pragma once

#include <cstdint>
#include <vector>

#include <btBulletDynamicsCommon.h>

#include "bullet_plant/robot.h"
#include "simulation/robot_multibody.h"

namespace bullet_plant
{
// The last state of a robot in which every number was finite, to fall back to if the physics
// diverges.
struct LastGoodState
{
  std::vector<btScalar> q, qd;
  std::vector<btScalar> ball_q;  // Bullet's quaternion (x y z w) of each ball joint, one after the other
  btTransform base = btTransform::getIdentity();
  btVector3 base_velocity{0, 0, 0}, base_omega{0, 0, 0};

  void save(const RobotMultibody& robot);
  // Back to the saved positions at rest.
  void restore(RobotMultibody& robot) const;
};

struct DivergenceRecovery
{
  LastGoodState last_good;
  long recoveries = 0;              // in all (Robot::recoveries)
  int64_t window_start_ns = -1;     // the first recovery of the current simulated second
  int recoveries_in_window = 0;
};

// After each physics step, before readSim: a finite state is saved as the last good one; a
// non-finite one is replaced by it (PIDs reset, the solver's history forgotten), said at the first
// recovery of each simulated second; after Robot::kRecoveriesBeforeDisabling within one second
// the robot is disabled (out of the physics), said once.
void recoverIfDiverged(Robot::Internals& robot);

}  // namespace bullet_plant
