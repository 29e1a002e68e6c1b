// physics::SurfaceParams and FrictionPyramid: a collision's <surface> as a plugin reads and changes
// it (Collision::GetSurface). The plant takes the friction coefficients and, in ODESurfaceParams,
// the slips as they are when the next step starts; the rest is what the model says, read-only in
// effect (docs/gazebo_api.md).
#pragma once

#include <ignition/math/Vector3.hh>

#include "gazebo/physics/PhysicsTypes.hh"
#include "gazebo/util/system.hh"

namespace gazebo
{
namespace physics
{
// <friction><ode>'s pyramid: mu along the first friction direction, mu2 across it.
class GZ_PHYSICS_VISIBLE FrictionPyramid
{
public:
  FrictionPyramid() = default;
  virtual ~FrictionPyramid() = default;
  double MuPrimary() const { return mu_primary_; }
  double MuSecondary() const { return mu_secondary_; }
  double MuTorsion() const { return mu_torsion_; }
  double PatchRadius() const { return patch_radius_; }
  double SurfaceRadius() const { return surface_radius_; }
  bool UsePatchRadius() const { return use_patch_radius_; }
  double PoissonsRatio() const { return poissons_ratio_; }
  double ElasticModulus() const { return elastic_modulus_; }
  // A negative coefficient is left as it was, as Gazebo's.
  void SetMuPrimary(double mu);
  void SetMuSecondary(double mu);
  void SetMuTorsion(double mu);
  void SetPatchRadius(double radius) { patch_radius_ = radius; }
  void SetSurfaceRadius(double radius) { surface_radius_ = radius; }
  void SetUsePatchRadius(bool use) { use_patch_radius_ = use; }
  void SetPoissonsRatio(double ratio) { poissons_ratio_ = ratio; }
  void SetElasticModulus(double modulus) { elastic_modulus_ = modulus; }

  // The first friction direction in the collision's frame; zero for ODE's default.
  ignition::math::Vector3d direction1;

private:
  double mu_primary_ = 1.0, mu_secondary_ = 1.0, mu_torsion_ = 1.0;
  double patch_radius_ = 0.0, surface_radius_ = 0.0;
  bool use_patch_radius_ = true;
  double poissons_ratio_ = 0.3, elastic_modulus_ = -1.0;
};

class GZ_PHYSICS_VISIBLE SurfaceParams
{
public:
  SurfaceParams();
  virtual ~SurfaceParams();
  virtual FrictionPyramidPtr FrictionPyramid() const;

  bool collideWithoutContact = false;
  unsigned int collideWithoutContactBitmask = 1;
  unsigned int collideBitmask = 0xffff;

protected:
  FrictionPyramidPtr friction_pyramid_;
};
}  // namespace physics
}  // namespace gazebo
