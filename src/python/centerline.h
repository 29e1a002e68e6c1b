// A race track's centre line: a closed polyline of (x, y) points in the direction of racing, and
// where a position lies along it; and a car's laps along it. bullet_plant.Centerline (racing/track.py's
// Centerline builds on it) and CarBatch, which measures each car's progress and laps in its world's
// task, use this one projection.
#pragma once

#include <array>
#include <cstddef>
#include <limits>
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

// A car's laps and lap times. Where the car is along the track: u, metres from the start line (s = 0)
// in the direction of racing, from its start (the nearest crossing of the line: in (-length/2,
// length/2]) plus what it has travelled along the centre line since. A lap is done when u first
// reaches a whole number of track lengths (1, 2, ...): a car that goes back over the line and forward
// again counts it once. It is timed from the crossing before it, found between two reads by
// interpolation (a car covers less than a lap a read); the first lap from the start when the car
// started on or behind the line (a grid start: as a race times its first lap, from the lights), and
// not at all when it started past it (short of a whole lap). Times are simulated seconds; +inf until
// a lap is timed (NaN would make two equal infos unequal: Gymnasium's check_env compares them).
class LapTimer
{
public:
  static constexpr double kNotTimed = std::numeric_limits<double>::infinity();

  explicit LapTimer(double length = 0) : length_(length) {}

  // The car starts at u = `start` (m) at `time` (s).
  void restart(double start, double time);
  // The car has travelled this far along the centre line since its start (m), at `time` (s).
  void read(double travelled, double time);

  long count() const { return count_; }  // laps done
  double last() const { return last_; }  // s, kNotTimed before a lap is timed
  double best() const { return best_; }

private:
  double length_;
  double start_ = 0;  // u at the start (m)
  long count_ = 0;
  double clock_ = std::numeric_limits<double>::quiet_NaN();  // when the lap under way started (s); NaN: not timed
  double last_ = kNotTimed, best_ = kNotTimed;
  double u_ = 0, time_ = 0;  // at the last read
};

}  // namespace python
}  // namespace bullet_plant
