"""What a Gazebo sensor plugin costs the plant, counted: gazebo_ros_pkgs' laser as the plant's own
(src/node/sensor_plugins/gazebo_ros_laser.cpp over the plant's lidar) against the same plugin built
from upstream's source against the plant's Gazebo 11 API (`--upstream-lib DIR`: a folder holding
upstream's libgazebo_ros_laser.so, which the plant then loads in place of its own, over Gazebo's
RaySensor, its LaserScanStamped messages and the transport, as Gazebo loads the file it finds).

The world: a box with a 360-ray lidar (0.12 to 3.5 m, turtlebot3's) scanning at 100 Hz (1 ms steps),
in a ring of walls; /scan subscribed by one rospy subscriber. The node runs STEPS_SHORT and
STEPS_LONG iterations (gzserver's --iters) from a paused start once the subscriber is connected,
under `valgrind --tool=callgrind`, counting the instructions of the threads that do a scan's work:
the simulation's step and publishing (RosPlant::stepAndPublish: the plant's own plugin converts and
publishes there), the transport's delivery (TopicManager::run: upstream's OnScan converts there) and
upstream's publishing queue (PubMultiQueue::spin: it publishes there); roscpp's own threads, which
do the same socket work for both and run by the wall clock, are not counted. (Ir(long) - Ir(short))
per scan, less the same world's with the lidar but no plugin (the box awake, the lidar idle), is
the cost of a scan. Instruction counts do not depend on the machine's load.

    python3 bench/gazebo_sensor_plugin_cost.py [--upstream-lib DIR]
"""
import argparse
import os
import re
import sys
import tempfile
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), os.pardir, 'test', 'helpers'))
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from gazebo_plugin_cost import plant_executable  # noqa: E402
from ros_harness import RosSystem  # noqa: E402

STEPS_SHORT, STEPS_LONG = 200, 1200
STEPS_PER_SCAN = 10
COUNTED = ['*RosPlant::stepAndPublish*', '*TopicManager::run*', '*PubMultiQueue::spin*']

LASER = '''
        <sensor type="ray" name="lidar"><pose>0 0 0.1 0 0 0</pose><update_rate>100</update_rate>
          <ray><scan><horizontal><samples>360</samples><min_angle>0</min_angle><max_angle>6.28</max_angle></horizontal>
            </scan><range><min>0.12</min><max>3.5</max></range></ray>
          %s
        </sensor>'''
LASER_PLUGIN = ('<plugin name="lidar" filename="libgazebo_ros_laser.so"><topicName>scan</topicName>'
                '<frameName>base_scan</frameName></plugin>')
SUBSCRIBER = '''
import rospy
from sensor_msgs.msg import LaserScan
rospy.init_node('scan_counter')
rospy.Subscriber('/scan', LaserScan, lambda m: None, queue_size=1)
rospy.spin()
'''


def world(sensor):
    walls = ''.join('''
    <model name="wall%d"><static>true</static><pose>%s 0.5 0 0 %s</pose><link name="l">
      <collision name="c"><geometry><box><size>0.1 4 1</size></box></geometry></collision></link></model>'''
                    % (i, xy, yaw) for i, (xy, yaw) in enumerate([('2 0', 0), ('-2 0', 0), ('0 2', 1.5708),
                                                                   ('0 -2', 1.5708)]))
    return '''<?xml version="1.0"?>
<sdf version="1.6">
  <world name="default">
    <physics type="ode"><max_step_size>0.001</max_step_size><real_time_update_rate>0</real_time_update_rate></physics>
    <model name="probe"><pose>0 0 0.1 0 0 0</pose>
      <link name="base">
        <inertial><mass>1.0</mass><inertia><ixx>0.01</ixx><iyy>0.01</iyy><izz>0.01</izz></inertia></inertial>
        <collision name="c"><geometry><box><size>0.2 0.2 0.2</size></box></geometry></collision>%s
      </link>
    </model>%s
  </world>
</sdf>
''' % (sensor, walls)


def instructions(world_file, steps, plugin_path, workdir, subscribed):
    """Ir of the counted threads' work in the node running `steps` iterations of `world_file`."""
    os.makedirs(workdir)
    out = os.path.join(workdir, 'callgrind.out')
    ros = RosSystem(workdir)
    try:
        ros.env['GAZEBO_PLUGIN_PATH'] = plugin_path
        ros.set_param('/use_sim_time', True)
        if subscribed:
            ros.start(['/usr/bin/python3', '-c', SUBSCRIBER], 'subscriber')
        # --fair-sched: the threads take turns as on a machine, so the transport hands a scan over
        # before the next comes (valgrind's default lets one thread run long)
        node = ros.start(['valgrind', '--tool=callgrind', '--fair-sched=yes', '--callgrind-out-file=' + out] +
                         ['--toggle-collect=' + f for f in COUNTED] +
                         [plant_executable(), '_world_name:=' + world_file, '_paused:=true',
                          '_iterations:=%d' % steps, '_lockstep:=false'], 'plant')
        ros.service('/gazebo/get_world_properties', wait=True, timeout=300)
        if subscribed:
            ros.wait_until(lambda: 'scan_counter' in ros.run(['rostopic', 'info', '/scan']).stdout, 120,
                           '/scan subscribed')
        ros.run(['rosservice', 'call', '/gazebo/unpause_physics'], timeout=120)
        if node.popen.wait(timeout=3600) != 0:
            raise SystemExit('gazebo_sensor_plugin_cost: the node exited %d:\n%s' % (node.popen.returncode,
                                                                                    node.log()[-3000:]))
    finally:
        ros.close()
    with open(out) as f:
        return int(re.search(r'^summary: (\d+)', f.read(), re.M).group(1))


def per_scan(world_text, plugin_path, workdir, label, subscribed=True):
    path = os.path.join(workdir, label + '.world')
    with open(path, 'w') as f:
        f.write(world_text)
    short = instructions(path, STEPS_SHORT, plugin_path, os.path.join(workdir, label + '_short'), subscribed)
    long = instructions(path, STEPS_LONG, plugin_path, os.path.join(workdir, label + '_long'), subscribed)
    return (long - short) / (STEPS_LONG - STEPS_SHORT) * STEPS_PER_SCAN


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument('--upstream-lib', metavar='DIR',
                        help="a folder with upstream's libgazebo_ros_laser.so built against the plant's API")
    options = parser.parse_args()
    started = time.time()
    with tempfile.TemporaryDirectory() as workdir:
        idle = per_scan(world(LASER % ''), '', workdir, 'idle', subscribed=False)
        own = per_scan(world(LASER % LASER_PLUGIN), '', workdir, 'own')
        print('instructions per scan (10 steps): the world with an idle lidar %.0f; with the plant\'s own laser %.0f '
              '(+%.0f)' % (idle, own, own - idle))
        if options.upstream_lib:
            library = os.path.join(os.path.abspath(options.upstream_lib), 'libgazebo_ros_laser.so')
            if not os.path.isfile(library):
                raise SystemExit('gazebo_sensor_plugin_cost: no %s' % library)
            upstream = per_scan(world(LASER % LASER_PLUGIN), os.path.abspath(options.upstream_lib), workdir,
                                'upstream')
            print('upstream\'s laser on the Gazebo API %.0f (+%.0f): %.2fx the plant\'s own plugin'
                  % (upstream, upstream - idle, (upstream - idle) / max(own - idle, 1.0)))
    print('(%.0f s)' % (time.time() - started))


if __name__ == '__main__':
    main()
