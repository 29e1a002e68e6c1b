"""A fleet of turtlebot3-like robots through ROS at real time (`make bench-fleet`).

The robot is test/fixtures/urdf/diff_bot.urdf, as a burger has it: gazebo_plugins' diff drive
(odometry, tf and the wheels' joint states at 30 Hz), a 360-ray lidar at 5 Hz and the IMU plugin at
200 Hz. N of them stand on a grid in a generated arena (walls round it, a crate between each four
robots, all within the lidars' 3.5 m), each spawned by /gazebo/spawn_urdf_model in its own
namespace tb3_I, as multi_turtlebot3 launches do. A probe subscribes to every robot's scan and odom
(counting the messages, without deserializing them: rospy.AnyMsg) and sends each a slow circle on
its cmd_vel once a second (the diff drive keeps the last command).

For each N, ROUNDS rounds, each two measurements one right after the other: the physics-only cost
of the same world and robots stepped from Python without ROS (bullet_plant.World in a process of its
own, PHYSICS_SECONDS simulated, the process's CPU time), while the node is paused; then, the node
running again, the real time factor from /clock and the plant process's user + system CPU from /proc
over WINDOW s of wall time. What a robot costs the node around its physics and sensors is the
difference. The ratio is taken in each round and its median reported: on a shared machine the speed
of a core moves by half between one minute and the next (the host's other tenants), both sides of a
round see the same machine, and two measurements minutes apart do not. Both fleets have driven their
circles for SETTLE s before the first round.

FLEET_SIZES=1,10, FLEET_WINDOW=8 and FLEET_ROUNDS=5 in the environment change the sizes, the window
and the rounds.
"""
import json
import math
import os
import platform
import select
import statistics
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), os.pardir, 'test', 'helpers'))
from plant_helpers import DIFF_BOT  # noqa: E402  (the test fixture is the benchmark's robot)
from ros_plant_bench import cpu_seconds, plant_pid  # noqa: E402
from ros_harness import PYTHON, Process, RosSystem, start_plant  # noqa: E402

SIZES = [int(n) for n in os.environ.get('FLEET_SIZES', '1,10,25,50,100').split(',')]
WINDOW = float(os.environ.get('FLEET_WINDOW', '8'))
ROUNDS = int(os.environ.get('FLEET_ROUNDS', '5'))
PHYSICS_SECONDS = 3.0
SETTLE = 3.0  # s both fleets drive before the first round
SPACING = 1.5  # m between robots on the grid
LINEAR, ANGULAR = 0.1, 0.5  # the slow circle (m/s, rad/s)
LIDAR = 'lds_lfcd_sensor'  # diff_bot.urdf's lidar: its scan is subscribed (the IMU's is not: it idles)


def fleet_robot():
    """diff_bot.urdf with its IMU plugin at 200 Hz, as a burger's IMU publishes."""
    with open(DIFF_BOT) as f:
        urdf = f.read()
    imu = urdf.index('<plugin name="imu_plugin"')
    rate = urdf.index('<updateRate>0</updateRate>', imu)
    return urdf[:rate] + '<updateRate>200</updateRate>' + urdf[rate + len('<updateRate>0</updateRate>'):]


