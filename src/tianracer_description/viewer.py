"""The browser view of the plant's world, where Gazebo has gzclient (and gzweb for a browser).

An aiohttp server (one asyncio loop) on a port, loopback unless asked, serves the page (web/index.html
and the bundle `make build` makes of web/src/viewer.js with three.js) and one WebSocket per page:
- the scene: what the node publishes, latched, on /gazebo/scene (every visual of the world and of each
  robot's links, the sun, the ambient light, the background; again whenever robots come or go);
- the links' poses from /gazebo/scene_link_states (the node's link_states at 30 Hz of simulated
  time; link_states itself comes every step) at `rate` Hz at the most, with the sim time of /clock,
  subscribed only while a page is open: with none, the plant publishes nothing for it;
- the status twice a second: sim time, real time factor (over the last second of /clock), paused;
- the page's buttons: play, pause, reset world, reset simulation (gazebo_ros's services), step (that
  many physics iterations while paused, on the plant's /gazebo/step_physics: gzclient's step), and
  a model the page moved or turned with the mouse put there by /gazebo/set_model_state;
- keyboard driving: teleop.py's keys (its tables, sent to the page) held in the page become a
  command at 10 Hz on a topic the page picks among those a node subscribes to with
  geometry_msgs/Twist or ackermann_msgs/AckermannDriveStamped; when the page stops sending for the
  converter's 0.2 s, or goes away, one zero command and nothing more (cmdvel2gazebo.py's dead man's
  rule, for drives that have none);
- overlays: a sensor_msgs/Image, sensor_msgs/LaserScan or gazebo_msgs/ContactsState topic a page
  turns on is subscribed while some page wants it, and its messages go to those pages OVERLAY_RATE a
  second at the most: images as JPEG (depth as grey, near dark, far light, nothing black), scans as
  their ranges (the page draws the hit points in the link named by the scan's frame), contacts as
  their points and normals in the world (the plant's /gazebo/scene_contacts has every contact of
  the world, as gzclient's contact view; gazebo_ros_bumper's topics a sensor's);
- the meshes' files, and the files beside them that their materials name (textures), and nothing
  else: only below the folders of the meshes the scene names.
rospy's callbacks run on its threads; they hand what they got to the loop. Service calls run on the
loop's executor threads.
"""
import asyncio
import base64
import collections
import io
import importlib.util
import json
import os
import threading
import time

import numpy as np
import rosgraph
import rospy
from ackermann_msgs.msg import AckermannDriveStamped
from aiohttp import WSMsgType, web
from gazebo_msgs.msg import ContactsState, LinkStates, ModelState
from gazebo_msgs.srv import GetPhysicsProperties, SetModelState
from geometry_msgs.msg import Twist
from PIL import Image as PilImage
from rosgraph_msgs.msg import Clock
from sensor_msgs.msg import Image, LaserScan
from std_msgs.msg import String, UInt32
from std_srvs.srv import Empty

from tianracer_description.tianracer import PACKAGE

DEFAULT_PORT = 8080
DEFAULT_RATE = 30.0  # Hz: the poses a page gets at the most
STATUS_PERIOD = 0.5  # s
RTF_WINDOW = 1.0  # s of wall time the real time factor is measured over
# The page's buttons and the gazebo_ros services they call (std_srvs/Empty).
CONTROLS = {'play': 'unpause_physics', 'pause': 'pause_physics', 'reset_world': 'reset_world',
            'reset_simulation': 'reset_simulation'}
STEP_TOPIC = 'step_physics'  # the plant's, in the gazebo namespace: std_msgs/UInt32 iterations
MAX_STEP = 100000  # iterations a page may ask for at once
DRIVE_TYPES = {'geometry_msgs/Twist': Twist, 'ackermann_msgs/AckermannDriveStamped': AckermannDriveStamped}
DRIVE_PERIOD = 0.1  # s: 10 Hz, as cmdvel2gazebo.py publishes
DRIVE_TIMEOUT = 0.2  # s: cmdvel2gazebo.py's dead man's switch
OVERLAY_TYPES = {'sensor_msgs/Image': 'image', 'sensor_msgs/LaserScan': 'scan',
                 'gazebo_msgs/ContactsState': 'contacts'}
