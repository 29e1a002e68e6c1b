"""f1tenth's tracks on the plant: a map in ROS map_server's format (an image and its YAML, as f1tenth
keeps its tracks) made into a world of walls, and f1tenth's centre line and race line CSVs read.

The map (map_server's rules, image_loader.cpp): the YAML names the `image` (relative to the YAML's
folder), its `resolution` (m a pixel), the `origin` (x, y, yaw of the image's lower-left corner;
yaw turns the map about it), `occupied_thresh`, `free_thresh`, `negate` and an optional `mode`
(trinary, the default, or scale). A pixel's channels are averaged (in trinary mode alpha too, as
map_server does), p = (255 - average) / 255 (average / 255 when negate), and the cell is occupied
when p > occupied_thresh. The image's top row is the map's largest y. Occupied cells become static
walls WALL_HEIGHT high, merged into few boxes (occupied_boxes); free and unknown cells are floor.

f1tenth's lines (f1tenth_gym v1.0's Raceline, f1tenth_racetracks): a centre line CSV
`# x_m, y_m, w_tr_right_m, w_tr_left_m` (',' separated) and a race line CSV
`# s_m; x_m; y_m; psi_rad; kappa_radpm; vx_mps; ax_mps2` (';' separated), both closed loops in the
direction of racing, beside the map as <name>_centerline.csv and <name>_raceline.csv, where the map
is <name>_map.yaml (or <name>.yaml).

PGM and PPM images are read here; PNG and the rest through Pillow (Debian's python3-pil).
"""
import hashlib
import math
import os
import tempfile

import numpy as np
import yaml

from tianracer_description.racing.track import track_world_sdf

WALL_HEIGHT = 0.3  # m: above the lidar (about 9 cm up on the Tianracer) and the car's body
WALL_RGBA = '0.8 0.1 0.1 1'  # the race tracks' red
CONVERTER_VERSION = 1  # part of a converted world's cache key: bump when the world written changes
REQUIRED_KEYS = ('image', 'resolution', 'origin', 'negate', 'occupied_thresh', 'free_thresh')
CENTERLINE_HEADER = '# x_m, y_m, w_tr_right_m, w_tr_left_m'
RACELINE_HEADER = '# s_m; x_m; y_m; psi_rad; kappa_radpm; vx_mps; ax_mps2'


class MapSpec:
    """A map's YAML as map_server reads it: image (an absolute path), resolution, origin (x, y, yaw),
    negate, occupied_thresh, free_thresh, mode; path: the YAML's own."""

    def __init__(self, path):
        self.path = os.path.abspath(path)
        if not os.path.isfile(self.path):
            raise FileNotFoundError('no map at %s: pass map= the YAML of a map in map_server\'s format '
                                    '(image, resolution, origin, negate, occupied_thresh, free_thresh)' % path)
        with open(self.path) as f:
            try:
                spec = yaml.safe_load(f)
            except yaml.YAMLError as e:
                raise ValueError('map %s is not YAML: %s' % (path, e)) from None
        if not isinstance(spec, dict):
            raise ValueError('map %s is not a YAML mapping of map_server\'s keys (%s)' % (path, ', '.join(REQUIRED_KEYS)))
        missing = [key for key in REQUIRED_KEYS if key not in spec]
        if missing:
            raise ValueError('map %s lacks %s: map_server needs %s' % (path, ', '.join(missing), ', '.join(REQUIRED_KEYS)))
        image = str(spec['image'])
        self.image = image if os.path.isabs(image) else os.path.join(os.path.dirname(self.path), image)
        self.resolution = self._number(spec, 'resolution')
        if not self.resolution > 0:
            raise ValueError('map %s: resolution is metres a pixel, above 0; got %r' % (path, spec['resolution']))
        origin = spec['origin']
        if not (isinstance(origin, (list, tuple)) and len(origin) == 3):
            raise ValueError('map %s: origin is [x, y, yaw]; got %r' % (path, origin))
        self.origin = tuple(float(v) for v in origin)
        self.negate = bool(int(spec['negate']))
        self.occupied_thresh = self._number(spec, 'occupied_thresh')
        self.free_thresh = self._number(spec, 'free_thresh')
        self.mode = str(spec.get('mode', 'trinary')).lower()
        if self.mode not in ('trinary', 'scale'):
            raise ValueError('map %s: mode %r is not read here: its pixels would be occupancy values, not a picture; '
                             'use mode: trinary or scale' % (path, spec['mode']))
        name = os.path.splitext(os.path.basename(self.path))[0]
        self.name = name[:-len('_map')] if name.endswith('_map') else name  # f1tenth's <name>_map.yaml

    def _number(self, spec, key):
        try:
            return float(spec[key])
        except (TypeError, ValueError):
            raise ValueError('map %s: %s is a number; got %r' % (self.path, key, spec[key])) from None


