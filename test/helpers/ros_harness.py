"""Real ROS processes for the integration tests, the ROS benchmarks and `make demo`: a ROS master on a
free loopback port, roslaunch, rosrun and the command-line tools, each test with its own master.
rospy binds a process to one master, so the tests talk to ROS through subprocesses (the tools, or
short rospy programs, the rooms' probes/). A test harness, not part of the runtime package: the suite's conftest.py puts
this folder (test/helpers) on sys.path, bench/ and tools/ put it there themselves, and the processes
a RosSystem starts find it on PYTHONPATH (their rospy programs import it by name, `ros_harness`)."""
import functools
import json
import math
import os
import select
import signal
import socket
import subprocess
import textwrap
import time
import uuid
import xmlrpc.client

import yaml

from suite_paths import HELPERS, TEST_DIR  # the processes' PYTHONPATH; the probes are named relative to test/
from tianracer_description.tianracer import CONFIG_YAML

PYTHON = '/usr/bin/python3'


def message_to_dict(message):
    """A ROS message as plain JSON values, for the rospy programs of the tests (probes/): times as seconds,
    non-finite floats as their repr (JSON has none)."""
    if hasattr(message, 'to_sec'):
        return message.to_sec()
    if hasattr(message, '__slots__'):
        return {slot: message_to_dict(getattr(message, slot)) for slot in message.__slots__}
    if isinstance(message, (list, tuple)):
        return [message_to_dict(item) for item in message]
    if isinstance(message, float) and not math.isfinite(message):
        return repr(message)
    return message


def connected_publisher(topic, message_class, timeout=30.0, **options):
    """For the rospy programs of the tests (probes/): a rospy Publisher once a subscriber has connected to it, so
    that what it publishes next is heard at once (before the connection a message is lost, or, latched,
    it arrives later by the connection's time and shortens a measurement that follows it)."""
    import rospy
    publisher = rospy.Publisher(topic, message_class, **options)
    end = time.monotonic() + timeout
    while publisher.get_num_connections() == 0:
        if time.monotonic() > end:
            raise RuntimeError('nothing subscribed to %s within %g s: is the plant running the plugin or '
                               'controller that reads it?' % (topic, timeout))
        time.sleep(0.01)
    return publisher


def descendants(pids):
    """The pids of the processes below each of `pids` (their children, theirs, ...), from /proc."""
    children = {}
    for entry in os.listdir('/proc'):
        if entry.isdigit():
            try:
                with open('/proc/%s/stat' % entry) as stat:
                    parent = int(stat.read().rsplit(')', 1)[1].split()[1])
            except (OSError, IndexError, ValueError):
                continue
            children.setdefault(parent, []).append(int(entry))
    found, todo = [], list(pids)
    while todo:
        for child in children.get(todo.pop(), []):
            found.append(child)
            todo.append(child)
    return found


def kill_trees(pids):
    """SIGKILL to each of `pids`, its process group and every process below it. roslaunch starts each
    of its processes in a process group of its own (roscore's rosmaster too): killing a group alone
    would leave them running, orphaned. They are all stopped (SIGSTOP) first and /proc read again, so
    that a roslaunch still starting its nodes starts none between the reading and the kill."""
    def signal_all(tree, number):
        for pid in tree:
            try:
                os.kill(pid, number)
            except ProcessLookupError:
                pass
    signal_all(list(pids) + descendants(pids), signal.SIGSTOP)
    signal_all(list(pids) + descendants(pids), signal.SIGKILL)
    for pid in pids:
        try:
            os.killpg(pid, signal.SIGKILL)
        except ProcessLookupError:
            pass


def free_port():
    with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as s:
        s.bind(('127.0.0.1', 0))
        return s.getsockname()[1]


_ROSRUN_FOUND = {}  # (package, executable, the workspaces): the file rosrun runs