OVERLAY_RATE = 5.0  # Hz: an overlay's messages to a page at the most
JPEG_QUALITY = 80


def teleop_keys():
    """teleop.py's key tables, read from the script itself: {'move': {key: [speed, turn]}, 'scale': ...}."""
    path = os.path.join(PACKAGE, 'scripts', 'teleop.py')
    spec = importlib.util.spec_from_file_location('teleop_keys', path)
    teleop = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(teleop)  # its main() runs only as a script
    return {'move': teleop.moveBindings, 'scale': teleop.speedBindings}


def drive_topics(master):
    """{topic: type} of the topics some node subscribes to with a Twist or an AckermannDriveStamped."""
    _, subscribers, _ = master.getSystemState()
    types = dict(master.getTopicTypes())
    return {topic: types[topic] for topic, _ in subscribers if types.get(topic) in DRIVE_TYPES}



def overlay_topics(master):
    """{topic: 'image', 'scan' or 'contacts'} of the topics of OVERLAY_TYPES some node publishes."""
    publishers, _, _ = master.getSystemState()
    types = dict(master.getTopicTypes())
    return {topic: OVERLAY_TYPES[types[topic]] for topic, _ in publishers if types.get(topic) in OVERLAY_TYPES}


def jpeg_of(image):
    """A sensor_msgs/Image as JPEG bytes: rgb8, bgr8, rgba8, bgra8 and mono8 as they are; 32FC1 and
    16UC1 depths as grey from the nearest to the farthest value in the frame (none: black)."""
    rows = np.frombuffer(image.data, dtype=np.uint8).reshape(image.height, image.step)
    encoding = image.encoding.lower()
    channels = {'rgb8': 3, 'bgr8': 3, 'rgba8': 4, 'bgra8': 4, 'mono8': 1}
    if encoding in channels:
        n = channels[encoding]
        pixels = rows[:, :image.width * n].reshape(image.height, image.width, n)
        if encoding.startswith('bgr'):
            pixels = pixels[:, :, [2, 1, 0]]
        pixels = pixels[:, :, :3] if n > 1 else pixels[:, :, 0]
    elif encoding in ('32fc1', '16uc1'):
        dtype = np.dtype('<f4' if encoding == '32fc1' else '<u2').newbyteorder('>' if image.is_bigendian else '<')
        depth = rows[:, :image.width * dtype.itemsize].copy().view(dtype).reshape(image.height, image.width)
        depth = depth.astype(np.float64)
        seen = np.isfinite(depth) & (depth > 0)
        pixels = np.zeros(depth.shape, np.uint8)
        if seen.any():
            near, far = depth[seen].min(), depth[seen].max()
            pixels[seen] = np.round(55 + 200 * (depth[seen] - near) / max(far - near, 1e-9))
    else:
        raise ValueError('an image in %s, which the viewer does not show' % image.encoding)
    out = io.BytesIO()
    PilImage.fromarray(np.ascontiguousarray(pixels)).save(out, format='JPEG', quality=JPEG_QUALITY)
    return out.getvalue()


def drive_command(kind, speed, turn):
    """A Twist (linear.x, angular.z) or an AckermannDriveStamped (speed, steering_angle)."""
    if kind == 'geometry_msgs/Twist':
        command = Twist()
        command.linear.x, command.angular.z = speed, turn
    else:
        command = AckermannDriveStamped()
        command.header.stamp = rospy.Time.now()
        command.drive.speed, command.drive.steering_angle = speed, turn
    return command


def default_web_root():
    """The package's web/ folder: index.html, and dist/viewer.js once `make build` has run."""
    return os.path.join(PACKAGE, 'web')


