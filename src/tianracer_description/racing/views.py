"""What the racing environments render: the chase camera behind a car (the plant's OpenGL cameras,
car.py) or a top-down map of the track drawn here with numpy, as rgb_array frames or in a window
(render_mode "human", a Tk window).

The top-down view: the floor, the walls (the world's static collision shapes that rise above the
floor, seen from above: boxes, cylinders, spheres, capsules, ellipsoids; meshes are left out), the
centre line and, on a map of f1tenth's, its race line, rasterized once per track into a background;
then each frame the cars' latest lidar hits and the cars themselves, each the rectangle around its
wheels at its pose, its front third yellow. North (+y) is up, +x to the right, TOP_DOWN_SCALE metres
a pixel (coarser for a track that would be wider or taller than TOP_DOWN_MAX_SIZE pixels). A frame
costs a copy of the background and a few small fills: about a millisecond.
"""
import math
import os
import time

import numpy as np

from tianracer_description.racing.car import CHASE_CAMERA, CHASE_CAMERA_SIZE
from tianracer_description.urdf_geometry import DEFAULT_JOINTS, UrdfModel

RENDER_MODES = ['human', 'rgb_array']
VIEWS = ('chase', 'top_down')
TOP_DOWN_SCALE = 0.025  # m a pixel: a 5 cm wall is 2 pixels, the Tianracer about 17 x 10
TOP_DOWN_MAX_SIZE = 1280  # px: the most a side of the top-down image takes at TOP_DOWN_SCALE
TOP_DOWN_MARGIN = 0.3  # m of floor around the walls and lines
TOP_DOWN_ALIGN = 16  # px: both sides a multiple of it, as video encoders want (yuv420p, macroblocks)
FLOOR_CLEARANCE = 0.01  # m: a static shape whose top is this low or lower is floor, not a wall

# Colours (RGB, uint8): what test_race_views.py looks for and docs/racing.md lists.
FLOOR = (245, 245, 245)
WALL = (204, 26, 26)  # the race tracks' walls' red (f1tenth_map.WALL_RGBA)
CENTERLINE = (160, 160, 160)
RACELINE = (30, 110, 230)
SCAN = (255, 140, 0)
NOSE = (255, 210, 0)
CAR_COLOURS = [(30, 30, 30), (0, 150, 70), (140, 40, 190), (0, 150, 170), (150, 90, 20), (220, 0, 120)]
NOSE_SHARE = 1.0 / 3.0  # of the car's length, at its front, drawn NOSE: which way it heads


def check_render(render_mode, view, modes=RENDER_MODES, views=VIEWS):
    """ValueError naming the offending argument unless render_mode and view are ones an environment
    draws; for "human", the errors of require_display() at once, rather than a hang later."""
    if render_mode is not None and render_mode not in modes:
        raise ValueError('render_mode is None or one of %s; got %r' % (', '.join(repr(m) for m in modes), render_mode))
    if view not in views:
        raise ValueError('view is what render() draws, one of %s; got %r' % (', '.join(repr(v) for v in views), view))
    if render_mode == 'human':
        require_display()


def require_display():
    """render_mode "human" shows frames in a Tk window: ImportError naming Debian's package without
    tkinter, RuntimeError without a display (rather than a window that never opens)."""
    try:
        import tkinter  # noqa: F401
    except ImportError:
        raise ImportError("render_mode='human' shows frames in a Tk window and tkinter is missing: install Debian's "
                          "python3-tk (tools/setup.sh does), or pass render_mode='rgb_array' and keep the frames") from None
    if not os.environ.get('DISPLAY'):
        raise RuntimeError("render_mode='human' opens a window and there is no display ($DISPLAY is not set): run it "
                           "on a desktop, under `xvfb-run -a`, or pass render_mode='rgb_array' and keep the frames "
                           "(gymnasium.wrappers.RecordVideo makes a video of them)")


def frames_per_second(control_period):
    """metadata['render_fps']: a frame a step, so that a video of the frames plays in simulated time
    (as Gymnasium's MuJoCo environments set it, 1 / dt)."""
    return max(1, int(round(1.0 / control_period)))


def yaw_of(quaternion):
    """The heading (rad) of an x y z w rotation: where it turns the x axis, seen from above."""
    x, y, z, w = quaternion
    return math.atan2(2.0 * (w * z + x * y), 1.0 - 2.0 * (y * y + z * z))


