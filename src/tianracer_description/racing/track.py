"""A race track's centre line, by which the environments measure progress: a closed polyline of (x, y)
points in the direction of racing. Shipped beside each world of ours that is a track
(worlds/race_track.centerline.csv, written by tools/make_race_track.py from the numbers that build the
world), and read for any other world from a file of the same form.

The projection and poses are bullet_plant.Centerline's, the same code CarBatch measures the cars'
progress with while it steps them."""
import os

import numpy as np

from tianracer_description import bullet_plant


def centerline_file(world_file):
    """Where a world's centre line lives: beside it, <world>.centerline.csv."""
    return os.path.splitext(world_file)[0] + '.centerline.csv'


class Centerline(bullet_plant.Centerline):
    """A closed polyline (bullet_plant.Centerline: length, project, pose_at, progress), read from a file
    too. ValueError names what is wrong with the points."""

    @classmethod
    def from_file(cls, path):
        """x y per line, '#' comments; FileNotFoundError naming what to do when there is none."""
        if not os.path.isfile(path):
            raise FileNotFoundError("no centre line at %s: write one (x y per line, in the direction of racing) "
                                    "or pass centerline= as points" % path)
        return cls(np.loadtxt(path, comments='#', ndmin=2))


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
