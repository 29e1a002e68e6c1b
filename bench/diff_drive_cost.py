"""What a turtlebot3-like robot costs the plant as a ROS node (`make bench-drive`).

The robot is test/fixtures/urdf/diff_bot.urdf: gazebo_plugins' diff drive, a 360-ray lidar at 5 Hz
(libgazebo_ros_laser.so) and the IMU model plugin at every step, as turtlebot3's URDF has them,
spawned by spawn_model into worlds/arena.world (walls and crates within the lidar's 3.5 m). A probe
subscribes to /scan, /imu, /odom, /joint_states and /tf and sends /cmd_vel at 10 Hz (a slow circle).

Per round, each with its own ROS master, in one run side by side:
  empty     the plant with the arena and no robot, at real time (its own cost: /clock, the world)
  robot     the same with the robot driving, every topic subscribed
  robot without the IMU plugin (the lidar and the diff drive only)
The plant process's user + system CPU over WINDOW s of wall time, as a share of one core, and the
real time factor. Medians of ROUNDS rounds; the robot's cost is robot minus empty of the same round.
"""
import os
import platform
import statistics
import sys
import tempfile
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), os.pardir, 'test', 'helpers'))
from plant_helpers import DIFF_BOT  # noqa: E402  (the test fixture is the benchmark's robot)
from ros_plant_bench import cpu_seconds, driving_probe, plant_pid  # noqa: E402
from ros_harness import RosSystem, spawn_urdf, start_plant  # noqa: E402

ROUNDS = 3
WINDOW = 30.0
ARENA = os.path.join(os.path.dirname(os.path.abspath(__file__)), os.pardir, 'worlds', 'arena.world')

ROBOT_TOPICS = [('/scan', 'sensor_msgs.msg', 'LaserScan'), ('/imu', 'sensor_msgs.msg', 'Imu'),
                ('/odom', 'nav_msgs.msg', 'Odometry'), ('/joint_states', 'sensor_msgs.msg', 'JointState'),
                ('/tf', 'tf2_msgs.msg', 'TFMessage')]


def without_imu(urdf):
    start = urdf.index('  <gazebo>\n    <plugin name="imu_plugin"')
    return urdf[:start] + urdf[urdf.index('</gazebo>', start) + len('</gazebo>\n'):]


def one_case(urdf):
    """CPU share of the plant and the probe's figures, with `urdf` spawned (None: no robot)."""
    with tempfile.TemporaryDirectory() as workdir:
        ros = RosSystem(workdir)
        try:
            plant = start_plant(ros, os.path.abspath(ARENA))
            if urdf:
                path = os.path.join(workdir, 'robot.urdf')
                with open(path, 'w') as f:
                    f.write(urdf)
                ros.run(['rosparam', 'set', '/robot_description', '--textfile', path])
                spawn_urdf(ros, plant, '/robot_description', 'diff_bot')
            else:
                ros.run(['rosservice', 'call', '--wait', '/gazebo/get_physics_properties'], timeout=60)
            pid = plant_pid(plant.pid)
            cpu_before, wall_before = cpu_seconds(pid), time.monotonic()
            probe_script = (driving_probe(WINDOW, '/cmd_vel', 0.15, 0.3, ROBOT_TOPICS, settle=3.0) if urdf
                            else driving_probe(WINDOW, settle=3.0))
            probe = ros.python(probe_script, timeout=WINDOW + 60)
            probe['cpu'] = (cpu_seconds(pid) - cpu_before) / (time.monotonic() - wall_before)
            return probe
        finally:
            ros.close()


def main():
    with open(DIFF_BOT) as f:
        urdf = f.read()
    cases = {'empty': None, 'robot': urdf, 'robot without IMU': without_imu(urdf)}
    results = {name: [] for name in cases}
    cpu_model = next((line.split(':', 1)[1].strip() for line in open('/proc/cpuinfo') if line.startswith('model name')),
                     platform.processor())
    print('CPU: %s, %d cores; %d rounds of %g s at real time' % (cpu_model, os.cpu_count(), ROUNDS, WINDOW), flush=True)
    for r in range(ROUNDS):
        for name, text in cases.items():
            results[name].append(one_case(text))
            last = results[name][-1]
            print('round %d %-18s plant CPU %5.1f %% of a core, rtf %.4f, topics/sim s: %s' % (
                r + 1, name, 100 * last['cpu'], last['rtf'],
                ', '.join('%s %.0f' % kv for kv in sorted(last['rates'].items()))), flush=True)

    def median(name, key='cpu'):
        return statistics.median(x[key] for x in results[name])

    def added(name):
        return statistics.median(x['cpu'] - e['cpu'] for x, e in zip(results[name], results['empty']))
    print('\nmedians over %d rounds:' % ROUNDS)
    print('  plant, arena and no robot            %5.1f %% of a core, rtf %.4f' % (100 * median('empty'), median('empty', 'rtf')))
    for name in ('robot', 'robot without IMU'):
        print('  plant with the %-21s %5.1f %% of a core (the robot: %+.1f %%), rtf %.4f' % (
            name, 100 * median(name), 100 * added(name), median(name, 'rtf')))
    print('  target: the robot (diff drive + 360-ray lidar at 5 Hz) under 5 % of one core at real time')


if __name__ == '__main__':
    main()