def _rotation(quaternion):
    x, y, z, w = quaternion
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
                     [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
                     [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]])


def convex_hull(points):
    """The convex hull of 2-D points, counter-clockwise (Andrew's monotone chain)."""
    pts = sorted(set(map(tuple, np.round(np.asarray(points, np.float64), 12))))
    if len(pts) < 3:
        return np.array(pts)

    def half(sequence):
        chain = []
        for p in sequence:
            while len(chain) >= 2 and ((chain[-1][0] - chain[-2][0]) * (p[1] - chain[-2][1]) -
                                       (chain[-1][1] - chain[-2][1]) * (p[0] - chain[-2][0])) <= 0:
                chain.pop()
            chain.append(p)
        return chain

    lower, upper = half(pts), half(reversed(pts))
    return np.array(lower[:-1] + upper[:-1])


def _circle(x, y, radius, sides=16):
    angles = np.arange(sides) * (2 * math.pi / sides)
    return np.stack([x + radius * np.cos(angles), y + radius * np.sin(angles)], axis=1)


def wall_outlines(static_collisions, floor_clearance=FLOOR_CLEARANCE):
    """The walls seen from above: a convex outline (an (N, 2) array of x, y, counter-clockwise) for
    each static collision shape of World.static_collisions() whose top is above floor_clearance.
    Boxes exactly (their 8 corners projected); cylinders, spheres, capsules and ellipsoids as the
    circle of their largest radius about their centre (upright, as a track's posts and cones stand);
    planes are the floor and meshes are left out."""
    outlines = []
    for shape in static_collisions:
        kind, pose = shape['kind'], np.asarray(shape['pose'], np.float64)
        centre = pose[:3]
        if kind == 'box':
            half = np.asarray(shape['size'], np.float64) / 2.0
            signs = np.array([[sx, sy, sz] for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)], np.float64)
            corners = (signs * half) @ _rotation(pose[3:]).T + centre
            if corners[:, 2].max() > floor_clearance:
                outlines.append(convex_hull(corners[:, :2]))
        elif kind in ('cylinder', 'sphere', 'capsule', 'ellipsoid'):
            radius = max(shape['radii'][:2]) if kind == 'ellipsoid' else shape['radius']
            reach = {'cylinder': shape.get('length', 0.0) / 2.0, 'sphere': radius,
                     'capsule': shape.get('length', 0.0) / 2.0 + radius,
                     'ellipsoid': max(shape.get('radii', [0.0])[-1:])}[kind]
            if centre[2] + reach > floor_clearance:
                outlines.append(_circle(centre[0], centre[1], radius))
    return outlines


def car_footprint(urdf, joints=None):
    """The car seen from above: the corners (4 x 2, counter-clockwise from rear right) of the rectangle
    around its four wheels, in its root link's frame: the wheel centres (the URDF's joints at rest)
    and a wheel's radius fore and aft, half its width to the sides."""
    names = dict(DEFAULT_JOINTS, **(joints or {}))
    model = UrdfModel(urdf)
    wheels = [names[role] for role in ('left_rear_wheel', 'right_rear_wheel', 'left_front_wheel', 'right_front_wheel')]
    centres = np.array([model.joint_position(joint)[:2] for joint in wheels])
    radius = model.wheel_radius(names['left_rear_wheel'])
    width = 0.0
    link = model.links[model.joint(names['left_rear_wheel']).find('child').get('link')]
    for cylinder in link.findall('collision/geometry/cylinder'):
        width = float(cylinder.get('length', 0.0))
    rear, front = centres[:, 0].min() - radius, centres[:, 0].max() + radius
    right, left = centres[:, 1].min() - width / 2.0, centres[:, 1].max() + width / 2.0
    return np.array([(rear, right), (front, right), (front, left), (rear, left)])


