// common::SphericalCoordinates (gazebo/common/SphericalCoordinates.hh), over ignition-math's.
#include "gazebo/common/SphericalCoordinates.hh"

#include "gazebo/common/Console.hh"

namespace gazebo
{
namespace common
{
namespace
{
using Math = ignition::math::SphericalCoordinates;

Math::CoordinateType toMath(SphericalCoordinates::CoordinateType type)
{
  // the same numbers, SPHERICAL 1 to LOCAL 4
  return static_cast<Math::CoordinateType>(type);
}
}  // namespace

SphericalCoordinates::SphericalCoordinates() : math_(Math::EARTH_WGS84) {}

SphericalCoordinates::SphericalCoordinates(const SurfaceType /*_type*/) : math_(Math::EARTH_WGS84) {}

SphericalCoordinates::SphericalCoordinates(const SurfaceType /*_type*/, const ignition::math::Angle& _latitude,
                                           const ignition::math::Angle& _longitude, double _elevation,
                                           const ignition::math::Angle& _heading)
  : math_(Math::EARTH_WGS84, _latitude, _longitude, _elevation, _heading)
{
}

SphericalCoordinates::~SphericalCoordinates() = default;

ignition::math::Vector3d SphericalCoordinates::SphericalFromLocal(const ignition::math::Vector3d& _xyz) const
{
  return math_.SphericalFromLocalPosition(_xyz);
}

ignition::math::Vector3d SphericalCoordinates::GlobalFromLocal(const ignition::math::Vector3d& _xyz) const
{
  return math_.GlobalFromLocalVelocity(_xyz);
}

ignition::math::Vector3d SphericalCoordinates::LocalFromSpherical(const ignition::math::Vector3d& _xyz) const
{
  return math_.LocalFromSphericalPosition(_xyz);
}

ignition::math::Vector3d SphericalCoordinates::LocalFromGlobal(const ignition::math::Vector3d& _xyz) const
{
  return math_.LocalFromGlobalVelocity(_xyz);
}

SphericalCoordinates::SurfaceType SphericalCoordinates::Convert(const std::string& _str)
{
  if (_str != "EARTH_WGS84")
    gzerr << "SurfaceType string not recognized, EARTH_WGS84 returned by default\n";
  return EARTH_WGS84;
}

double SphericalCoordinates::Distance(const ignition::math::Angle& _latA, const ignition::math::Angle& _lonA,
                                      const ignition::math::Angle& _latB, const ignition::math::Angle& _lonB)
{
  return Math::Distance(_latA, _lonA, _latB, _lonB);
}

SphericalCoordinates::SurfaceType SphericalCoordinates::GetSurfaceType() const { return EARTH_WGS84; }

ignition::math::Angle SphericalCoordinates::LatitudeReference() const { return math_.LatitudeReference(); }

ignition::math::Angle SphericalCoordinates::LongitudeReference() const { return math_.LongitudeReference(); }

double SphericalCoordinates::GetElevationReference() const { return math_.ElevationReference(); }

ignition::math::Angle SphericalCoordinates::HeadingOffset() const { return math_.HeadingOffset(); }

void SphericalCoordinates::SetSurfaceType(const SurfaceType& /*_type*/) { math_.SetSurface(Math::EARTH_WGS84); }

void SphericalCoordinates::SetLatitudeReference(const ignition::math::Angle& _angle)
{
  math_.SetLatitudeReference(_angle);
}

void SphericalCoordinates::SetLongitudeReference(const ignition::math::Angle& _angle)
{
  math_.SetLongitudeReference(_angle);
}

void SphericalCoordinates::SetElevationReference(double _elevation) { math_.SetElevationReference(_elevation); }

void SphericalCoordinates::SetHeadingOffset(const ignition::math::Angle& _angle) { math_.SetHeadingOffset(_angle); }

void SphericalCoordinates::UpdateTransformationMatrix() { math_.UpdateTransformationMatrix(); }

ignition::math::Vector3d SphericalCoordinates::PositionTransform(const ignition::math::Vector3d& _pos,
                                                                 const CoordinateType& _in,
                                                                 const CoordinateType& _out) const
{
  return math_.PositionTransform(_pos, toMath(_in), toMath(_out));
}

ignition::math::Vector3d SphericalCoordinates::VelocityTransform(const ignition::math::Vector3d& _vel,
                                                                 const CoordinateType& _in,
                                                                 const CoordinateType& _out) const
{
  return math_.VelocityTransform(_vel, toMath(_in), toMath(_out));
}
}  // namespace common
}  // namespace gazebo
