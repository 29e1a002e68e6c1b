"""A race track's centre line, by which the environments measure progress: a closed polyline of (x, y)
points in the direction of racing. Shipped beside each world of ours that is a track
(worlds/race_track.centerline.csv, written by tools/make_race_track.py from the numbers that build the
world), and read for any other world from a file of the same form."""
import math
import os

import numpy as np


def centerline_file(world_file):
    """Where a world's centre line lives: beside it, <world>.centerline.csv."""
    return os.path.splitext(world_file)[0] + '.centerline.csv'


class Centerline:
    """A closed polyline: arc length along it, the nearest point to a position, poses on it."""

    NEAR_SEGMENTS = 4  # searched either side of the last nearest segment (project's `near`)

    def __init__(self, points):
        points = np.asarray(points, dtype=np.float64)
        if points.ndim != 2 or points.shape[1] != 2 or len(points) < 3:
            raise ValueError('a centre line is three or more (x, y) points; got an array of shape %s'
                             % (points.shape,))
        self.points = points
        self.segments = np.roll(points, -1, axis=0) - points  # from each point to the next, closing the loop
        self.lengths = np.hypot(self.segments[:, 0], self.segments[:, 1])
        if np.any(self.lengths == 0):
            raise ValueError('a centre line repeats a point at index %d' % int(np.argmin(self.lengths)))
        self.starts = np.concatenate([[0.0], np.cumsum(self.lengths)[:-1]])  # arc length at each point
        self.length = float(np.sum(self.lengths))  # of a lap
        # The same as Python floats, for project's loop.
        self._points, self._segments = self.points.tolist(), self.segments.tolist()
        self._lengths, self._starts = self.lengths.tolist(), self.starts.tolist()
        self._squared_lengths = (self.lengths ** 2).tolist()

    @classmethod
    def from_file(cls, path):
        """x y per line, '#' comments; FileNotFoundError naming what to do when there is none."""
        if not os.path.isfile(path):
            raise FileNotFoundError("no centre line at %s: write one (x y per line, in the direction of racing) "
                                    "or pass centerline= as points" % path)
        return cls(np.loadtxt(path, comments='#', ndmin=2))

    def project(self, x, y, near=None):
        """(s, offset, segment): the arc length of the nearest point of the line, the signed distance to
        it (positive to the left of the direction of racing) and the segment it lies on. With `near`
        (a segment an earlier call returned), only the segments within NEAR_SEGMENTS of it are searched:
        a car moves less than that in a step."""
        count = len(self._points)
        candidates = range(count) if near is None else \
            ((near + d) % count for d in range(-self.NEAR_SEGMENTS, self.NEAR_SEGMENTS + 1))
        best = None
        for k in candidates:  # plain floats: numpy's overhead outweighs a few segments' arithmetic
            px, py = self._points[k]
            dx, dy = self._segments[k]
            along = min(1.0, max(0.0, ((x - px) * dx + (y - py) * dy) / self._squared_lengths[k]))
            nx, ny = px + along * dx, py + along * dy
            squared = (x - nx) ** 2 + (y - ny) ** 2
            if best is None or squared < best[0]:
                best = (squared, k, along, nx, ny, dx, dy)
        squared, k, along, nx, ny, dx, dy = best
        offset = math.copysign(math.sqrt(squared), dx * (y - ny) - dy * (x - nx))
        return self._starts[k] + along * self._lengths[k], offset, k


    def progress(self, s_from, s_to):
        """How far s_to is ahead of s_from along the lap (negative: behind), across the start line too."""
        return (s_to - s_from + self.length / 2) % self.length - self.length / 2

    def pose_at(self, s, offset=0.0):
        """(x, y, yaw): the point at arc length s (any number of laps), `offset` to its left, facing the
        direction of racing."""
        s = s % self.length
        k = int(np.searchsorted(self.starts, s, side='right')) - 1
        u = (s - self.starts[k]) / self.lengths[k]
        dx, dy = self.segments[k] / self.lengths[k]
        x, y = self.points[k] + u * self.segments[k]
        return float(x - dy * offset), float(y + dx * offset), math.atan2(dy, dx)