def lidar_mount(urdf, lidar):
    """(x, y, yaw) of the lidar named `lidar` in the car's root link's frame: its link's fixed joints
    chained from the root, and the sensor's own <pose>; ValueError when the URDF has no such sensor."""
    model = UrdfModel(urdf)
    for gazebo in model.root.findall('gazebo'):
        for sensor in gazebo.findall('sensor'):
            if sensor.get('name') != lidar:
                continue
            link = gazebo.get('reference')
            transform = np.eye(4)
            if link != model.root_link():
                joint = next(j for j in model.joints.values() if j.find('child').get('link') == link)
                transform = model.joint_frame(joint.get('name'))
            yaw = math.atan2(transform[1, 0], transform[0, 0])
            x, y = transform[0, 3], transform[1, 3]
            pose = sensor.findtext('pose')
            if pose:
                px, py, _, _, _, pyaw = [float(v) for v in pose.split()]
                x, y = x + math.cos(yaw) * px - math.sin(yaw) * py, y + math.sin(yaw) * px + math.cos(yaw) * py
                yaw += pyaw
            return x, y, yaw
    raise ValueError('the car\'s URDF has no sensor named %r in a <gazebo reference> block: pass the lidar\'s '
                     'name' % (lidar,))


def _transform(points, x, y, yaw):
    c, s = math.cos(yaw), math.sin(yaw)
    points = np.asarray(points, np.float64)
    return np.stack([x + c * points[:, 0] - s * points[:, 1], y + s * points[:, 0] + c * points[:, 1]], axis=1)


class TopDownView:
    """A track seen from above at a fixed scale: its background (floor, walls, lines) drawn once, and
    frames of cars on it (see the module's text). pixel() says where a point of the world is drawn."""

    def __init__(self, static_collisions, centerline, raceline=None, scale=None, margin=TOP_DOWN_MARGIN):
        walls = wall_outlines(static_collisions)
        lines = [np.asarray(centerline, np.float64)] + ([] if raceline is None else [np.asarray(raceline, np.float64)])
        everything = np.concatenate(walls + lines)
        low, high = everything.min(axis=0) - margin, everything.max(axis=0) + margin
        if scale is None:
            scale = max(TOP_DOWN_SCALE, float((high - low).max()) / TOP_DOWN_MAX_SIZE)
        if not (math.isfinite(scale) and scale > 0):
            raise ValueError('the top-down scale is metres a pixel, above 0; got %r' % (scale,))
        self.scale = float(scale)
        size = np.ceil((high - low) / self.scale / TOP_DOWN_ALIGN).astype(int) * TOP_DOWN_ALIGN
        centre = (low + high) / 2.0
        self.width, self.height = int(size[0]), int(size[1])
        # the image's left edge and top edge in the world, the track centred in it
        self.left = centre[0] - self.width * self.scale / 2.0
        self.top = centre[1] + self.height * self.scale / 2.0
        self.background = np.empty((self.height, self.width, 3), np.uint8)
        self.background[:] = FLOOR
        self.polyline(self.background, centerline, CENTERLINE, closed=True)
        if raceline is not None:
            self.polyline(self.background, raceline, RACELINE, closed=True)
        for outline in walls:  # last: a line never hides a wall
            self.polygon(self.background, outline, WALL)
            self.polyline(self.background, outline, WALL, closed=True)  # a wall thinner than a pixel shows too
        self.background.flags.writeable = False

    def columns_rows(self, points):
        """Points (N x 2, x y in the world) as image coordinates (column, row; pixel (r, c) spans
        [c, c + 1) x [r, r + 1))."""
        points = np.asarray(points, np.float64).reshape(-1, 2)
        return (points[:, 0] - self.left) / self.scale, (self.top - points[:, 1]) / self.scale

    def pixel(self, x, y):
        """(row, column) of the pixel the world's point (x, y) falls in (perhaps outside the image)."""
        columns, rows = self.columns_rows([(x, y)])
        return int(math.floor(rows[0])), int(math.floor(columns[0]))

    def polygon(self, image, outline, colour):
        """Fills the convex outline (N x 2, world) on `image`: the pixels whose centres are inside."""
        columns, rows = self.columns_rows(outline)
        c0, c1 = max(int(math.floor(columns.min())), 0), min(int(math.ceil(columns.max())), self.width)
        r0, r1 = max(int(math.floor(rows.min())), 0), min(int(math.ceil(rows.max())), self.height)
        if c0 >= c1 or r0 >= r1:
            return
        cc, rr = np.meshgrid(np.arange(c0, c1) + 0.5, np.arange(r0, r1) + 0.5)
        # rows grow downwards: the world's counter-clockwise is clockwise here; either way, inside is
        # the side of every edge that the outline's own turning says
        x0, y0 = columns, rows
        x1, y1 = np.roll(columns, -1), np.roll(rows, -1)
        area = np.sum(x0 * y1 - x1 * y0)
        sign = 1.0 if area >= 0 else -1.0
        inside = np.ones(cc.shape, bool)
        for ax, ay, bx, by in zip(x0, y0, x1, y1):
            inside &= sign * ((bx - ax) * (rr - ay) - (by - ay) * (cc - ax)) >= 0
        image[r0:r1, c0:c1][inside] = colour

    def polyline(self, image, points, colour, closed=False):
        """Draws the line through `points` (N x 2, world) on `image`, a pixel wide: every pixel it
        passes through, sampled a third of a pixel apart."""
        columns, rows = self.columns_rows(points)
        if closed:
            columns, rows = np.append(columns, columns[0]), np.append(rows, rows[0])
        lengths = np.hypot(np.diff(columns), np.diff(rows))
        counts = np.ceil(lengths * 3).astype(int) + 1
        segment = np.repeat(np.arange(len(lengths)), counts)
        share = np.concatenate([np.linspace(0.0, 1.0, n) for n in counts]) if len(counts) else np.zeros(0)
        self.points(image, columns[segment] + share * np.diff(columns)[segment],
                    rows[segment] + share * np.diff(rows)[segment], colour)

    def points(self, image, columns, rows, colour, size=1):
        """Sets the size x size pixels at each (column, row) (image coordinates) that are in the image."""
        columns, rows = np.floor(columns).astype(np.int64), np.floor(rows).astype(np.int64)
        for dc in range(size):
            for dr in range(size):
                c, r = columns + dc, rows + dr
                keep = (c >= 0) & (c < self.width) & (r >= 0) & (r < self.height)
                image[r[keep], c[keep]] = colour

    def frame(self, cars):
        """A frame of the cars on the track: `cars` a list of dicts, each `pose` (x, y, yaw), `footprint`
        (car_footprint), and where it has scanned `scan` (the hits: N x 2, world)."""
        image = self.background.copy()
        for car in cars:
            if car.get('scan') is not None and len(car['scan']):
                columns, rows = self.columns_rows(car['scan'])
                self.points(image, columns - 0.5, rows - 0.5, SCAN, size=2)  # 2 x 2 pixels about each hit
        for index, car in enumerate(cars):
            corners = car['footprint']
            self.polygon(image, _transform(corners, *car['pose']), CAR_COLOURS[index % len(CAR_COLOURS)])
            rear, front = corners[:, 0].min(), corners[:, 0].max()
            nose = corners.copy()
            nose[:, 0] = np.maximum(nose[:, 0], front - NOSE_SHARE * (front - rear))
            self.polygon(image, _transform(nose, *car['pose']), NOSE)
        return image


