// physics::Inertial as a plugin reads a link's (Link::GetInertial): its mass, its centre of mass
// and inertia, as Gazebo 11's (the centre and the inertia's axes in the link frame). A copy: what a
// plugin sets on it changes nothing in the simulation.
#pragma once

#include <ignition/math/Matrix3.hh>
#include <ignition/math/Pose3.hh>
#include <ignition/math/Vector3.hh>

#include "gazebo/util/system.hh"

namespace gazebo
{
namespace physics
{
class GZ_PHYSICS_VISIBLE Inertial
{
public:
  Inertial() = default;
  explicit Inertial(double mass) : mass_(mass) {}
  double Mass() const { return mass_; }
  void SetMass(double mass) { mass_ = mass; }
  const ignition::math::Vector3d& CoG() const { return pose_.Pos(); }
  void SetCoG(const ignition::math::Vector3d& cog) { pose_.Pos() = cog; }
  // The centre of mass and the inertia's axes, link frame.
  const ignition::math::Pose3d& Pose() const { return pose_; }
  void SetPose(const ignition::math::Pose3d& pose) { pose_ = pose; }
  double IXX() const { return ixx_; }
  double IYY() const { return iyy_; }
  double IZZ() const { return izz_; }
  double IXY() const { return ixy_; }
  double IXZ() const { return ixz_; }
  double IYZ() const { return iyz_; }
  void SetInertiaMatrix(double ixx, double iyy, double izz, double ixy, double ixz, double iyz)
  {
    ixx_ = ixx;
    iyy_ = iyy;
    izz_ = izz;
    ixy_ = ixy;
    ixz_ = ixz;
    iyz_ = iyz;
  }
  ignition::math::Vector3d PrincipalMoments() const { return {ixx_, iyy_, izz_}; }
  ignition::math::Vector3d ProductsOfInertia() const { return {ixy_, ixz_, iyz_}; }
  // The inertia about the centre of mass, in the inertia's axes.
  ignition::math::Matrix3d MOI() const { return {ixx_, ixy_, ixz_, ixy_, iyy_, iyz_, ixz_, iyz_, izz_}; }

private:
  double mass_ = 1.0;
  ignition::math::Pose3d pose_;
  double ixx_ = 1.0, iyy_ = 1.0, izz_ = 1.0, ixy_ = 0.0, ixz_ = 0.0, iyz_ = 0.0;
};
}  // namespace physics
}  // namespace gazebo