def mesh_roots(scene):
    """The folders a page may read files below: each mesh's folder and the one above it (a Gazebo
    model keeps meshes/ and materials/textures/ side by side)."""
    roots = set()
    for visual in scene.get('visuals', []):
        if visual.get('kind') == 'mesh' and visual.get('mesh'):
            folder = os.path.dirname(os.path.realpath(visual['mesh']))
            roots.update({folder, os.path.dirname(folder)})
    return roots


def contacts_message(topic, contacts):
    """A page's contacts overlay: each contact point and its normal, [x y z nx ny nz], in the world."""
    points = []
    for state in contacts.states:
        for p, n in zip(state.contact_positions, state.contact_normals):
            points.append([round(v, 4) for v in (p.x, p.y, p.z, n.x, n.y, n.z)])
    return {'type': 'contacts', 'topic': topic, 'stamp': contacts.header.stamp.to_sec(), 'points': points}


def poses_message(link_states, sim_time):
    """The page's poses: {"type": "poses", "time": s, "links": {model::link: [x y z qx qy qz qw]}}."""
    links = {}
    for name, pose in zip(link_states.name, link_states.pose):
        p, q = pose.position, pose.orientation
        links[name] = [p.x, p.y, p.z, q.x, q.y, q.z, q.w]
    return json.dumps({'type': 'poses', 'time': sim_time, 'links': links})


