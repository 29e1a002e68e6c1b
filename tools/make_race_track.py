#!/usr/bin/env python3
"""Writes worlds/race_track.world: a closed stadium-shaped track with walls, sized for the Tianracer, and
worlds/race_track.centerline.csv: its centre line (x, y every 5 cm, counter-clockwise from the start at
the origin), by which the Gymnasium environment measures progress.

The centre line has 6 m straights and 1.5 m radius bends (the car turns down to about 0.45 m), the
lane is 1.2 m wide, walls are 0.3 m high boxes (the lidar scans at about 9 cm). The bottom straight
runs along the x axis through the origin, so the car spawned at the origin facing +x is on the track.
Run it again after changing the numbers below; the world file is committed.
"""
import math
import os

from tianracer_description.racing.track import track_world_sdf

STRAIGHT = 6.0        # m, length of each straight
RADIUS = 1.5          # m, centre line radius of the bends
LANE = 1.2            # m, wall to wall
WALL_HEIGHT = 0.3
WALL_THICKNESS = 0.05
ARC_SEGMENTS = 16     # boxes per half circle
CENTRE_Y = RADIUS     # the bottom straight's centre line is y = 0


def wall(name, x0, y0, x1, y1):
    length = math.hypot(x1 - x0, y1 - y0) + WALL_THICKNESS  # overlap the joints
    yaw = math.atan2(y1 - y0, x1 - x0)
    return f"""    <model name="{name}">
      <static>true</static>
      <pose>{(x0 + x1) / 2:.4f} {(y0 + y1) / 2:.4f} {WALL_HEIGHT / 2:.4f} 0 0 {yaw:.6f}</pose>
      <link name="link">
        <collision name="collision">
          <geometry><box><size>{length:.4f} {WALL_THICKNESS} {WALL_HEIGHT}</size></box></geometry>
        </collision>
        <visual name="visual">
          <geometry><box><size>{length:.4f} {WALL_THICKNESS} {WALL_HEIGHT}</size></box></geometry>
          <material><ambient>0.8 0.1 0.1 1</ambient><diffuse>0.8 0.1 0.1 1</diffuse></material>
        </visual>
      </link>
    </model>
"""


def boundary(prefix, radius):
    """A stadium of the given bend radius around the track's centre, as wall segments."""
    half = STRAIGHT / 2
    walls = [wall(f"{prefix}_straight_south", -half, CENTRE_Y - radius, half, CENTRE_Y - radius),
             wall(f"{prefix}_straight_north", half, CENTRE_Y + radius, -half, CENTRE_Y + radius)]
    for end, cx, start_angle in (("east", half, -math.pi / 2), ("west", -half, math.pi / 2)):
        for i in range(ARC_SEGMENTS):
            a0 = start_angle + math.pi * i / ARC_SEGMENTS
            a1 = start_angle + math.pi * (i + 1) / ARC_SEGMENTS
            walls.append(wall(f"{prefix}_bend_{end}_{i:02d}",
                              cx + radius * math.cos(a0), CENTRE_Y + radius * math.sin(a0),
                              cx + radius * math.cos(a1), CENTRE_Y + radius * math.sin(a1)))
    return walls


def cone(name, x, y):
    return f"""    <model name="{name}">
      <static>true</static>
      <pose>{x} {y} 0.1 0 0 0</pose>
      <link name="link">
        <collision name="collision"><geometry><cylinder><radius>0.05</radius><length>0.2</length></cylinder></geometry></collision>
        <visual name="visual">
          <geometry><cylinder><radius>0.05</radius><length>0.2</length></cylinder></geometry>
          <material><ambient>1 0.5 0 1</ambient><diffuse>1 0.5 0 1</diffuse></material>
        </visual>
      </link>
    </model>
"""


CENTERLINE_SPACING = 0.05  # m between the centre line's points


def centerline():
    """The centre line's points, counter-clockwise from the origin (the start, facing +x)."""
    half = STRAIGHT / 2
    lap = 2 * STRAIGHT + 2 * math.pi * RADIUS
    points = []
    for k in range(int(round(lap / CENTERLINE_SPACING))):
        s = k * lap / round(lap / CENTERLINE_SPACING)
        # from the origin: half the south straight, the east bend, the north straight, the west
        # bend, the other half of the south straight
        legs = [half, math.pi * RADIUS, STRAIGHT, math.pi * RADIUS]
        if s < legs[0]:
            points.append((s, 0.0))
            continue
        s -= legs[0]
        if s < legs[1]:
            a = -math.pi / 2 + s / RADIUS
            points.append((half + RADIUS * math.cos(a), CENTRE_Y + RADIUS * math.sin(a)))
            continue
        s -= legs[1]
        if s < legs[2]:
            points.append((half - s, 2 * RADIUS))
            continue
        s -= legs[2]
        if s < legs[3]:
            a = math.pi / 2 + s / RADIUS
            points.append((-half + RADIUS * math.cos(a), CENTRE_Y + RADIUS * math.sin(a)))
            continue
        s -= legs[3]
        points.append((-half + s, 0.0))
    return points


def world_text(name, comment, parts):
    """An SDF world of the ground plane, the sun, 1 ms physics and `parts` (the package's frame for
    track worlds)."""
    return track_world_sdf(name, comment, parts)


def write_track(name, text, centre_line, tool):
    """worlds/<name>.world and its centre line worlds/<name>.centerline.csv."""
    path = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "worlds", name + ".world")
    with open(path, "w") as f:
        f.write(text)
    print(f"wrote {path}")
    path = path.replace(".world", ".centerline.csv")
    with open(path, "w") as f:
        f.write(f"# x y (m): the centre line of {name}.world, counter-clockwise from the start; made by {tool}\n")
        f.writelines(f"{x:.4f} {y:.4f}\n" for x, y in centre_line)
    print(f"wrote {path}")


def main():
    parts = boundary("outer", RADIUS + LANE / 2) + boundary("inner", RADIUS - LANE / 2)
    parts += [cone("cone_1", 1.5, 0.35), cone("cone_2", -1.0, 2 * RADIUS - 0.35)]
    comment = (f"Generated by tools/make_race_track.py: a closed track with walls for the Tianracer.\n"
               f"     Centre line: {STRAIGHT} m straights, {RADIUS} m bends; lane {LANE} m; the car starts at the "
               f"origin facing +x.")
    write_track("race_track", world_text("race_track", comment, parts), centerline(), "tools/make_race_track.py")


if __name__ == "__main__":
    main()