def read_pnm(path):
    """A binary PGM (P5) or PPM (P6) image as an array (rows, columns[, 3]) of 0-255, values scaled
    from the file's maxval as SDL_image (map_server's loader) scales them."""
    with open(path, 'rb') as f:
        data = f.read()
    magic = data[:2]
    if magic not in (b'P5', b'P6'):
        raise ValueError('%s is not a binary PGM (P5) or PPM (P6) image' % path)
    fields, position = [], 2
    while len(fields) < 3:  # width, height, maxval, with '#' comments between them
        while position < len(data) and data[position:position + 1].isspace():
            position += 1
        if data[position:position + 1] == b'#':
            position = data.index(b'\n', position) + 1
            continue
        end = position
        while end < len(data) and data[end:end + 1].isdigit():
            end += 1
        if end == position:
            raise ValueError('%s: its PNM header is cut short' % path)
        fields.append(int(data[position:end]))
        position = end
    width, height, maxval = fields
    position += 1  # the one whitespace character before the raster
    channels = 3 if magic == b'P6' else 1
    dtype = np.dtype('>u2') if maxval > 255 else np.dtype(np.uint8)
    count = width * height * channels
    if len(data) - position < count * dtype.itemsize:
        raise ValueError('%s: %d x %d pixels declared, fewer stored' % (path, width, height))
    raster = np.frombuffer(data, dtype, count, position).astype(np.float64)
    if maxval != 255:
        raster = np.round(raster * 255.0 / maxval)
    shape = (height, width, channels) if channels > 1 else (height, width)
    return raster.astype(np.uint8).reshape(shape)


def read_image(path):
    """A map's image as an array (rows, columns[, channels]) of 0-255, top row first."""
    if not os.path.isfile(path):
        raise FileNotFoundError('no map image at %s: the YAML\'s image names it, relative to the YAML\'s folder' % path)
    with open(path, 'rb') as f:
        magic = f.read(2)
    if magic in (b'P5', b'P6'):
        return read_pnm(path)
    try:
        from PIL import Image
    except ImportError:
        raise ImportError('reading %s needs Pillow (apt install python3-pil), or save the map as a PGM' % path) from None
    with Image.open(path) as image:
        if image.mode == 'P':  # a palette: its colours, as the picture shows them
            image = image.convert('RGBA' if 'transparency' in image.info else 'RGB')
        elif image.mode == 'LA':
            image = image.convert('RGBA')
        elif image.mode == '1':
            image = image.convert('L')
        elif image.mode.startswith('I'):  # 16-bit grey: its high byte, as SDL_image keeps 8 bits
            return (np.asarray(image, np.int64) >> 8).clip(0, 255).astype(np.uint8)
        elif image.mode not in ('L', 'RGB', 'RGBA'):
            image = image.convert('RGB')
        return np.asarray(image, np.uint8)


def occupied_cells(pixels, spec):
    """Which pixels map_server reads as occupied (a bool array shaped as the image, top row first):
    the channels' mean (alpha left out in scale mode only), p = (255 - mean) / 255, or mean / 255
    when negate, and occupied where p > occupied_thresh."""
    pixels = np.asarray(pixels, np.float64)
    if pixels.ndim == 3:
        channels = pixels.shape[2]
        if spec.mode == 'scale' and channels in (2, 4):
            channels -= 1  # the alpha channel
        mean = pixels[:, :, :channels].mean(axis=2)
    else:
        mean = pixels
    p = mean / 255.0 if spec.negate else (255.0 - mean) / 255.0
    return p > spec.occupied_thresh


def row_rectangles(occupied):
    """Occupied cells as disjoint rectangles (row, column, rows, columns): each row's runs, a run
    merged with the one below while they span the same columns."""
    rectangles, open_runs = [], {}  # (first column, end column) -> first row
    height = occupied.shape[0]
    for r in range(height + 1):
        runs = set()
        if r < height:
            edges = np.flatnonzero(np.diff(np.concatenate([[0], occupied[r].astype(np.int8), [0]])))
            runs = set(zip(edges[0::2].tolist(), edges[1::2].tolist()))
        for run in list(open_runs):
            if run not in runs:
                first = open_runs.pop(run)
                rectangles.append((first, run[0], r - first, run[1] - run[0]))
        for run in runs:
            open_runs.setdefault(run, r)
    return rectangles


