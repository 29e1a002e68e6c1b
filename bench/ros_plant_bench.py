"""The plant as a ROS node, timed (`make bench-ros`): what issue 5 asks of it.

  launch -> running   wall time from starting `roslaunch tianracer_description tianracer.launch
                      gui:=false` until list_controllers shows the tutorial's five running
  real time factor    simulated / wall time over WINDOW s at real time, with the five controllers
                      running, the car driving a circle (cmd_vel at 10 Hz) and the lidar subscribed
  CPU                 the plant process's user+system time over that window, as a share of one core
  fastest             real time factor with real_time_factor:=0 (as fast as possible), same load

Each figure is the median of ROUNDS rounds, each with its own ROS master. Uses the test harness
(test/helpers/ros_harness.py): real roscore, roslaunch and tools on loopback.
"""
import os
import statistics
import sys
import tempfile
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), os.pardir, 'test', 'helpers'))
from ros_harness import RosSystem, plant_pid  # noqa: E402,F401  (the test harness; plant_pid for the benches)
from tianracer_description.tianracer import TUTORIAL_CONTROLLERS  # noqa: E402

ROUNDS = 3
WINDOW = 60.0        # s of wall time for the real time factor at real time
FAST_WINDOW = 10.0   # s of wall time as fast as possible
CONTROLLERS = len(TUTORIAL_CONTROLLERS)

# A probe that drives `drive_topic` with Twist(linear x, angular z) at 10 Hz, subscribes to `topics`
# ((topic, 'package.msg', 'Type'), ...), waits SETTLE s, then measures over `window` s of wall time:
# the real time factor from /clock and each topic's messages per simulated second.
DRIVING_PROBE = """
import importlib, json, threading, time, rospy
from geometry_msgs.msg import Twist
from rosgraph_msgs.msg import Clock
rospy.init_node('bench_probe', anonymous=True)
clock, counts = [], {{}}
rospy.Subscriber('/clock', Clock, lambda m: clock.append(m.clock.to_sec()))
def count(topic):
    return lambda m: counts.__setitem__(topic, counts.get(topic, 0) + 1)
for topic, module, kind in {topics!r}:
    rospy.Subscriber(topic, getattr(importlib.import_module(module), kind), count(topic))
if {drive_topic!r}:
    drive = rospy.Publisher({drive_topic!r}, Twist, queue_size=1)
    def keep_driving():
        twist = Twist()
        twist.linear.x, twist.angular.z = {linear!r}, {angular!r}
        while not rospy.is_shutdown():
            drive.publish(twist)
            time.sleep(0.1)
    threading.Thread(target=keep_driving, daemon=True).start()
time.sleep({settle!r})
start_wall, start_sim, start_counts = time.monotonic(), clock[-1], dict(counts)
time.sleep({window!r})
wall, sim = time.monotonic() - start_wall, clock[-1] - start_sim
print(json.dumps(dict(rtf=sim / wall, rates={{t: (n - start_counts.get(t, 0)) / sim for t, n in counts.items()}})))
"""


def driving_probe(window, drive_topic=None, linear=0.0, angular=0.0, topics=(), settle=2.0):
    """The DRIVING_PROBE script for ros.python: prints {"rtf": ..., "rates": {topic: per sim s}}."""
    return DRIVING_PROBE.format(window=window, drive_topic=drive_topic, linear=linear, angular=angular,
                                topics=list(topics), settle=settle)


def cpu_seconds(pid):
    with open('/proc/%d/stat' % pid) as f:
        fields = f.read().rsplit(')', 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf('SC_CLK_TCK')


# Started before roslaunch: polls list_controllers every 20 ms and prints when all five run (wall clock).
STARTUP_PROBE = """
import json, time, rospy
from controller_manager_msgs.srv import ListControllers
name = '/tianracer/controller_manager/list_controllers'
while True:
    try:
        rospy.wait_for_service(name, 0.02)
        states = [c.state for c in rospy.ServiceProxy(name, ListControllers)().controller]
        if states.count('running') == {count}:
            break
    except (rospy.ROSException, rospy.ServiceException):
        pass
    time.sleep(0.02)
print(json.dumps(time.time()))
"""


def one_round(real_time_factor):
    with tempfile.TemporaryDirectory() as workdir:
        ros = RosSystem(workdir)
        try:
            args = ['roslaunch', 'tianracer_description', 'tianracer_world.launch', 'gui:=false']
            if real_time_factor is not None:
                args.append('real_time_factor:=%g' % real_time_factor)
            probe = ros.start([sys.executable, '-c', STARTUP_PROBE.format(count=CONTROLLERS)], 'startup_probe')
            time.sleep(1.5)  # the probe's Python and rospy are loaded before the clock starts
            start = time.time()
            launch = ros.start(args, 'launch')
            assert probe.wait(60) == 0, probe.log()
            startup = float(probe.log().strip().splitlines()[-1]) - start
            pid = plant_pid(launch.pid)
            window = WINDOW if real_time_factor is None else FAST_WINDOW
            cpu_before, wall_before = cpu_seconds(pid), time.monotonic()
            load = ros.python(driving_probe(window, '/tianracer/cmd_vel', 1.0, 0.5,
                                            [('/scan', 'sensor_msgs.msg', 'LaserScan')]), timeout=window + 60)
            cpu = (cpu_seconds(pid) - cpu_before) / (time.monotonic() - wall_before)
            return dict(startup=startup, rtf=load['rtf'], cpu=cpu, scans_per_sim_s=load['rates'].get('/scan', 0.0))
        finally:
            ros.close()


def main():
    real_time, fastest = [], []
    for r in range(ROUNDS):
        real_time.append(one_round(None))
        fastest.append(one_round(0))
        print('round %d: launch->running %.2f s, rtf %.4f, plant cpu %.1f %% of a core, scans %.1f/sim s; '
              'fastest rtf %.1f (cpu %.0f %%)' % (r + 1, real_time[-1]['startup'], real_time[-1]['rtf'],
                                                  100 * real_time[-1]['cpu'], real_time[-1]['scans_per_sim_s'],
                                                  fastest[-1]['rtf'], 100 * fastest[-1]['cpu']), flush=True)

    def median(rounds, key):
        return statistics.median(r[key] for r in rounds)
    print('\nmedians over %d rounds (targets in brackets):' % ROUNDS)
    print('  launch -> five controllers running  %.2f s      [<= 3 s]' % median(real_time + fastest, 'startup'))
    print('  real time factor over %g s          %.4f       [0.99 .. 1.01]' % (WINDOW, median(real_time, 'rtf')))
    print('  plant CPU at real time              %.1f %% of a core [< 20 %%]' % (100 * median(real_time, 'cpu')))
    print('  fastest real time factor            %.1f        [>= 20]' % median(fastest, 'rtf'))


if __name__ == '__main__':
    main()
