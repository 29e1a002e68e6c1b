// bullet_plant.Centerline: see centerline.h.
#include "centerline.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "bindings.h"

namespace bullet_plant
{
namespace python
{
Centerline::Centerline(std::vector<std::array<double, 2>> points) : points_(std::move(points))
{
  const size_t count = points_.size();
  if (count < 3)
    throw std::invalid_argument("a centre line is three or more (x, y) points; got " + std::to_string(count));
  for (size_t k = 0; k < count; ++k)
  {
    const auto& p = points_[k];
    const auto& next = points_[(k + 1) % count];
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]))
      throw std::invalid_argument("a centre line's point " + std::to_string(k) + " is not finite");
    segments_.push_back({next[0] - p[0], next[1] - p[1]});
    lengths_.push_back(std::hypot(segments_[k][0], segments_[k][1]));
    if (lengths_[k] == 0)
      throw std::invalid_argument("a centre line repeats a point at index " + std::to_string(k));
    squared_lengths_.push_back(lengths_[k] * lengths_[k]);
    starts_.push_back(length_);
    length_ += lengths_[k];
  }
}

Centerline::Projection Centerline::project(double x, double y, std::ptrdiff_t near) const
{
  const auto count = std::ptrdiff_t(points_.size());
  const bool everywhere = near < 0 || near >= count;
  const std::ptrdiff_t first = everywhere ? 0 : near - kNearSegments;
  const std::ptrdiff_t last = everywhere ? count - 1 : near + kNearSegments;
  double best = INFINITY, best_along = 0, nx = 0, ny = 0;
  std::ptrdiff_t best_k = 0;
  for (std::ptrdiff_t j = first; j <= last; ++j)
  {
    const std::ptrdiff_t k = ((j % count) + count) % count;
    const auto& p = points_[k];
    const auto& d = segments_[k];
    const double along = std::min(1.0, std::max(0.0, ((x - p[0]) * d[0] + (y - p[1]) * d[1]) / squared_lengths_[k]));
    const double px = p[0] + along * d[0], py = p[1] + along * d[1];
    const double squared = (x - px) * (x - px) + (y - py) * (y - py);
    if (squared < best)
      best = squared, best_k = k, best_along = along, nx = px, ny = py;
  }
  const auto& d = segments_[best_k];
  const double offset = std::copysign(std::sqrt(best), d[0] * (y - ny) - d[1] * (x - nx));
  return {starts_[best_k] + best_along * lengths_[best_k], offset, best_k};
}

Centerline::Pose Centerline::poseAt(double s, double offset) const
{
  s = std::fmod(s, length_);
  if (s < 0)
    s = std::min(s + length_, std::nextafter(length_, 0.0));
  const auto k = std::ptrdiff_t(std::upper_bound(starts_.begin(), starts_.end(), s) - starts_.begin()) - 1;
  const double u = (s - starts_[k]) / lengths_[k];
  const double dx = segments_[k][0] / lengths_[k], dy = segments_[k][1] / lengths_[k];
  const double x = points_[k][0] + u * segments_[k][0], y = points_[k][1] + u * segments_[k][1];
  return {x - dy * offset, y + dx * offset, std::atan2(dy, dx)};
}

double Centerline::progress(double s_from, double s_to) const
{
  const double half = length_ / 2;
  const double ahead = std::fmod(s_to - s_from + half, length_);  // Python's %: the divisor's sign
  return (ahead < 0 ? ahead + length_ : ahead) - half;
}

void LapTimer::restart(double start, double time)
{
  start_ = u_ = start;
  time_ = time;
  count_ = 0;
  clock_ = start <= 0.0 ? time : std::numeric_limits<double>::quiet_NaN();
  last_ = best_ = kNotTimed;
}

void LapTimer::read(double travelled, double time)
{
  const double u = start_ + travelled;
  const double reached = std::floor(u / length_);
  if (reached > double(count_))
  {
    const double share = u > u_ ? std::min(std::max((reached * length_ - u_) / (u - u_), 0.0), 1.0) : 1.0;
    const double crossed = time_ + share * (time - time_);
    const double lap = crossed - clock_;
    if (std::isfinite(lap))
    {
      last_ = lap;
      best_ = std::min(best_, lap);
    }
    clock_ = crossed;
    count_ = long(reached);
  }
  u_ = u;
  time_ = time;
}