def occupied_boxes(occupied):
    """Few rectangles (row, column, rows, columns) covering exactly the occupied cells: runs along
    the rows merged downwards, or runs down the columns merged rightwards, whichever gives fewer."""
    by_rows = row_rectangles(occupied)
    by_columns = [(r, c, h, w) for c, r, w, h in row_rectangles(occupied.T)]
    return sorted(by_rows if len(by_rows) <= len(by_columns) else by_columns)


def box_poses(spec, rows, rectangles):
    """Each rectangle's centre (x, y) in the world and its size (x, y) in metres, in the map's frame
    (turned by the origin's yaw): image row 0 is the map's top, its largest y."""
    res = spec.resolution
    x0, y0, yaw = spec.origin
    c, s = math.cos(yaw), math.sin(yaw)
    for r, col, h, w in rectangles:
        u, v = (col + w / 2.0) * res, (rows - r - h / 2.0) * res
        yield (x0 + c * u - s * v, y0 + s * u + c * v), (w * res, h * res)


def map_world_sdf(spec, wall_height=WALL_HEIGHT):
    """The world SDF of a map (a MapSpec): the ground plane, the sun, 1 ms physics and one static
    model of the occupied cells' boxes, wall_height high. (text, number of boxes)."""
    occupied = occupied_cells(read_image(spec.image), spec)
    rectangles = occupied_boxes(occupied)
    yaw = spec.origin[2]
    parts = []
    for k, ((x, y), (sx, sy)) in enumerate(box_poses(spec, occupied.shape[0], rectangles)):
        geometry = '<geometry><box><size>%.6f %.6f %.6f</size></box></geometry>' % (sx, sy, wall_height)
        parts.append(f"""        <collision name="wall_{k}">
          <pose>{x:.6f} {y:.6f} {wall_height / 2:.6f} 0 0 {yaw:.6f}</pose>
          {geometry}
        </collision>
        <visual name="wall_{k}">
          <pose>{x:.6f} {y:.6f} {wall_height / 2:.6f} 0 0 {yaw:.6f}</pose>
          {geometry}
          <material><ambient>{WALL_RGBA}</ambient><diffuse>{WALL_RGBA}</diffuse></material>
        </visual>
""")
    walls = ('    <model name="walls">\n      <static>true</static>\n      <link name="link">\n' + ''.join(parts) +
             '      </link>\n    </model>\n')
    comment = ('Made from the map %s by tianracer_description.racing.f1tenth_map: its occupied cells\n     as %d '
               'static boxes %s m high.' % (spec.path, len(rectangles), wall_height))
    text = track_world_sdf(spec.name, comment, [walls])
    return text, len(rectangles)


def cache_folder():
    """Where converted maps' worlds are kept: $XDG_CACHE_HOME (or ~/.cache)/tianracer_description/maps,
    or the temporary folder where that cannot be written."""
    base = os.environ.get('XDG_CACHE_HOME') or os.path.join(os.path.expanduser('~'), '.cache')
    folder = os.path.join(base, 'tianracer_description', 'maps')
    try:
        os.makedirs(folder, exist_ok=True)
        if os.access(folder, os.W_OK):
            return folder
    except OSError:
        pass
    folder = os.path.join(tempfile.gettempdir(), 'tianracer_description_maps')
    os.makedirs(folder, exist_ok=True)
    return folder


def map_world_file(map_yaml, wall_height=WALL_HEIGHT):
    """The world file of a map: converted once and kept in cache_folder() under a name from the
    YAML's and image's bytes, so every environment (and every process) of the same map reads the
    same file."""
    spec = MapSpec(map_yaml)
    digest = hashlib.sha1(('%d %r\n' % (CONVERTER_VERSION, float(wall_height))).encode())
    with open(spec.path, 'rb') as f:
        digest.update(f.read())
    if not os.path.isfile(spec.image):
        read_image(spec.image)  # the error naming it
    with open(spec.image, 'rb') as f:
        digest.update(f.read())
    path = os.path.join(cache_folder(), '%s-%s.world' % (spec.name, digest.hexdigest()[:16]))
    if not os.path.isfile(path):
        text, _ = map_world_sdf(spec, wall_height)
        partial = '%s.%d.partial' % (path, os.getpid())
        with open(partial, 'w') as f:
            f.write(text)
        os.replace(partial, path)  # whole or absent, for processes converting the same map at once
    return path


def _data_rows(path, delimiter, columns, header):
    if not os.path.isfile(path):
        raise FileNotFoundError('no line at %s' % path)
    try:
        rows = np.loadtxt(path, delimiter=delimiter, comments='#', ndmin=2)
    except ValueError as e:
        raise ValueError('%s is not f1tenth\'s %s (columns separated by %r): %s' % (path, header, delimiter, e)) from None
    if rows.shape[1] not in columns or len(rows) < 3:
        raise ValueError('%s has %d columns and %d rows; f1tenth\'s %s has %s columns and a closed loop of 3 rows '
                         'or more' % (path, rows.shape[1], len(rows), header, ' or '.join(map(str, columns))))
    return rows


