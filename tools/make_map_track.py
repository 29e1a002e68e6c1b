#!/usr/bin/env python3
"""Writes worlds/peanut_map.pgm and worlds/peanut_map.yaml: a track of our own as f1tenth keeps its
tracks (a ROS map_server map), worlds/peanut_centerline.csv (f1tenth's centre line CSV) and
worlds/peanut_raceline.csv (f1tenth's race line CSV), drawn from a parametric closed curve.

The centre line is a peanut, r = A + B cos(2 theta) in polar coordinates with y squashed by
SQUASH: 19.2 m a lap, bends down to 1.3 m radius and a waist on either side that bends the other
way (3.7 m), so a lap turns both ways. It runs counter-clockwise from the start at the origin,
facing +x. The map at RESOLUTION: free (254) within LANE / 2 of the centre line, a wall (0)
WALL_THICKNESS wide beyond it, unknown (205, neither free nor occupied under the thresholds) the
rest, as map_server's map_saver writes maps. The race line is the centre line pulled towards the
inside of the bends within the lane (less curvature), its speed from the curvature (lateral
acceleration LATERAL_ACCEL, at most TOP_SPEED, braking and accelerating at LONGITUDINAL_ACCEL).
Standard library and numpy only; run it again after changing the numbers below.
"""
import math
import os

import numpy as np

NAME = 'peanut'
A, B, SQUASH = 3.0, 0.9, 0.8  # m, m, the y scale
LANE = 1.2             # m, wall to wall
WALL_THICKNESS = 0.1   # m
RESOLUTION = 0.05      # m a pixel, as f1tenth's maps
MARGIN = 0.3           # m of unknown around the walls
CENTERLINE_SPACING = 0.05  # m between the lines' points
RACELINE_CLEARANCE = 0.35  # m the race line keeps from a wall (the car's half width and room)
TOP_SPEED = 2.0            # m/s, the environments' default max_speed
LATERAL_ACCEL = 2.5        # m/s^2
LONGITUDINAL_ACCEL = 2.0   # m/s^2
FREE, UNKNOWN, OCCUPIED = 254, 205, 0
WORLDS = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), 'worlds')


def peanut(count=20000):
    """Dense points of the closed curve, counter-clockwise from its bottom waist, moved so that it
    starts at the origin (where the curve heads +x)."""
    theta = np.linspace(-math.pi / 2, 3 * math.pi / 2, count, endpoint=False)
    r = A + B * np.cos(2 * theta)
    x, y = r * np.cos(theta), SQUASH * r * np.sin(theta)
    return np.column_stack([x - x[0], y - y[0]])


def resample(points, spacing):
    """A closed polyline's points every `spacing` metres of its length (the last segment closing it)."""
    closed = np.vstack([points, points[:1]])
    s = np.concatenate([[0.0], np.cumsum(np.hypot(*np.diff(closed, axis=0).T))])
    count = int(round(s[-1] / spacing))
    targets = np.arange(count) * s[-1] / count
    return np.column_stack([np.interp(targets, s, closed[:, 0]), np.interp(targets, s, closed[:, 1])])


def headings_and_curvatures(points):
    """Each point's heading (rad) and curvature (1/m, left positive) by central differences on the loop."""
    ahead, behind = np.roll(points, -1, axis=0), np.roll(points, 1, axis=0)
    heading = np.arctan2(*(ahead - behind).T[::-1])
    turn = np.angle(np.exp(1j * (np.arctan2(*(ahead - points).T[::-1]) - np.arctan2(*(points - behind).T[::-1]))))
    step = (np.hypot(*(ahead - points).T) + np.hypot(*(points - behind).T)) / 2
    return heading, turn / step


def raceline(centre):
    """The centre line pulled towards the inside of its bends: offsets along the normals smoothed
    (a Laplacian's pull shortens and straightens the line) and held within the lane less the
    clearance. (points, the points' offsets)."""
    heading, _ = headings_and_curvatures(centre)
    normal = np.column_stack([-np.sin(heading), np.cos(heading)])
    limit = LANE / 2 - RACELINE_CLEARANCE
    offset = np.zeros(len(centre))
    for _ in range(3000):
        points = centre + offset[:, None] * normal
        pulled = points + 0.5 * ((np.roll(points, 1, axis=0) + np.roll(points, -1, axis=0)) / 2 - points)
        offset = np.clip(np.sum((pulled - centre) * normal, axis=1), -limit, limit)
    return centre + offset[:, None] * normal, offset


def speed_profile(curvature, spacing):
    """Speeds along a loop: the lateral limit in the bends, then braking before them and
    accelerating out of them at LONGITUDINAL_ACCEL (passes round the loop until nothing changes)."""
    speed = np.minimum(TOP_SPEED, np.sqrt(LATERAL_ACCEL / np.maximum(np.abs(curvature), 1e-9)))
    count = len(speed)
    for _ in range(3):
        for k in range(2 * count):  # forwards: accelerating
            i, j = k % count, (k + 1) % count
            speed[j] = min(speed[j], math.sqrt(speed[i] ** 2 + 2 * LONGITUDINAL_ACCEL * spacing))
        for k in range(2 * count, 0, -1):  # backwards: braking
            i, j = k % count, (k - 1) % count
            speed[j] = min(speed[j], math.sqrt(speed[i] ** 2 + 2 * LONGITUDINAL_ACCEL * spacing))
    return speed


