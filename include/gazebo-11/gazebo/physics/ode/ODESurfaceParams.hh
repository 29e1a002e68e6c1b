// physics::ODESurfaceParams: <surface>'s <contact><ode>, <bounce> and <friction><ode> slips, the
// fields Gazebo's ODE reads at each contact. slip1 and slip2 (m/s per N of friction, along the
// first friction direction and across it) are taken by the plant from the next step on, as the
// friction pyramid's coefficients are; kp, kd, max_vel, min_depth and the bounce hold what the
// model gives.
#pragma once

#include "gazebo/physics/SurfaceParams.hh"
#include "gazebo/physics/ode/ODETypes.hh"

namespace gazebo
{
namespace physics
{
class GZ_PHYSICS_VISIBLE ODESurfaceParams : public SurfaceParams
{
public:
  ODESurfaceParams();
  ~ODESurfaceParams() override;

  double bounce = 0.0;
  double bounceThreshold = 100000.0;
  double kp = 1e12;
  double kd = 1.0;
  double cfm = 0.0;
  double erp = 0.2;
  double maxVel = 0.01;
  double minDepth = 0.0;
  double slip1 = 0.0;
  double slip2 = 0.0;
  double slipTorsion = 0.0;
};
}  // namespace physics
}  // namespace gazebo