def _open_loop(points):
    """The points of a closed loop without a last point repeating the first (a zero-length segment)."""
    if len(points) > 3 and np.hypot(*(points[-1, :2] - points[0, :2])) < 1e-6:
        return points[:-1]
    return points


class Raceline:
    """A race line: x, y (m), and where its file gives them s, psi, kappa, vx (m/s), ax; the speeds
    of a centre line are None."""

    def __init__(self, xs, ys, vxs=None, path=None):
        self.xs, self.ys = np.asarray(xs, np.float64), np.asarray(ys, np.float64)
        self.vxs = None if vxs is None else np.asarray(vxs, np.float64)
        self.path = path

    @property
    def points(self):
        return np.column_stack([self.xs, self.ys])


def read_centerline(path):
    """f1tenth's centre line CSV (x_m, y_m, w_tr_right_m, w_tr_left_m; ',' separated) as a Raceline
    without speeds; the track widths are not used (the walls are the map's)."""
    rows = _open_loop(_data_rows(path, ',', (2, 4), CENTERLINE_HEADER))
    return Raceline(rows[:, 0], rows[:, 1], path=path)


def read_raceline(path):
    """f1tenth's race line CSV (s_m; x_m; y_m; psi_rad; kappa_radpm; vx_mps; ax_mps2) as a Raceline."""
    rows = _open_loop(_data_rows(path, ';', (7,), RACELINE_HEADER))
    return Raceline(rows[:, 1], rows[:, 2], rows[:, 5], path=path)


def read_line(path):
    """A centre line or a race line CSV of f1tenth's, told apart by its separator."""
    if not os.path.isfile(path):
        raise FileNotFoundError('no line at %s: pass f1tenth\'s %s or %s CSV' % (path, CENTERLINE_HEADER, RACELINE_HEADER))
    with open(path) as f:
        data = [line for line in f if line.strip() and not line.lstrip().startswith('#')]
    return read_raceline(path) if data and ';' in data[0] else read_centerline(path)


def lines_beside(map_yaml):
    """f1tenth's centre line and race line files beside a map, by f1tenth's naming: for
    <folder>/<name>_map.yaml (or <name>.yaml), <name>_centerline.csv and <name>_raceline.csv (then
    <name>_map_centerline.csv ...). (centre line path or None, race line path or None)."""
    spec_name = os.path.splitext(os.path.basename(map_yaml))[0]
    folder = os.path.dirname(os.path.abspath(map_yaml))
    names = [spec_name[:-len('_map')], spec_name] if spec_name.endswith('_map') else [spec_name]
    found = []
    for kind in ('centerline', 'raceline'):
        candidates = [os.path.join(folder, '%s_%s.csv' % (name, kind)) for name in names]
        found.append(next((c for c in candidates if os.path.isfile(c)), None))
    return tuple(found)


class MapTrack:
    """A map of f1tenth's made ready to race: its world file (converted), its centre line (for the
    progress and the reward) and its race line (for waypoint followers; the centre line where the
    map has none). centerline= and raceline= override what lies beside the map: a path to f1tenth's
    CSV, or (x, y) points."""

    def __init__(self, map_yaml, centerline=None, raceline=None, wall_height=WALL_HEIGHT):
        self.spec = MapSpec(map_yaml)
        self.world_file = map_world_file(self.spec.path, wall_height)
        beside_centerline, beside_raceline = lines_beside(self.spec.path)
        self.raceline = self._line(raceline if raceline is not None else beside_raceline)
        centre = self._line(centerline if centerline is not None else beside_centerline)
        if centre is None and self.raceline is None:
            raise FileNotFoundError(
                'map %s has no centre line or race line beside it: write %s (%s) or %s (%s) there, or pass '
                'centerline= a CSV or (x, y) points in the direction of racing'
                % (self.spec.path, os.path.join(os.path.dirname(self.spec.path), self.spec.name + '_centerline.csv'),
                   CENTERLINE_HEADER, os.path.join(os.path.dirname(self.spec.path), self.spec.name + '_raceline.csv'),
                   RACELINE_HEADER))
        self.centerline = centre if centre is not None else self.raceline  # f1tenth_gym's fallback, the other way
        if self.raceline is None:
            self.raceline = self.centerline

    @staticmethod
    def _line(line):
        if line is None or isinstance(line, Raceline):
            return line
        if isinstance(line, (str, os.PathLike)):
            return read_line(os.fspath(line))
        points = np.asarray(line, np.float64)
        return Raceline(points[:, 0], points[:, 1])