def scan_hits(scan, x, y, yaw):
    """The scan's returns as world points (N x 2) for a lidar at (x, y) heading yaw; the rays that
    returned nothing (range_max or beyond, or not finite) left out."""
    ranges = np.asarray(scan['ranges'], np.float64)
    angles = yaw + scan['angle_min'] + scan['angle_increment'] * np.arange(len(ranges))
    hit = np.isfinite(ranges) & (ranges < scan['range_max']) & (ranges >= scan.get('range_min', 0.0))
    return np.stack([x + ranges[hit] * np.cos(angles[hit]), y + ranges[hit] * np.sin(angles[hit])], axis=1)


def tile(frames, columns=None):
    """Frames (H x W x 3 each, perhaps of different sizes) in one image, a grid of `columns` (about
    the square root of their number), row by row, black between them: what a window shows of a
    vector environment."""
    frames = [np.asarray(f, np.uint8) for f in frames]
    count = len(frames)
    columns = columns or int(math.ceil(math.sqrt(count)))
    rows = int(math.ceil(count / columns))
    height, width = max(f.shape[0] for f in frames), max(f.shape[1] for f in frames)
    image = np.zeros((rows * height, columns * width, 3), np.uint8)
    for k, f in enumerate(frames):
        r, c = divmod(k, columns)
        image[r * height:r * height + f.shape[0], c * width:c * width + f.shape[1]] = f
    return image