class Viewer:
    def __init__(self, web_root=None, host='127.0.0.1', port=DEFAULT_PORT, rate=DEFAULT_RATE,
                 gazebo_namespace='/gazebo'):
        self.web_root = web_root or default_web_root()
        self.host, self.port, self.rate = host, port, rate
        self.namespace = gazebo_namespace.rstrip('/')
        self._scene = None
        self._scene_text = None
        self._roots = set()
        self._sim_time = 0.0
        self._clock_samples = collections.deque()  # (wall, sim) of /clock over the last RTF_WINDOW
        self._pages = set()
        self._link_states = None  # the subscriber, while a page is open
        self._last_poses = 0.0  # monotonic s of the last poses sent
        self._poses_waiting = None  # link states that arrived and wait for their turn
        self._lock = threading.Lock()
        self._loop = None
        self._drive_topics = {}
        self._keys = teleop_keys()
        self._publishers = {}  # topic: publisher, made on a page's first command for it
        self._step_publisher = None  # made when serving starts (rospy's node is up by then)
        self._driving = {}  # topic: (speed, turn, the page's last request, monotonic s)
        self._overlay_topics = {}  # topic: 'image' or 'scan', of those published
        self._overlays = {}  # topic: {'pages': set of pages, 'subscriber', 'last': monotonic s}

    # ------------------------------------------------------------------ ROS side (rospy's threads)

    def _on_scene(self, message):
        scene = json.loads(message.data)
        text = json.dumps({'type': 'scene', 'scene': scene})
        with self._lock:
            self._scene, self._scene_text, self._roots = scene, text, mesh_roots(scene)
        self._to_pages(text)

    def _on_clock(self, message):
        now = time.monotonic()
        self._sim_time = message.clock.to_sec()
        with self._lock:
            self._clock_samples.append((now, self._sim_time))
            while self._clock_samples and now - self._clock_samples[0][0] > RTF_WINDOW:
                self._clock_samples.popleft()

    def real_time_factor(self):
        """Simulated over wall seconds across the last RTF_WINDOW of /clock; 0 when it stands."""
        now = time.monotonic()
        with self._lock:
            samples = [s for s in self._clock_samples if now - s[0] <= RTF_WINDOW]
        if len(samples) < 2 or samples[-1][0] == samples[0][0]:
            return 0.0
        return (samples[-1][1] - samples[0][1]) / (now - samples[0][0])

    def _paused(self):
        """gazebo_ros's get_physics_properties' pause; None when the simulator does not answer."""
        try:
            name = self.namespace + '/get_physics_properties'
            rospy.wait_for_service(name, 1.0)
            return bool(rospy.ServiceProxy(name, GetPhysicsProperties)().pause)
        except (rospy.ROSException, rospy.ServiceException):
            return None

    def _set_model_pose(self, model, pose):
        """/gazebo/set_model_state: `model` at `pose` (x y z qx qy qz qw) in the world, at rest."""
        name = self.namespace + '/set_model_state'
        state = ModelState(model_name=model, reference_frame='world')
        p, q = state.pose.position, state.pose.orientation
        p.x, p.y, p.z, q.x, q.y, q.z, q.w = pose
        try:
            rospy.wait_for_service(name, 5.0)
            result = rospy.ServiceProxy(name, SetModelState)(state)
            if not result.success:
                rospy.logerr('viewer: %s %s: %s', name, model, result.status_message)
        except (rospy.ROSException, rospy.ServiceException) as error:
            rospy.logerr('viewer: %s: %s', name, error)

    def _control(self, action):
        name = self.namespace + '/' + CONTROLS[action]
        try:
            rospy.wait_for_service(name, 5.0)
            rospy.ServiceProxy(name, Empty)()
        except (rospy.ROSException, rospy.ServiceException) as error:
            rospy.logerr('viewer: %s: %s', name, error)

    def _on_link_states(self, message):
        """The latest link states go to the pages `rate` times a second at the most, the last of a burst
        too (a step of the paused world ends with one): what arrives too soon waits for its turn,
        replaced by anything newer."""
        with self._lock:
            waiting = self._poses_waiting is not None
            self._poses_waiting = message
        if not waiting and self._loop is not None:
            delay = max(0.0, self._last_poses + 1.0 / self.rate - time.monotonic())
            self._loop.call_soon_threadsafe(self._loop.call_later, delay, self._send_poses)

    def _send_poses(self):
        with self._lock:
            message, self._poses_waiting = self._poses_waiting, None
        self._last_poses = time.monotonic()
        self._send_all(poses_message(message, self._sim_time))

    def _due(self, topic):
        """Whether a message of an overlay's topic goes to its pages now (OVERLAY_RATE at the most)."""
        now = time.monotonic()
        with self._lock:
            overlay = self._overlays.get(topic)
            if overlay is None or now - overlay['last'] < 1.0 / OVERLAY_RATE:
                return False
            overlay['last'] = now
            return True

    def _on_image(self, topic, image):
        if not self._due(topic):
            return
        try:
            jpeg = jpeg_of(image)
        except ValueError as error:
            rospy.logwarn_throttle(10.0, 'viewer: %s: %s' % (topic, error))
            return
        self._to_overlay(topic, {'type': 'image', 'topic': topic, 'width': image.width, 'height': image.height,
                                 'stamp': image.header.stamp.to_sec(),
                                 'jpeg': base64.b64encode(jpeg).decode('ascii')})

    def _on_scan(self, topic, scan):
        if not self._due(topic):
            return
        ranges = [round(r, 4) if scan.range_min <= r <= scan.range_max else None for r in scan.ranges]
        self._to_overlay(topic, {'type': 'scan', 'topic': topic, 'frame': scan.header.frame_id,
                                 'angle_min': scan.angle_min, 'angle_increment': scan.angle_increment,
                                 'ranges': ranges})

    def _on_contacts(self, topic, contacts):
        if self._due(topic):
            self._to_overlay(topic, contacts_message(topic, contacts))

    def _to_overlay(self, topic, message):
        if self._loop is not None:
            self._loop.call_soon_threadsafe(self._send_overlay, topic, json.dumps(message))

    def _send_overlay(self, topic, text):
        overlay = self._overlays.get(topic)
        for page in list(overlay['pages'] if overlay else []):
            if not page.closed:
                asyncio.ensure_future(page.send_str(text))

    def _show(self, page, topic, on):
        """Turns a page's overlay of a topic on or off: subscribed while a page wants it."""
        with self._lock:
            overlay = self._overlays.get(topic)
            if on and overlay is None:
                kind, handler = {'image': (Image, self._on_image), 'scan': (LaserScan, self._on_scan),
                                 'contacts': (ContactsState, self._on_contacts)}[self._overlay_topics[topic]]
                overlay = self._overlays[topic] = {'pages': set(), 'last': 0.0, 'subscriber': rospy.Subscriber(
                    topic, kind, lambda message: handler(topic, message), queue_size=1, buff_size=2 ** 24)}
            if overlay is None:
                return
            (overlay['pages'].add if on else overlay['pages'].discard)(page)
            if not overlay['pages']:
                overlay['subscriber'].unregister()
                del self._overlays[topic]

    def _to_pages(self, text):
        if self._loop is not None:
            self._loop.call_soon_threadsafe(self._send_all, text)

    # ------------------------------------------------------------------ the loop

    def _send_all(self, text):
        for page in list(self._pages):
            if not page.closed:
                asyncio.ensure_future(page.send_str(text))

    def _follow_links(self, on):
        with self._lock:
            if on and self._link_states is None:
                self._link_states = rospy.Subscriber(self.namespace + '/scene_link_states', LinkStates,
                                                     self._on_link_states, queue_size=1)
            elif not on and self._link_states is not None:
                self._link_states.unregister()
                self._link_states = None

    async def _index(self, request):
        return web.FileResponse(os.path.join(self.web_root, 'index.html'))

    async def _bundle(self, request):
        path = os.path.join(self.web_root, 'dist', 'viewer.js')
        if not os.path.isfile(path):
            raise web.HTTPNotFound(text='viewer: %s is not there; run `make build`' % path)
        return web.FileResponse(path)

    async def _file(self, request):
        path = os.path.realpath('/' + request.match_info['path'])
        with self._lock:
            allowed = any(path.startswith(root + os.sep) for root in self._roots)
        if not allowed or not os.path.isfile(path):
            raise web.HTTPNotFound(text='viewer: %s is not a file of the scene' % path)
        return web.FileResponse(path)

    async def _page(self, request):
        # A page gone without a word (a closed laptop, a dropped tunnel) is found by the pings.
        page = web.WebSocketResponse(heartbeat=2.0)
        await page.prepare(request)
        self._pages.add(page)
        print('viewer: a page opened from %s (%d open)' % (request.remote, len(self._pages)), flush=True)
        self._follow_links(True)
        with self._lock:
            scene_text = self._scene_text
        await page.send_str(json.dumps({'type': 'keys', 'keys': self._keys}))
        if scene_text:
            await page.send_str(scene_text)
        try:
            async for message in page:
                if message.type == WSMsgType.ERROR:
                    break
                if message.type == WSMsgType.TEXT:
                    await self._from_page(page, message.data)
        finally:
            self._pages.discard(page)
            print('viewer: a page closed (%d open)' % len(self._pages), flush=True)
            for topic in list(self._overlays):
                self._show(page, topic, False)
            if not self._pages:
                self._follow_links(False)
        return page

    async def _from_page(self, page, text):
        """A page's request: {"type": "control", "action": one of CONTROLS}, {"type": "step",
        "iterations"}, {"type": "drive",
        "topic", "speed", "turn"}, {"type": "set_pose", "model", "pose": [x y z qx qy qz qw]} or
        {"type": "overlay", "topic", "on"}; anything else is ignored."""
        try:
            request = json.loads(text)
        except ValueError:
            return
        if not isinstance(request, dict):
            return
        if request.get('type') == 'control' and request.get('action') in CONTROLS:
            await asyncio.get_running_loop().run_in_executor(None, self._control, request['action'])
        elif request.get('type') == 'step':
            iterations = request.get('iterations')
            if type(iterations) is int and 0 < iterations <= MAX_STEP:  # noqa: E721  not a bool
                self._step_publisher.publish(UInt32(iterations))
        elif request.get('type') == 'drive' and request.get('topic') in self._drive_topics:
            try:
                speed, turn = float(request['speed']), float(request['turn'])
            except (KeyError, TypeError, ValueError):
                return
            if all(map(lambda v: abs(v) < 1e3, (speed, turn))):  # finite and sane; NaN fails too
                self._driving[request['topic']] = (speed, turn, time.monotonic())
        elif request.get('type') == 'set_pose' and request.get('model') in (self._scene or {}).get('robots', []):
            try:
                pose = [float(v) for v in request['pose']]
            except (KeyError, TypeError, ValueError):
                return
            if len(pose) == 7 and all(abs(v) < 1e6 for v in pose):  # finite; NaN fails too
                await asyncio.get_running_loop().run_in_executor(None, self._set_model_pose, request['model'], pose)
        elif request.get('type') == 'overlay' and request.get('topic') in self._overlay_topics:
            self._show(page, request['topic'], bool(request.get('on')))

    def _publisher(self, topic):
        if topic not in self._publishers:
            self._publishers[topic] = rospy.Publisher(topic, DRIVE_TYPES[self._drive_topics[topic]], queue_size=1)
        return self._publishers[topic]

    async def _drive(self):
        """The held commands at 10 Hz; a zero one, once, when a page stopped sending."""
        while True:
            now = time.monotonic()
            for topic, (speed, turn, since) in list(self._driving.items()):
                stale = now - since > DRIVE_TIMEOUT or not self._pages
                self._publisher(topic).publish(drive_command(self._drive_topics[topic], 0.0 if stale else speed,
                                                             0.0 if stale else turn))
                if stale:
                    del self._driving[topic]
            await asyncio.sleep(DRIVE_PERIOD)

    async def _status(self):
        master = rosgraph.Master(rospy.get_name())
        while True:
            try:
                await self._send_status(master)
            except Exception as error:  # noqa: BLE001  the status goes on, whatever one round met
                rospy.logerr_throttle(10.0, 'viewer: status: %r' % error)
            await asyncio.sleep(STATUS_PERIOD)

    async def _send_status(self, master):
        """One status to the pages, with the command and sensor topics the master knows now."""
        if not self._pages:
            return
        loop = asyncio.get_running_loop()
        paused = await loop.run_in_executor(None, self._paused)
        try:  # one master call at a time: its proxy is not for two threads
            self._drive_topics = await loop.run_in_executor(None, drive_topics, master)
            self._overlay_topics = await loop.run_in_executor(None, overlay_topics, master)
        except (rosgraph.MasterException, OSError) as error:
            rospy.logwarn_throttle(10.0, 'viewer: the master does not answer: %s' % error)
        self._send_all(json.dumps({'type': 'status', 'time': self._sim_time,
                                   'real_time_factor': self.real_time_factor(), 'paused': paused,
                                   'drive_topics': sorted(self._drive_topics),
                                   'overlay_topics': self._overlay_topics}))

    def app(self):
        app = web.Application()
        app.router.add_get('/', self._index)
        app.router.add_get('/viewer.js', self._bundle)
        app.router.add_get('/files/{path:.+}', self._file)
        app.router.add_get('/ws', self._page)
        return app

    async def serve(self, started=None):
        """Subscribes, serves until cancelled or rospy shuts down. `started(url)` once listening."""
        self._loop = asyncio.get_running_loop()
        rospy.Subscriber(self.namespace + '/scene', String, self._on_scene, queue_size=1)
        rospy.Subscriber('/clock', Clock, self._on_clock, queue_size=1)
        self._step_publisher = rospy.Publisher(self.namespace + '/' + STEP_TOPIC, UInt32, queue_size=10)
        runner = web.AppRunner(self.app())
        await runner.setup()
        site = web.TCPSite(runner, self.host, self.port)
        await site.start()
        if started:  # the port bound: the one asked for, or the system's pick for port 0
            started('http://%s:%d/' % (self.host, runner.addresses[0][1]))
        status, drive = asyncio.ensure_future(self._status()), asyncio.ensure_future(self._drive())
        try:
            while not rospy.is_shutdown():
                await asyncio.sleep(0.2)
        finally:
            status.cancel()
            drive.cancel()
            self._follow_links(False)
            await runner.cleanup()