def rosrun_resolved(args, env):
    """`rosrun PACKAGE EXECUTABLE ARGS...` as the command rosrun execs (the same process: rosrun ends in
    `exec FILE ARGS...`), the file found by rosrun itself (`rosrun --prefix echo`) once a session for a
    package, executable and workspaces. Each rosrun runs catkin_find twice: 0.7 s of CPU, a few hundred
    times a suite. Any other command (or a rosrun that finds nothing: it says why when run) as given."""
    if len(args) < 3 or args[0] != 'rosrun' or args[1].startswith('-'):
        return list(args)
    key = (args[1], args[2], env.get('ROS_PACKAGE_PATH'), env.get('CMAKE_PREFIX_PATH'))
    if key not in _ROSRUN_FOUND:
        found = subprocess.run(['rosrun', '--prefix', 'echo', args[1], args[2]], env=env, capture_output=True,
                               text=True, timeout=60)
        if found.returncode != 0 or not os.path.isfile(found.stdout.strip()):
            return list(args)
        _ROSRUN_FOUND[key] = found.stdout.strip()
    return [_ROSRUN_FOUND[key], *args[3:]]


class Process:
    """A background process in its own process group, stopped through its own pid."""

    def __init__(self, args, env, log_path, stdin=subprocess.DEVNULL, stdout=None):
        """stdin, stdout: pipes to talk to it (text lines); its output goes to its log otherwise (its
        errors always)."""
        self.log_path = log_path
        self._log = open(log_path, 'w')
        # SIGINT as a terminal's Ctrl-C delivers it, even when the suite itself runs as a background
        # job of a shell without job control (which starts it with SIGINT ignored, inherited here).
        self.popen = subprocess.Popen(rosrun_resolved(args, env), env=env, stdout=self._log if stdout is None else stdout,
                                      stderr=subprocess.STDOUT if stdout is None else self._log,
                                      stdin=stdin, start_new_session=True, text=True, bufsize=1,
                                      preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))

    @property
    def pid(self):
        return self.popen.pid

    def interrupt(self):
        """SIGINT to the process group (as Ctrl-C in a terminal)."""
        if self.popen.poll() is None:
            os.killpg(self.popen.pid, signal.SIGINT)

    def wait(self, timeout):
        try:
            return self.popen.wait(timeout)
        except subprocess.TimeoutExpired:
            return None

    def stop(self, timeout=10.0):
        """interrupt(), then finish(timeout)."""
        self.interrupt()
        self.finish(timeout)

    def finish(self, timeout):
        """After interrupt(): waits `timeout` s for the process to end, then kills it and everything below it."""
        if self.popen.poll() is None and self.wait(timeout) is None:
            self.kill()
        self._log.close()

    def kill(self):
        """SIGKILL to the process and everything below it (kill_trees)."""
        if self.popen.poll() is None:
            kill_trees([self.popen.pid])
            self.popen.wait(5)
        self._log.close()

    def log(self):
        if not self._log.closed:
            self._log.flush()
        with open(self.log_path, errors='replace') as f:
            return f.read()


