// common::SphericalCoordinates as Gazebo 11's: a world's <spherical_coordinates> (the WGS84 earth,
// the latitude, longitude and elevation of its origin, the heading of its x axis) and the
// conversions between the world's frame and geodetic coordinates, positions (SphericalFromLocal,
// LocalFromSpherical) and velocities (GlobalFromLocal: east, north, up). The conversions are
// ignition-math's SphericalCoordinates, which Gazebo's became; this class keeps Gazebo 11's names.
#pragma once

#include <memory>
#include <string>

#include <ignition/math/Angle.hh>
#include <ignition/math/SphericalCoordinates.hh>
#include <ignition/math/Vector3.hh>

#include "gazebo/common/CommonTypes.hh"
#include "gazebo/util/system.hh"

namespace gazebo
{
namespace common
{
class GZ_COMMON_VISIBLE SphericalCoordinates
{
public:
  enum SurfaceType
  {
    EARTH_WGS84 = 1
  };
  enum CoordinateType
  {
    SPHERICAL = 1,
    ECEF = 2,
    GLOBAL = 3,
    LOCAL = 4  // ignition-math's LOCAL, which keeps Gazebo 11's heading convention
  };

  SphericalCoordinates();
  explicit SphericalCoordinates(const SurfaceType _type);
  SphericalCoordinates(const SurfaceType _type, const ignition::math::Angle& _latitude,
                       const ignition::math::Angle& _longitude, double _elevation,
                       const ignition::math::Angle& _heading);
  ~SphericalCoordinates();

  // Latitude (degrees), longitude (degrees) and altitude (m) of a position in the world's frame.
  ignition::math::Vector3d SphericalFromLocal(const ignition::math::Vector3d& _xyz) const;
  // A velocity in the world's frame as east, north, up.
  ignition::math::Vector3d GlobalFromLocal(const ignition::math::Vector3d& _xyz) const;
  ignition::math::Vector3d LocalFromSpherical(const ignition::math::Vector3d& _xyz) const;
  ignition::math::Vector3d LocalFromGlobal(const ignition::math::Vector3d& _xyz) const;
  // "EARTH_WGS84" (Gazebo's error and EARTH_WGS84 for any other)
  static SurfaceType Convert(const std::string& _str);
  // The great-circle distance between two points, m.
  static double Distance(const ignition::math::Angle& _latA, const ignition::math::Angle& _lonA,
                         const ignition::math::Angle& _latB, const ignition::math::Angle& _lonB);
  SurfaceType GetSurfaceType() const;
  ignition::math::Angle LatitudeReference() const;
  ignition::math::Angle LongitudeReference() const;
  double GetElevationReference() const;
  ignition::math::Angle HeadingOffset() const;
  void SetSurfaceType(const SurfaceType& _type);
  void SetLatitudeReference(const ignition::math::Angle& _angle);
  void SetLongitudeReference(const ignition::math::Angle& _angle);
  void SetElevationReference(double _elevation);
  void SetHeadingOffset(const ignition::math::Angle& _angle);
  void UpdateTransformationMatrix();
  ignition::math::Vector3d PositionTransform(const ignition::math::Vector3d& _pos, const CoordinateType& _in,
                                             const CoordinateType& _out) const;
  ignition::math::Vector3d VelocityTransform(const ignition::math::Vector3d& _vel, const CoordinateType& _in,
                                             const CoordinateType& _out) const;

private:
  ignition::math::SphericalCoordinates math_;
};
}  // namespace common
}  // namespace gazebo
