// A race track's centre line: a closed polyline of (x, y) points in the direction of racing, and
// where a position lies along it. bullet_plant.Centerline (racing/track.py's Centerline builds on it)
// and CarBatch, which measures each car's progress in its world's task, use this one projection.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

namespace bullet_plant
{
namespace python
{
class Centerline
{
public:
  // Searched either side of the last nearest segment by project's `near`: a car moves less than
  // that in a control period.
  static constexpr std::ptrdiff_t kNearSegments = 4;

  struct Projection
  {
    double s;       // arc length of the nearest point of the line, from its first point
    double offset;  // signed distance to it, positive to the left of the direction of racing
    std::ptrdiff_t segment;  // the segment (from point k to k + 1) it lies on
  };

  struct Pose
  {
    double x, y, yaw;
  };

  // Throws std::invalid_argument naming the problem: fewer than three points, a point repeated, or
  // one not finite.
  explicit Centerline(std::vector<std::array<double, 2>> points);

  // The nearest point of the line to (x, y): of every segment, or (near >= 0, a segment an earlier
  // call returned) of those within kNearSegments of it.
  Projection project(double x, double y, std::ptrdiff_t near = -1) const;
  // The point at arc length s (any number of laps), `offset` to its left, facing the direction of racing.
  Pose poseAt(double s, double offset) const;
  // How far s_to is ahead of s_from along the lap (negative: behind), across the start line too:
  // within half a lap either way.
  double progress(double s_from, double s_to) const;

  double length() const { return length_; }
  const std::vector<std::array<double, 2>>& points() const { return points_; }

private:
  std::vector<std::array<double, 2>> points_;
  std::vector<std::array<double, 2>> segments_;  // from each point to the next, the last closing the loop
  std::vector<double> lengths_, squared_lengths_, starts_;  // starts_: arc length at each point
  double length_ = 0;  // of a lap
};

}  // namespace python
}  // namespace bullet_plant