def grid(n):
    """The robots' (x, y) on a square grid about the origin, SPACING apart, and the grid's side."""
    side = max(1, math.ceil(math.sqrt(n)))
    offset = (side - 1) * SPACING / 2
    return [((i % side) * SPACING - offset, (i // side) * SPACING - offset) for i in range(n)], side


def box(name, x, y, sx, sy, height):
    size = '%g %g %g' % (sx, sy, height)
    return ('<model name="%s"><static>true</static><pose>%g %g %g 0 0 0</pose><link name="link">'
            '<collision name="collision"><geometry><box><size>%s</size></box></geometry></collision>'
            '<visual name="visual"><geometry><box><size>%s</size></box></geometry></visual>'
            '</link></model>\n' % (name, x, y, height / 2, size, size))


def arena(n):
    """An SDF world for n robots: ground, sun, walls SPACING beyond the grid, a 0.2 m crate at the
    centre of each square of four robots."""
    _, side = grid(n)
    half = (side - 1) * SPACING / 2 + SPACING
    models = [box('wall_%s' % name, x, y, sx, sy, 0.3) for name, x, y, sx, sy in (
        ('north', 0, half, 2 * half + 0.1, 0.1), ('south', 0, -half, 2 * half + 0.1, 0.1),
        ('east', half, 0, 0.1, 2 * half + 0.1), ('west', -half, 0, 0.1, 2 * half + 0.1))]
    for i in range(side - 1):
        for j in range(side - 1):
            x, y = (i + 0.5) * SPACING - (side - 1) * SPACING / 2, (j + 0.5) * SPACING - (side - 1) * SPACING / 2
            models.append(box('crate_%d_%d' % (i, j), x, y, 0.2, 0.2, 0.3))
    return ('<?xml version="1.0"?>\n<sdf version="1.6"><world name="fleet_arena">\n'
            '<include><uri>model://ground_plane</uri></include><include><uri>model://sun</uri></include>\n'
            '<physics type="ode"><max_step_size>0.001</max_step_size><real_time_factor>1</real_time_factor>'
            '</physics>\n' + ''.join(models) + '</world></sdf>\n')


# Spawns the fleet through gazebo_ros's service, as spawn_model -urdf -robot_namespace does.
SPAWN_PROBE = """
import json, rospy
from gazebo_msgs.srv import SpawnModel
from geometry_msgs.msg import Pose
rospy.init_node('fleet_spawner', anonymous=True)
rospy.wait_for_service('/gazebo/spawn_urdf_model', timeout=60)
spawn = rospy.ServiceProxy('/gazebo/spawn_urdf_model', SpawnModel)
urdf = open({urdf_path!r}).read()
failed = []
for i, (x, y) in enumerate({places!r}):
    pose = Pose()
    pose.position.x, pose.position.y, pose.orientation.w = x, y, 1.0
    answer = spawn('tb3_%d' % i, urdf, '/tb3_%d' % i, pose, 'world')
    if not answer.success:
        failed.append(answer.status_message)
print(json.dumps(dict(failed=failed)))
"""

# Subscribes to every robot's scan and odom (counted, not deserialized) and drives each on a slow
# circle (its twist sent once a second); then, for each line `window S` on its input, measures S s of
# wall time and prints one JSON line.
FLEET_PROBE = """
import json, sys, threading, time, rospy
from geometry_msgs.msg import Twist
from rosgraph_msgs.msg import Clock
rospy.init_node('fleet_probe', anonymous=True)
clock, counts = [], {{}}
rospy.Subscriber('/clock', Clock, lambda m: clock.append(m.clock.to_sec()))
def count(kind):
    return lambda m: counts.__setitem__(kind, counts.get(kind, 0) + 1)
for i in range({n}):
    rospy.Subscriber('/tb3_%d/scan' % i, rospy.AnyMsg, count('scan'))
    rospy.Subscriber('/tb3_%d/odom' % i, rospy.AnyMsg, count('odom'))
drives = [rospy.Publisher('/tb3_%d/cmd_vel' % i, Twist, queue_size=1) for i in range({n})]
def keep_driving():
    twist = Twist()
    twist.linear.x, twist.angular.z = {linear!r}, {angular!r}
    while not rospy.is_shutdown():
        for drive in drives:
            drive.publish(twist)
        time.sleep(1.0)
threading.Thread(target=keep_driving, daemon=True).start()
print(json.dumps('driving'), flush=True)
for line in sys.stdin:
    window = float(line.split()[1])
    start_wall, start_sim, start_counts = time.monotonic(), clock[-1], dict(counts)
    time.sleep(window)
    wall, sim = time.monotonic() - start_wall, clock[-1] - start_sim
    print(json.dumps(dict(rtf=sim / wall, sim=sim,
                          rates={{k: (c - start_counts.get(k, 0)) / sim / {n} for k, c in counts.items()}})),
          flush=True)
"""

# The same world and fleet stepped from Python without ROS, each robot on the probe's circle; for each
# line `step K` on its input, K steps and one JSON line: the process's CPU seconds for them. What
# computes is what computes through ROS: the physics, the model plugins, and the sensors whose topics
# the probe subscribes (the lidars; a sensor computes only while subscribed).
PHYSICS_WORKER = """
import json, sys
sys.path.insert(0, {bench!r})
import time
import fleet_cost
from tianracer_description import bullet_plant
world = bullet_plant.World.from_file({world_path!r})
world.echo = False
urdf = open({urdf_path!r}).read()
places, _ = fleet_cost.grid({n})
robots = [world.spawn(urdf, 'tb3_%d' % i, [x, y, 0, 0, 0, 0], '/tb3_%d' % i) for i, (x, y) in enumerate(places)]
for robot in robots:
    robot.plugin_send('diff_drive', 'cmd_vel', (fleet_cost.LINEAR, fleet_cost.ANGULAR))
    robot.enable_sensor(fleet_cost.LIDAR, True)
world.step(int({settle!r} / 0.001))
print(json.dumps('driving'), flush=True)
for line in sys.stdin:
    steps = int(line.split()[1])
    start = time.process_time()
    world.step(steps)
    print(json.dumps(time.process_time() - start), flush=True)
"""


def conversing(args, env, log_path):
    """A process that answers each line it is given with one JSON line."""
    return Process(args, env, log_path, stdin=subprocess.PIPE, stdout=subprocess.PIPE)


def answer(process, line, timeout):
    """Sends `line` (None: none, waits for what it says unasked) and returns its JSON answer."""
    if line is not None:
        process.popen.stdin.write(line + '\n')
        process.popen.stdin.flush()
    if not select.select([process.popen.stdout], [], [], timeout)[0]:
        raise RuntimeError('%s: no answer to %r within %g s; its log:\n%s' % (
            process.popen.args, line, timeout, process.log()[-2000:]))
    text = process.popen.stdout.readline()
    if not text:
        raise RuntimeError('%s ended; its log:\n%s' % (process.popen.args, process.log()[-2000:]))
    return json.loads(text)


def fleet_rounds(n, world_path, urdf_path):
    """ROUNDS rounds of the fleet of n: in each, the physics-only CPU a simulated second (the node
    paused meanwhile), then through the node over WINDOW s: the real time factor, the plant's CPU (share
    of one core) and the probe's per-robot message rates."""
    places, _ = grid(n)
    with tempfile.TemporaryDirectory() as workdir:
        ros = RosSystem(workdir)
        try:
            plant = start_plant(ros, world_path)
            spawned = ros.python(SPAWN_PROBE.format(urdf_path=urdf_path, places=places), timeout=60 + 5 * n)
            if spawned['failed']:
                raise RuntimeError('spawning the fleet failed: %s' % spawned['failed'][:3])
            pid = plant_pid(plant.pid)
            physics = conversing([PYTHON, '-c', PHYSICS_WORKER.format(
                bench=os.path.dirname(os.path.abspath(__file__)), world_path=world_path, urdf_path=urdf_path, n=n,
                settle=SETTLE)], ros.env, os.path.join(workdir, 'physics_only.log'))
            ros.processes.append(physics)
            probe = conversing([PYTHON, '-c', FLEET_PROBE.format(n=n, linear=LINEAR, angular=ANGULAR)], ros.env,
                               os.path.join(workdir, 'fleet_probe.log'))
            ros.processes.append(probe)
            answer(physics, None, 60 + n)
            answer(probe, None, 60)
            time.sleep(SETTLE)
            rounds = []
            steps = int(PHYSICS_SECONDS / 0.001)
            for _ in range(ROUNDS):
                ros.service('/gazebo/pause_physics')
                physics_cpu = answer(physics, 'step %d' % steps, 60 + 2 * n) / PHYSICS_SECONDS
                ros.service('/gazebo/unpause_physics')
                time.sleep(1.0)  # the pace and the probe's subscriptions running again
                cpu_before, wall_before = cpu_seconds(pid), time.monotonic()
                measured = answer(probe, 'window %g' % WINDOW, WINDOW + 60)
                measured['cpu'] = (cpu_seconds(pid) - cpu_before) / (time.monotonic() - wall_before)
                measured['physics'] = physics_cpu
                rounds.append(measured)
            return rounds
        finally:
            ros.close()


def main():
    urdf = fleet_robot()
    cpu_model = next((line.split(':', 1)[1].strip() for line in open('/proc/cpuinfo') if line.startswith('model name')),
                     platform.processor())
    print('CPU: %s, %d cores; the fleet through ROS over %g s of wall time, physics only over %g s simulated; '
          'medians of %d rounds, the ratio taken in each' % (cpu_model, os.cpu_count(), WINDOW, PHYSICS_SECONDS, ROUNDS), flush=True)
    print('%5s %7s %12s %12s %12s %9s %12s %12s %12s' % ('N', 'RTF', 'plant CPU', 'per robot', 'physics only', 'ratio',
                                                          'ratio range', 'scan/robot', 'odom/robot'), flush=True)
    with tempfile.TemporaryDirectory() as workdir:
        urdf_path = os.path.join(workdir, 'fleet_robot.urdf')
        with open(urdf_path, 'w') as f:
            f.write(urdf)
        for n in SIZES:
            world_path = os.path.join(workdir, 'fleet_%d.world' % n)
            with open(world_path, 'w') as f:
                f.write(arena(n))
            rounds = fleet_rounds(n, world_path, urdf_path)
            rtf = statistics.median(r['rtf'] for r in rounds)
            cpu = statistics.median(r['cpu'] for r in rounds)
            # per robot: the plant's CPU a simulated second, over n
            per_robot = [r['cpu'] / r['rtf'] / n for r in rounds]
            physics_per_robot = [r['physics'] / n for r in rounds]
            ratios = sorted(node / physics for node, physics in zip(per_robot, physics_per_robot))
            print('%5d %7.3f %11.1f%% %11.2f%% %11.2f%% %9.2f %12s %12.2f %12.2f' % (
                n, rtf, 100 * cpu, 100 * statistics.median(per_robot), 100 * statistics.median(physics_per_robot),
                statistics.median(ratios), '%.2f-%.2f' % (ratios[0], ratios[-1]),
                statistics.median(r['rates'].get('scan', 0.0) for r in rounds),
                statistics.median(r['rates'].get('odom', 0.0) for r in rounds)), flush=True)
    print('target (issue 56): 50 robots at RTF >= 0.99 with the node\'s cost a robot within 1.5x the '
          'physics-only cost; 100 robots run')


if __name__ == '__main__':
    main()