def rate_of_stamps(stamps):
    """The rate (Hz) a publisher stamped its messages at: one over the median interval between the
    stamps heard, which neither the reader's lag nor a message dropped on the way (roscpp drops a
    slow subscriber's oldest beyond the publisher's queue) changes, where a count over the span does.
    None with fewer than two stamps or a median interval of 0."""
    intervals = sorted(b - a for a, b in zip(stamps, stamps[1:]))
    if not intervals or intervals[len(intervals) // 2] <= 0:
        return None
    return 1.0 / intervals[len(intervals) // 2]


@functools.lru_cache(maxsize=None)
def core_parameters():
    """The parameters roscore sets from roscore.xml (/rosversion, /rosdistro), asked of rosversion once
    a session."""
    def rosversion(*args):
        return subprocess.run(['rosversion', *args], capture_output=True, text=True, check=True).stdout.strip()
    return {'/rosversion': rosversion('roslaunch'), '/rosdistro': rosversion('-d')}


@functools.lru_cache(maxsize=None)
def rosout_executable():
    from roslib.packages import find_node
    return find_node('rosout', 'rosout')[0]


class _TransportWithTimeout(xmlrpc.client.Transport):
    """XML-RPC over HTTP giving up after `timeout` s: a port that another server holds (a node's
    TCPROS server) accepts the connection and never answers."""

    def __init__(self, timeout):
        super().__init__()
        self.timeout = timeout

    def make_connection(self, host):
        connection = super().make_connection(host)
        connection.timeout = self.timeout
        return connection


class RosSystem:
    """A ROS master of its own and the processes started against it. The master is what roscore starts
    (rosmaster --core, rosout, /run_id, /rosversion and /rosdistro) without roscore's own roslaunch,
    which cost each test a second of CPU (roslaunch and two rosversion runs)."""

    def __init__(self, workdir, base_env=None):
        """base_env: the environment the processes start from (default this one's: the suite's
        sourced workspace); a user's own workspace, sourced apart, for the tests of that."""
        self.base_env = os.environ if base_env is None else base_env
        self.workdir = workdir
        self.processes = []
        self._service_caller = None
        self.master = self._start_master()
        master = xmlrpc.client.ServerProxy(self.env['ROS_MASTER_URI'])
        for name, value in dict(core_parameters(), **{'/run_id': str(uuid.uuid1())}).items():
            master.setParam('/ros_harness', name, value)
        self.start([rosout_executable(), '__name:=rosout'], 'rosout')

    def _start_master(self, attempts=5):
        """rosmaster on a port found free, and this system's environment for it. The port can be taken
        between free_port() and rosmaster's bind (any process's ephemeral port: a connection, a node's
        server, another test's master that found the same port): rosmaster then waits for ever, or
        another master answers there. Each port is tried until its master answers with its own pid."""
        for _ in range(attempts):
            self.port = free_port()
            self.env = dict(self.base_env, ROS_MASTER_URI='http://127.0.0.1:%d' % self.port, ROS_IP='127.0.0.1',
                            ROS_HOME=os.path.join(self.workdir, 'ros_home'), PYTHONUNBUFFERED='1')
            self.env.pop('ROS_HOSTNAME', None)
            self.env['PYTHONPATH'] = os.pathsep.join(filter(None, [HELPERS, self.base_env.get('PYTHONPATH')]))
            master = Process(['rosmaster', '--core', '-p', str(self.port), '-w', '3'], self.env,
                             os.path.join(self.workdir, 'rosmaster.log'))
            try:
                answers = self._master_answers(master, timeout=15)
            except AssertionError:
                master.kill()  # nothing else stops it: the caller has no RosSystem to close
                raise
            if answers:
                self.processes.append(master)
                return master
            master.kill()
        raise AssertionError('rosmaster did not start on any of %d free ports; the last one said: %s'
                             % (attempts, master.log()))

    def _master_answers(self, master, timeout):
        """Whether `master` (rosmaster's process) answers its XML-RPC API as itself (getPid, asked
        here: a `rosparam` would start a Python) within `timeout` s; False as soon as it cannot (its
        port taken); an AssertionError with its log when it says nothing in that time."""
        proxy = xmlrpc.client.ServerProxy(self.env['ROS_MASTER_URI'], transport=_TransportWithTimeout(1.0))
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            if master.popen.poll() is not None or 'Address already in use' in master.log():
                return False
            try:
                code, _, pid = proxy.getPid('/ros_harness')
                if code == 1:
                    return pid == master.pid  # another master on the port: ours cannot bind it
            except (OSError, xmlrpc.client.Error):  # not listening yet, or not answering XML-RPC yet
                pass
            time.sleep(0.05)
        raise AssertionError('timed out after %g s waiting for the ROS master (rosmaster on port %d): %s'
                             % (timeout, self.port, master.log()))

    def start(self, args, name):
        process = Process(args, self.env, os.path.join(self.workdir, name + '.log'))
        self.processes.append(process)
        return process

    def run(self, args, timeout=30, input=None):
        return subprocess.run(rosrun_resolved(args, self.env), env=self.env, capture_output=True, text=True,
                              timeout=timeout, input=input)

    def set_param(self, name, value=None, textfile=None):
        """`rosparam set NAME VALUE` with a Python value, or `rosparam set NAME --textfile PATH`, by
        rosparam's rule (a dict updates the namespace key by key, as rosparam's set_param_raw does),
        asked of the master here: a `rosparam` process would import rospy for it (half a second of
        CPU, each of the suite's hundred)."""
        if textfile is not None:
            with open(textfile) as text:
                value = text.read()
        if isinstance(value, dict):
            for key, item in value.items():
                self.set_param(name.rstrip('/') + '/' + key, item)
            return
        code, message, _ = xmlrpc.client.ServerProxy(self.env['ROS_MASTER_URI']).setParam('/ros_harness', name, value)
        assert code == 1, 'setting the parameter %s: %s' % (name, message)

    def get_param(self, name):
        """`rosparam get NAME`'s value, asked of the master here (no `rosparam` process)."""
        code, message, value = xmlrpc.client.ServerProxy(self.env['ROS_MASTER_URI']).getParam('/ros_harness', name)
        assert code == 1, 'getting the parameter %s: %s' % (name, message)
        return value

    def services(self):
        """`rosservice list`: the services the master knows, asked of it here (its getSystemState, as
        rosservice asks it; no process)."""
        code, message, (_, _, services) = xmlrpc.client.ServerProxy(self.env['ROS_MASTER_URI']).getSystemState(
            '/ros_harness')
        assert code == 1, 'the master\'s system state: %s' % message
        return [name for name, _ in services]

    def load_params(self, path):
        """`rosparam load PATH`: the file read by rosparam's own reader (its documents, namespaces and
        !degrees / !radians tags), its values set as `set_param` sets them."""
        import rosparam
        for values, namespace in rosparam.load_file(path, default_namespace='/'):
            self.set_param(namespace, values)

    def probe(self, program, *args, timeout=30):
        """Runs a rospy program of the suite (test/<room>/probes/<name>.py, named relative to test/) with
        `args` against this master; it prints one JSON value on its last line, which is returned."""
        return self._json_of([PYTHON, os.path.join(TEST_DIR, program), *map(str, args)], timeout)

    def python(self, code, timeout=30):
        """Runs a rospy program given as text (the benchmarks' generated ones) against this master; it
        prints one JSON value on its last line, which is returned."""
        return self._json_of([PYTHON, '-c', textwrap.dedent(code)], timeout)

    def _json_of(self, args, timeout):
        result = self.run(args, timeout=timeout)
        assert result.returncode == 0, result.stderr
        return json.loads(result.stdout.strip().splitlines()[-1])

    def service(self, name, request_yaml='{}', timeout=15, wait=False):
        """`rosservice call [--wait] NAME REQUEST_YAML`: the response as YAML reads what rosservice
        prints. The calls of a test go through one process of rosservice's own code
        (probes/service_caller.py); one that takes longer than `timeout` s (the wait included) stops
        it (the next call starts another)."""
        if self._service_caller is None or self._service_caller.popen.poll() is not None:
            self._service_caller = Process([PYTHON, os.path.join(HELPERS, 'probes', 'service_caller.py')], self.env,
                                           os.path.join(self.workdir, 'service_caller.log'),
                                           stdin=subprocess.PIPE, stdout=subprocess.PIPE)
            self.processes.append(self._service_caller)
        caller = self._service_caller.popen
        caller.stdin.write(json.dumps({'service': name, 'request': request_yaml, 'wait': wait}) + '\n')
        caller.stdin.flush()
        if not select.select([caller.stdout], [], [], timeout)[0]:
            self._service_caller.stop(1.0)
            raise AssertionError('rosservice call %s %s: no answer within %g s' % (name, request_yaml, timeout))
        line = caller.stdout.readline()
        assert line, 'the service caller exited: ' + self._service_caller.log()
        answer = json.loads(line)
        assert 'error' not in answer, 'rosservice call %s %s: %s' % (name, request_yaml, answer.get('error'))
        return yaml.safe_load(answer['response'])

    def wait_for_controllers(self, count, namespace='/tianracer', timeout=60):
        """Until `count` controllers run in the namespace's controller manager: its list_controllers
        asked through the test's service caller every 0.1 s (a rospy program for it cost each test
        half a second of CPU)."""
        name = namespace + '/controller_manager/list_controllers'
        deadline = time.monotonic() + timeout

        def running():
            listed = self.service(name, timeout=max(deadline - time.monotonic(), 1.0), wait=True)
            return [controller['state'] for controller in listed['controller'] or []].count('running') == count
        self.wait_until(running, timeout, '%d controllers to run in %s' % (count, name))

    def model_pose(self, model):
        """`model`'s pose in the world from gazebo/get_model_state (through the service caller):
        {'position': {x, y, z}, 'orientation': {x, y, z, w}}."""
        state = self.service('/gazebo/get_model_state', json.dumps({'model_name': model}))
        assert state['success'], 'get_model_state %s: %s' % (model, state['status_message'])
        return state['pose']

    @staticmethod
    def wait_until(condition, timeout, what):
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            if condition():
                return
            time.sleep(0.1)
        raise AssertionError('timed out after %g s waiting for %s' % (timeout, what))

    def close(self):
        # A test's teardown: nothing is checked after it, so every process and everything below it
        # (roslaunch starts each node in a process group of its own) is killed at once. Interrupted
        # (SIGINT) and given time to stop, the processes of a test took 0.7 s of its teardown, about
        # 90 s of a run's time over its ROS tests; a test that checks how something stops stops it
        # itself (Process.stop).
        running = [process for process in self.processes if process.popen.poll() is None]
        kill_trees([process.pid for process in running])
        for process in self.processes:
            process.kill()  # reaps the killed ones, closes every log


def plant_pid(started_pid, timeout=30.0):
    """The bullet_plant process of a process started to run it: that process itself once gazebo_ros's
    gzserver has become it (it execs the node), or its child (roslaunch's)."""
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        for entry in os.listdir('/proc'):
            if not entry.isdigit():
                continue
            try:
                with open('/proc/%s/stat' % entry) as f:
                    fields = f.read().rsplit(')', 1)[1].split()
                with open('/proc/%s/comm' % entry) as f:
                    name = f.read().strip()
            except OSError:
                continue
            if name == 'bullet_plant' and started_pid in (int(entry), int(fields[1])):
                return int(entry)
        time.sleep(0.1)
    raise RuntimeError('no bullet_plant process from process %d within %g s' % (started_pid, timeout))


def start_plant(ros, world=None, paused=False):
    """The simulator with no robot yet, as gazebo_ros_pkgs' own tests start it: gazebo_ros's gzserver
    on the world (rosrun; `-u` paused), with /use_sim_time set as empty_world.launch sets it. Through
    roslaunch it cost each test a second more of CPU and of waiting (roslaunch, and the two rosversion
    runs of each roslaunch); the launch files are tested as users start them in gazebo_ros/,
    tutorial/ and rostest/."""
    ros.set_param('/use_sim_time', True)
    return ros.start(['rosrun', 'gazebo_ros', 'gzserver', *(['-u'] if paused else []), world or 'worlds/empty.world'],
                     'plant')


def spawn_urdf(ros, plant, param, model, robot_namespace='/', xyz=(0.0, 0.0, 0.0)):
    """The URDF on the parameter `param` spawned as `model` (at `xyz`, its plugins in `robot_namespace`):
    the gazebo/spawn_urdf_model call `spawn_model -urdf -param PARAM -model MODEL [-robot_namespace NS]
    [-x X -y Y -z Z]` makes, made through the test's service caller. A spawn_model process would import
    rospy for it (0.7 s of CPU, some seventy times a suite); the script itself is run where users run
    it, from the launch files of gazebo_ros/, tutorial/ and rostest/, and in gazebo_ros/test_spawn_sdf.
    Asserts it succeeded (the plant's log in the message otherwise)."""
    request = {'model_name': model, 'model_xml': ros.get_param(param), 'robot_namespace': robot_namespace,
               'initial_pose': {'position': dict(zip('xyz', map(float, xyz))), 'orientation': {'w': 1.0}},
               'reference_frame': ''}
    answer = ros.service('/gazebo/spawn_urdf_model', json.dumps(request), timeout=60, wait=True)
    assert answer['success'], answer['status_message'] + plant.log()


def tianracer_plant(ros, urdf_path, world=None, paused=False):
    """The plant with the car spawned and the tutorial's YAML loaded (no controllers yet)."""
    plant = start_plant(ros, world, paused)
    ros.set_param('/robot_description', textfile=urdf_path)
    ros.load_params(CONFIG_YAML)
    spawn_urdf(ros, plant, 'robot_description', 'tianracer')
    return plant


def spawn_with_controllers(ros, plant, urdf_path, controllers_yaml, namespace, model, controllers):
    """A robot driven through gazebo_ros_control, as a robot maker's launch file brings it up: its
    URDF on <namespace>/robot_description, its controllers' YAML loaded, spawned (spawn_urdf), then
    controller_manager's spawner in the namespace; returns the spawner once they all run."""
    ros.set_param(namespace + '/robot_description', textfile=urdf_path)
    ros.load_params(controllers_yaml)
    spawn_urdf(ros, plant, namespace + '/robot_description', model)
    spawner = ros.start(['rosrun', 'controller_manager', 'spawner', '__ns:=' + namespace, *controllers], 'spawner')
    ros.wait_for_controllers(len(controllers), namespace=namespace)
    return spawner


def frames_in(ros, target, topics, timeout=30):
    """Through a tf2 buffer (tf2_ros, as rviz and navigation use it): one message of each topic, its
    header's frame id and that frame's origin in `target` at the message's stamp. A message stamped
    before the buffer's first transform is dropped for the next, as a tf2 message filter drops it.
    {topic: {'frame': ..., 'xyz': [x, y, z]}}; a lookup that fails fails the snippet."""
    return ros.probe('helpers/probes/frames_in.py', target, timeout, *topics, timeout=timeout * len(topics) + 30)


def running_controllers(namespace, count, timeout=60.0):
    """From inside a rospy node (the rostest nodes): the names of the controllers running in the
    controller manager of `namespace` once `count` of them run, or at the timeout (wall clock)."""
    import rospy
    from controller_manager_msgs.srv import ListControllers
    service = namespace + '/controller_manager/list_controllers'
    end = time.monotonic() + timeout
    running = []
    while time.monotonic() < end and not rospy.is_shutdown():
        try:
            rospy.wait_for_service(service, 1.0)
            running = [c.name for c in rospy.ServiceProxy(service, ListControllers)().controller
                       if c.state == 'running']
            if len(running) >= count:
                break
        except (rospy.ROSException, rospy.ServiceException):
            pass
        time.sleep(0.05)
    return running


class TopicRates:
    """From inside a rospy node (the rostest nodes): rostest's hztest for several topics at once, in one
    launch (rostest starts the whole launch file again for each <test>). Each topic is heard from its
    first message on, in ROS time (simulated time under /use_sim_time). A message that carries a time
    (a header's stamp, /clock's clock) counts at that time, when the publisher made it, and the rate is
    one over the median interval between those times: neither this node's lag nor a message the
    publisher's queue dropped while this node was slow to read changes it. Counting messages over the
    span, as hztest does, read /clock's 100 Hz as 93.8 when a second test process loaded the machine
    (roscpp drops a subscriber's oldest messages beyond the publisher's queue of 10), and arrival times
    read /tianracer/odom's 50 Hz as 42.6. A message carrying no time counts at its arrival, and its
    rate is hztest's, (messages - 1) / (last - first)."""

    def __init__(self, topics):
        import rospy
        self._arrivals = {topic: [] for topic in topics}
        self._stamped = set()  # the topics whose messages carry their time
        self._time_at = {}  # message type: the byte offset of the time it carries (None: none)
        self._subscribers = [rospy.Subscriber(topic, rospy.AnyMsg, self._heard, topic) for topic in topics]

    def _heard(self, message, topic):
        import rospy
        stamp = self._carried_time(message)
        if stamp is not None:
            self._stamped.add(topic)
        self._arrivals[topic].append(stamp if stamp is not None else rospy.get_time())

    def _carried_time(self, message):
        """The time (s) a message carries in its first field, a std_msgs/Header's stamp or a time (as
        rosgraph_msgs/Clock's); None for one that carries none there."""
        import struct
        import rospy
        from roslib.message import get_message_class
        if not isinstance(message, rospy.AnyMsg):
            # the topic's typed subscriber in this node deserialized it (rospy's own /clock subscriber
            # under /use_sim_time hands this one a rosgraph_msgs/Clock: its first field is the time)
            header = getattr(message, 'header', None)
            if header is not None and hasattr(header, 'stamp'):
                return header.stamp.to_sec()
            if message._slot_types and message._slot_types[0] == 'time':
                return getattr(message, message.__slots__[0]).to_sec()
            return None
        kind = message._connection_header['type']
        if kind not in self._time_at:
            message_class = get_message_class(kind)
            first = message_class._slot_types[0] if message_class and message_class._slot_types else None
            # a Header serializes as uint32 seq, then its stamp
            self._time_at[kind] = 4 if first in ('std_msgs/Header', 'Header') else 0 if first == 'time' else None
        offset = self._time_at[kind]
        if offset is None:
            return None
        secs, nsecs = struct.unpack_from('<II', message._buff, offset)
        return secs + 1e-9 * nsecs

    def measure(self, duration, wait_time=60.0):
        """{topic: Hz} over `duration` s of ROS time after every topic's first message (None for a topic with
        fewer than two messages); waits at most `wait_time` s of wall clock for the first messages, as hztest."""
        import rospy
        end = time.monotonic() + wait_time
        while not all(self._arrivals.values()) and time.monotonic() < end and not rospy.is_shutdown():
            time.sleep(0.05)
        stop = rospy.get_time() + duration
        while rospy.get_time() < stop and not rospy.is_shutdown():
            time.sleep(0.05)
        for subscriber in self._subscribers:
            subscriber.unregister()
        rates = {}
        for topic, arrivals in self._arrivals.items():
            if len(arrivals) < 2:
                rates[topic] = None
            elif topic in self._stamped:
                rates[topic] = rate_of_stamps(arrivals)
            else:
                span = arrivals[-1] - arrivals[0]
                rates[topic] = (len(arrivals) - 1) / span if span > 0 else None
        return rates


def drive_mimic_gripper(ros, plant, urdf_path):
    """The test gripper (test/fixtures/urdf/gripper.urdf at `urdf_path`, its mimic joint plugin's PID
    gains at /mimic_gains: p 100, d 4) spawned into `plant`, its first finger commanded to 0.03 m
    through a position controller: the fingers' y where the plugin left them ({link: y})."""
    ros.set_param('/gripper/robot_description', textfile=str(urdf_path))
    ros.set_param('/mimic_gains', {'p': 100.0, 'i': 0.0, 'd': 4.0})
    ros.set_param('/gripper/finger_controller', {'type': 'position_controllers/JointPositionController',
                                                 'joint': 'finger_joint'})
    spawn_urdf(ros, plant, '/gripper/robot_description', 'gripper')
    spawner = ros.start(['rosrun', 'controller_manager', 'spawner', '__ns:=/gripper', 'finger_controller'], 'spawner')
    ros.wait_for_controllers(1, namespace='/gripper')
    seen = ros.probe('model_plugins/probes/the_mimic_joint_plugin_reads_its_pid_gains_from_the_parameter_server.py',
                     timeout=60)
    spawner.stop()
    return seen
