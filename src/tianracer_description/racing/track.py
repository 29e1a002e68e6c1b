"""A race track's centre line, by which the environments measure progress: a closed polyline of (x, y)
points in the direction of racing. Shipped beside each world of ours that is a track
(worlds/race_track.centerline.csv, written by tools/make_race_track.py from the numbers that build the
world), and read for any other world from a file of the same form.

The projection and poses are bullet_plant.Centerline's, the same code CarBatch measures the cars'
progress with while it steps them. Centerline adds the line's curvature and a pose's Frenet
coordinates (s, ey, epsi) on it; the environments' observations of them (cars.py) are these.
A race line is a Centerline too: the same arithmetic on its points."""
import math
import os

import numpy as np

from tianracer_description import bullet_plant

CURVATURE_SPAN = 0.5  # m of line whose turn curvature_at averages


def centerline_file(world_file):
    """Where a world's centre line lives: beside it, <world>.centerline.csv."""
    return os.path.splitext(world_file)[0] + '.centerline.csv'


class Centerline(bullet_plant.Centerline):
    """A closed polyline (bullet_plant.Centerline: length, project, pose_at, progress), read from a file
    too. ValueError names what is wrong with the points."""

    def _turning(self):
        """(the arc length at each point (m, from the first), the cumulative turn up to and at each
        point (rad, left positive; 0 first)), made once."""
        if not hasattr(self, '_turns'):
            points = self.points
            out_of = np.roll(points, -1, axis=0) - points  # segment k, from point k
            headings = np.arctan2(out_of[:, 1], out_of[:, 0])
            turns = wrap_angle(headings - np.roll(headings, 1))  # at point k, from segment k - 1 into k
            vertex_s = np.concatenate([[0.0], np.cumsum(np.hypot(out_of[:, 0], out_of[:, 1]))[:-1]])
            self._turns = vertex_s, np.concatenate([[0.0], np.cumsum(turns)])
        return self._turns

    def turned(self, s):
        """How far the line has turned from s = 0 to arc lengths s (an array, any number of laps; rad,
        left positive)."""
        vertex_s, cumulative = self._turning()
        s = np.asarray(s, np.float64)
        laps = np.floor(s / self.length)
        return laps * cumulative[-1] + cumulative[np.searchsorted(vertex_s, s - laps * self.length, side='right')]

    def curvature_at(self, s, span=CURVATURE_SPAN):
        """The line's curvature at arc lengths s (an array, any number of laps; 1/m, positive turning
        left): its turn over `span` metres centred there, over span. A polyline turns at its points
        alone, and their coordinates' rounding (a CSV's 0.1 mm) makes each point's own turn noisy
        (+-7 % on the race track's 5 cm segments); over 0.5 m it is within 1 %."""
        s = np.asarray(s, np.float64)
        return (self.turned(s + span / 2.0) - self.turned(s - span / 2.0)) / span

    def frenet(self, x, y, yaw, s=None, offset=None):
        """(s, ey, epsi) of a pose: the arc length of its nearest point of the line (m), its signed distance
        from it (m, positive to the left of the direction of racing), and its heading less the line's
        there (rad, in [-pi, pi]). s and offset: the projection where it is already known."""
        if s is None:
            s, offset, _ = self.project(x, y)
        return s, offset, wrap_angle(yaw - self.pose_at(s)[2])

    @classmethod
    def from_file(cls, path):
        """x y per line, '#' comments; FileNotFoundError naming what to do when there is none."""
        if not os.path.isfile(path):
            raise FileNotFoundError("no centre line at %s: write one (x y per line, in the direction of racing) "
                                    "or pass centerline= as points" % path)
        return cls(np.loadtxt(path, comments='#', ndmin=2))


def wrap_angle(angle):
    """An angle (or an array of them) in [-pi, pi]."""
    return np.mod(np.asarray(angle) + math.pi, 2.0 * math.pi) - math.pi


def track_world_sdf(name, comment, parts):
    """An SDF world of the ground plane, the sun, 1 ms physics at real time and `parts` (SDF text of
    its models): the frame of every track world of ours, written by tools/make_race_track.py,
    tools/make_race_circuit.py and f1tenth_map.py."""
    return f"""<?xml version="1.0"?>
<!-- {comment} -->
<sdf version="1.6">
  <world name="{name}">
    <include>
      <uri>model://ground_plane</uri>
    </include>
    <include>
      <uri>model://sun</uri>
    </include>
    <physics type="ode">
      <max_step_size>0.001</max_step_size>
      <real_time_factor>1</real_time_factor>
      <real_time_update_rate>1000</real_time_update_rate>
    </physics>
    <gravity>0 0 -9.8</gravity>
{''.join(parts)}  </world>
</sdf>
"""