def distances_to(points, xs, ys):
    """Each (x, y) cell centre's distance to the closed polyline (m), exactly, segment by segment."""
    a, b = points, np.roll(points, -1, axis=0)
    d = b - a
    best = np.full(xs.shape, np.inf)
    for (ax, ay), (dx, dy) in zip(a, d):
        t = np.clip(((xs - ax) * dx + (ys - ay) * dy) / (dx * dx + dy * dy), 0.0, 1.0)
        best = np.minimum(best, np.hypot(xs - ax - t * dx, ys - ay - t * dy))
    return best


def draw_map(centre):
    """The map's pixels (top row first, as the image stores them) and its origin (x, y of the
    lower-left corner)."""
    reach = LANE / 2 + WALL_THICKNESS + MARGIN
    low = np.floor((centre.min(axis=0) - reach) / RESOLUTION) * RESOLUTION
    high = centre.max(axis=0) + reach
    columns, rows = (np.ceil((high - low) / RESOLUTION)).astype(int)
    xs = low[0] + (np.arange(columns) + 0.5) * RESOLUTION
    ys = low[1] + (rows - 1 - np.arange(rows) + 0.5) * RESOLUTION  # row 0 is the top: the largest y
    distance = distances_to(resample(centre, 0.1), *np.meshgrid(xs, ys))
    pixels = np.full((rows, columns), UNKNOWN, np.uint8)
    pixels[distance <= LANE / 2 + WALL_THICKNESS] = OCCUPIED
    pixels[distance <= LANE / 2] = FREE
    return pixels, (float(low[0]), float(low[1]))


def write_pgm(path, pixels, comment):
    with open(path, 'wb') as f:
        f.write(b'P5\n# %s\n%d %d\n255\n' % (comment.encode(), pixels.shape[1], pixels.shape[0]))
        f.write(np.ascontiguousarray(pixels, np.uint8).tobytes())


def main():
    tool = 'tools/make_map_track.py'
    centre = resample(peanut(), CENTERLINE_SPACING)
    pixels, origin = draw_map(centre)
    image = NAME + '_map.pgm'
    write_pgm(os.path.join(WORLDS, image), pixels, 'the %s track, drawn by %s' % (NAME, tool))
    with open(os.path.join(WORLDS, NAME + '_map.yaml'), 'w') as f:
        f.write(f"# The {NAME} track as a ROS map_server map (f1tenth's track format), drawn by {tool}\n"
                f"image: {image}\nresolution: {RESOLUTION}\norigin: [{origin[0]:.4f}, {origin[1]:.4f}, 0.0]\n"
                f"negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n")
    with open(os.path.join(WORLDS, NAME + '_centerline.csv'), 'w') as f:
        f.write(f"# the centre line of {NAME}_map.yaml, counter-clockwise from the start (f1tenth's centre line CSV); made by {tool}.\n"
                "# x_m, y_m, w_tr_right_m, w_tr_left_m\n")
        f.writelines('%.4f, %.4f, %.3f, %.3f\n' % (x, y, LANE / 2, LANE / 2) for x, y in centre)
    line, _ = raceline(centre)
    line = resample(line, CENTERLINE_SPACING)
    heading, curvature = headings_and_curvatures(line)
    spacing = np.hypot(*np.diff(np.vstack([line, line[:1]]), axis=0).T)
    s = np.concatenate([[0.0], np.cumsum(spacing[:-1])])
    speed = speed_profile(curvature, float(np.mean(spacing)))
    accel = (np.roll(speed, -1) ** 2 - speed ** 2) / (2 * spacing)
    with open(os.path.join(WORLDS, NAME + '_raceline.csv'), 'w') as f:
        f.write(f"# the race line of {NAME}_map.yaml (f1tenth's race line CSV: inside the bends, speeds from the curvature); made by {tool}.\n"
                "# s_m; x_m; y_m; psi_rad; kappa_radpm; vx_mps; ax_mps2\n")
        f.writelines('%.4f; %.4f; %.4f; %.5f; %.5f; %.3f; %.3f\n' % row
                     for row in zip(s, line[:, 0], line[:, 1], np.mod(heading, 2 * math.pi), curvature, speed, accel))
    _, centre_curvature = headings_and_curvatures(centre)
    print('wrote worlds/%s_map.pgm (%d x %d), .yaml, _centerline.csv (%.2f m a lap, bends down to %.2f m) and '
          '_raceline.csv (%.2f m, %.2f-%.2f m/s)'
          % (NAME, pixels.shape[1], pixels.shape[0], len(centre) * CENTERLINE_SPACING,
             1 / np.abs(centre_curvature).max(), float(np.sum(spacing)), speed.min(), speed.max()))


if __name__ == '__main__':
    main()