void init_centerline(py::module_& m)
{
  py::class_<Centerline, std::shared_ptr<Centerline>>(
      m, "Centerline",
      "a race track's centre line: a closed polyline of (x, y) points in the direction of racing; "
      "arc length along it, the nearest point to a position, poses on it")
      .def(py::init([](py::array_t<double, py::array::c_style | py::array::forcecast> points) {
             if (points.ndim() != 2 || points.shape(1) != 2)
               throw py::value_error("a centre line is an array of (x, y) rows; got one of " +
                                     std::to_string(points.ndim()) + " dimensions" +
                                     (points.ndim() == 2 ? " and " + std::to_string(points.shape(1)) + " columns" : ""));
             std::vector<std::array<double, 2>> rows(size_t(points.shape(0)));
             std::copy_n(points.data(), 2 * rows.size(), rows.empty() ? nullptr : rows[0].data());
             try
             {
               return std::make_shared<Centerline>(std::move(rows));
             }
             catch (const std::invalid_argument& e)
             {
               throw py::value_error(e.what());
             }
           }),
           py::arg("points"))
      .def_property_readonly("length", &Centerline::length, "of a lap (m)")
      .def_property_readonly("points", [](const Centerline& line) {
        const auto& points = line.points();
        return py::array_t<double>({points.size(), size_t(2)}, points[0].data());
      }, "the (x, y) points, a copy")
      .def("project", [](const Centerline& line, double x, double y, py::object near) {
             const Centerline::Projection p = line.project(x, y, near.is_none() ? -1 : near.cast<std::ptrdiff_t>());
             return py::make_tuple(p.s, p.offset, p.segment);
           }, py::arg("x"), py::arg("y"), py::arg("near") = py::none(),
           "(s, offset, segment): the arc length of the nearest point of the line, the signed distance to it "
           "(positive to the left of the direction of racing) and the segment it lies on. With `near` (a "
           "segment an earlier call returned), only the segments within NEAR_SEGMENTS of it are searched")
      .def("pose_at", [](const Centerline& line, double s, double offset) {
             const Centerline::Pose p = line.poseAt(s, offset);
             return py::make_tuple(p.x, p.y, p.yaw);
           }, py::arg("s"), py::arg("offset") = 0.0,
           "(x, y, yaw): the point at arc length s (any number of laps), `offset` to its left, facing the "
           "direction of racing")
      .def("progress", &Centerline::progress, py::arg("s_from"), py::arg("s_to"),
           "how far s_to is ahead of s_from along the lap (negative: behind), across the start line too")
      .def_readonly_static("NEAR_SEGMENTS", &Centerline::kNearSegments);

  py::class_<LapTimer>(m, "LapTimer",
                       "a car's laps and lap times along a centre line of `length` (m), as CarBatch counts them "
                       "(centerline.h): a lap is done when the car's way from the start line first reaches a "
                       "whole number of lengths; times in simulated seconds, inf until a lap is timed")
      .def(py::init([](double length) {
             if (!(length > 0 && std::isfinite(length)))
               throw py::value_error("LapTimer: a lap's length is a distance above 0 (m); got " + std::to_string(length));
             return LapTimer(length);
           }),
           py::arg("length"))
      .def("restart", &LapTimer::restart, py::arg("start"), py::arg("time"),
           "the car starts `start` m from the start line (in (-length/2, length/2]) at `time` (s)")
      .def("read", &LapTimer::read, py::arg("travelled"), py::arg("time"),
           "the car has travelled this far along the centre line since its start (m), at `time` (s)")
      .def_property_readonly("count", &LapTimer::count, "laps done")
      .def_property_readonly("last", &LapTimer::last, "the last lap's time (s), inf before one is timed")
      .def_property_readonly("best", &LapTimer::best, "the best lap's time (s), inf before one is timed");
}

}  // namespace python
}  // namespace bullet_plant