class Window:
    """render_mode "human": frames shown in a Tk window (tkinter, Python's own), opened at the first
    frame, shown no faster than `fps` (as Gymnasium's human modes pace themselves to render_fps). A
    closed window stays closed; the environment runs on."""

    def __init__(self, title, fps):
        self.title, self.period = title, 1.0 / fps
        self._root = self._label = self._photo = None
        self._shown = None  # when the last frame was shown (time.monotonic)
        self.closed = False

    def show(self, frame):
        if self.closed:
            return
        import tkinter
        height, width = frame.shape[:2]
        ppm = b'P6 %d %d 255\n' % (width, height) + np.ascontiguousarray(frame, np.uint8).tobytes()
        try:
            if self._root is None:
                self._root = tkinter.Tk()
                self._root.title(self.title)
                self._root.protocol('WM_DELETE_WINDOW', self.close)
                self._photo = tkinter.PhotoImage(master=self._root, data=ppm, format='PPM')
                self._label = tkinter.Label(self._root, image=self._photo)
                self._label.pack()
            else:
                self._photo.configure(data=ppm, format='PPM', width=width, height=height)
            if self._shown is not None:
                time.sleep(max(0.0, self._shown + self.period - time.monotonic()))
            self._root.update()
            self._shown = time.monotonic()
        except tkinter.TclError as e:
            if self.closed:
                return
            raise RuntimeError("render_mode='human' could not show a frame on display %r: %s"
                               % (os.environ.get('DISPLAY'), e)) from None

    def close(self):
        self.closed = True
        if self._root is not None:
            root, self._root = self._root, None
            root.destroy()


class RaceViews:
    """What one environment draws (its render_mode and view) of its RaceCars: each car's chase
    camera frame, the top-down frame of some of its cars, and the window of render_mode "human"."""

    def __init__(self, cars, render_mode, view, scale=None, title='Tianracer', fps=30):
        self.cars, self.render_mode, self.view, self.scale = cars, render_mode, view, scale
        self.window = Window(title, fps) if render_mode == 'human' else None
        self._top_down = None  # built at the first top-down frame, from the first world's walls
        self._footprint = self._mount = None

    @property
    def top_down(self):
        """The TopDownView of the track (its background drawn at the first call: a world is needed)."""
        if self._top_down is None:
            world = next(w for w in self.cars.worlds if w is not None)
            track = self.cars.track
            self._top_down = TopDownView(world.static_collisions(), track.centerline.points,
                                         track.raceline if track.map is not None else None, self.scale)
            self._footprint = car_footprint(self.cars.model.urdf)
            self._mount = lidar_mount(self.cars.model.urdf, self.cars.model.lidar)
        return self._top_down

    def chase_frame(self, i):
        """Car i's chase camera frame (black before its first)."""
        frame = self.cars.robots[i].image(CHASE_CAMERA)
        width, height = CHASE_CAMERA_SIZE
        return np.zeros((height, width, 3), np.uint8) if frame is None else np.array(frame['rgb'])

    def top_down_frame(self, indices):
        """The top-down frame of cars `indices` (of one world, or drawn on one track) on the track."""
        view = self.top_down
        drawn = []
        for i in indices:
            robot = self.cars.robots[i]
            pose = robot.base_pose()
            x, y, yaw = pose[0], pose[1], yaw_of(pose[3:])
            mx, my, myaw = self._mount
            c, s = math.cos(yaw), math.sin(yaw)
            scan = robot.scan(self.cars.model.lidar)
            hits = None if scan is None else scan_hits(scan, x + c * mx - s * my, y + s * mx + c * my, yaw + myaw)
            drawn.append({'pose': (x, y, yaw), 'footprint': self._footprint, 'scan': hits})
        return view.frame(drawn)

    def frame(self, i):
        """Car i's frame in the chosen view, or None before it is placed."""
        if self.cars.robots[i] is None:
            return None
        return self.chase_frame(i) if self.view == 'chase' else self.top_down_frame([i])

    def show(self, frame):
        """render()'s answer: the frame, or None after showing it in the window."""
        if self.window is None or frame is None:
            return frame
        self.window.show(frame)
        return None

    def close(self):
        if self.window is not None:
            self.window.close()
