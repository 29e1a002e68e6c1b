"""A camera robot in a furnished room at real time, through the ROS node (`make bench`, and by hand).

The world is bench/house_world.py's (generated: 100+ textured meshes, ~270k triangles, six point
lights and a spot, no ground plane), or any world given with --world (AWS RoboMaker's bookstore, by
hand: never copied into the repository). The robot is a turtlebot3 waffle_pi's sensor set on the
test fixture diff_bot.urdf: its 360-ray lidar at 5 Hz, IMU and diff drive, and a 640 x 480 camera at
30 Hz with waffle_pi's field of view (1.085595 rad) and gazebo_ros_camera, spawned by spawn_model into
the world started by gazebo_ros's empty_world.launch (as Gazebo runs: out of lockstep, a late frame
skipped), at rest.

Per round, each case with its own ROS master, side by side:
  camera and lidar   /camera/rgb/image_raw, /scan, /imu, /odom subscribed
  lidar only         the same but the camera (unsubscribed: it renders nothing)
The plant process's user + system CPU over WINDOW s of wall time as a share of one core, the real
time factor, and the camera's frames per simulated second. Medians of ROUNDS rounds; the camera's own
share is the first case minus the second of the same round.

    bench/house_bench.py [--world FILE --pose X Y Z YAW] [--rounds N] [--window S]
"""
import argparse
import os
import platform
import statistics
import sys
import tempfile
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), os.pardir, 'test', 'helpers'))
from house_world import write_house  # noqa: E402  (beside this file)
from plant_helpers import DIFF_BOT  # noqa: E402  (the test fixture is the benchmark's robot)
from ros_plant_bench import cpu_seconds, driving_probe, plant_pid  # noqa: E402
from ros_harness import RosSystem, spawn_urdf, start_plant  # noqa: E402

ROUNDS = 3
WINDOW = 30.0
HOUSE_POSE = (-6.3, 0.9, 0.0, 0.0)  # x y z yaw: the aisle between the tables, looking down the room

# turtlebot3_waffle_pi's camera (its gazebo.xacro): 640 x 480 at 30 Hz, 1.085595 rad, gazebo_ros_camera
CAMERA = """  <link name="camera_link"/>
  <joint name="camera_joint" type="fixed"><parent link="base_link"/><child link="camera_link"/>
    <origin xyz="0.064 -0.065 0.094"/></joint>
  <gazebo reference="camera_link">
    <sensor type="camera" name="camera">
      <always_on>true</always_on><update_rate>30</update_rate>
      <camera name="picam"><horizontal_fov>1.085595</horizontal_fov>
        <image><width>640</width><height>480</height><format>R8G8B8</format></image>
        <clip><near>0.03</near><far>100</far></clip></camera>
      <plugin name="camera_controller" filename="libgazebo_ros_camera.so"><alwaysOn>true</alwaysOn>
        <updateRate>30.0</updateRate><cameraName>camera</cameraName><imageTopicName>rgb/image_raw</imageTopicName>
        <cameraInfoTopicName>rgb/camera_info</cameraInfoTopicName><frameName>camera_rgb_optical_frame</frameName>
      </plugin>
    </sensor>
  </gazebo>
</robot>"""

BASE_TOPICS = [('/scan', 'sensor_msgs.msg', 'LaserScan'), ('/imu', 'sensor_msgs.msg', 'Imu'),
               ('/odom', 'nav_msgs.msg', 'Odometry')]
IMAGE = ('/camera/rgb/image_raw', 'sensor_msgs.msg', 'Image')


def camera_robot():
    with open(DIFF_BOT) as f:
        return f.read().replace('</robot>', CAMERA)


def one_case(world, pose, topics, window):
    """The plant's CPU share and the probe's figures with the camera robot at `pose`, `topics` subscribed."""
    with tempfile.TemporaryDirectory() as workdir:
        ros = RosSystem(workdir)
        try:
            plant = start_plant(ros, os.path.abspath(world))
            path = os.path.join(workdir, 'robot.urdf')
            with open(path, 'w') as f:
                f.write(camera_robot())
            ros.run(['rosparam', 'set', '/robot_description', '--textfile', path])
            x, y, z, yaw = pose
            spawn_urdf(ros, plant, '/robot_description', 'waffle_pi_like', '-x', str(x), '-y', str(y), '-z', str(z),
                       '-Y', str(yaw))
            pid = plant_pid(plant.pid)
            probe_script = driving_probe(window, topics=topics, settle=5.0)
            cpu_before, wall_before = cpu_seconds(pid), time.monotonic()
            probe = ros.python(probe_script, timeout=window + 90)
            probe['cpu'] = (cpu_seconds(pid) - cpu_before) / (time.monotonic() - wall_before)
            log = plant.log()
            probe['skipped'] = sum(1 for line in log.splitlines() if 'frames skipped' in line)
            return probe
        finally:
            ros.close()


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('--world', help='a world file (default: the generated house)')
    parser.add_argument('--pose', nargs=4, type=float, metavar=('X', 'Y', 'Z', 'YAW'), help='where the robot stands')
    parser.add_argument('--rounds', type=int, default=ROUNDS)
    parser.add_argument('--window', type=float, default=WINDOW)
    options = parser.parse_args()
    cpu_model = next((line.split(':', 1)[1].strip() for line in open('/proc/cpuinfo') if line.startswith('model name')),
                     platform.processor())
    with tempfile.TemporaryDirectory() as house:
        if options.world:
            world, pose = options.world, tuple(options.pose or (0, 0, 0, 0))
            print('world %s, the robot at %s' % (world, pose))
        else:
            size = write_house(house)
            world, pose = os.path.join(house, 'house.world'), HOUSE_POSE
            print('world: the generated house, %(models)d static models with textured meshes, %(triangles)d '
                  'triangles, %(lights)d lights' % size)
        print('CPU: %s, %d cores; %d rounds of %g s at real time; robot: 640 x 480 camera at 30 Hz, 360-ray lidar '
              'at 5 Hz, IMU, diff drive' % (cpu_model, os.cpu_count(), options.rounds, options.window), flush=True)
        cases = {'camera and lidar': BASE_TOPICS + [IMAGE], 'lidar only': BASE_TOPICS}
        results = {name: [] for name in cases}
        for r in range(options.rounds):
            for name, topics in cases.items():
                results[name].append(one_case(world, pose, topics, options.window))
                last = results[name][-1]
                print('round %d %-17s plant CPU %5.1f %% of a core, rtf %.4f, camera %.1f frames/sim s%s' % (
                    r + 1, name, 100 * last['cpu'], last['rtf'], last['rates'].get(IMAGE[0], 0.0),
                    ', skipped frames reported' if last['skipped'] else ''), flush=True)

    def median(name, key='cpu'):
        return statistics.median(x[key] for x in results[name])
    camera_share = statistics.median(a['cpu'] - b['cpu'] for a, b in zip(results['camera and lidar'],
                                                                          results['lidar only']))
    frames = statistics.median(x['rates'].get(IMAGE[0], 0.0) for x in results['camera and lidar'])
    print('\nmedians over %d rounds:' % options.rounds)
    for name in cases:
        print('  %-17s plant CPU %5.1f %% of a core, rtf %.4f' % (name, 100 * median(name), median(name, 'rtf')))
    print('  the camera: %.1f %% of a core, %.1f frames per simulated second (30 asked)' % (100 * camera_share, frames))
    print('  goal: rtf >= 0.99 and the plant under 50 % of a core with the camera and the lidar subscribed')


if __name__ == '__main__':
    main()
