#!/usr/bin/python3
"""Drives the Tianracer on a figure-eight through /tianracer/cmd_vel and reports how well it follows.

Two loops, left then right, at ~out_speed m/s and the steering angle ~steering (cmdvel2gazebo's
default angular mode). The commanded path is the ideal bicycle model of the same commands; the
actual path comes from /tianracer/odom. Prints the figures and writes a PNG with both paths and the
last lidar scan (~plot, default figure_eight.png).
"""
import math

import rospy
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry
from sensor_msgs.msg import LaserScan

from tianracer_description.path_metrics import circle_radius
from tianracer_description.urdf_geometry import UrdfModel, ackermann_geometry


def longest_run(samples):
    """The (x, y) of the longest run of consecutive samples (x, y, steady) that are all steady."""
    best, run = [], []
    for x, y, steady in samples:
        if not steady:
            run = []
            continue
        run.append((x, y))
        if len(run) > len(best):
            best = run
    return best


def yaw(q):
    return math.atan2(2 * (q.w * q.z + q.x * q.y), 1 - 2 * (q.y * q.y + q.z * q.z))


class FigureEight:
    def __init__(self):
        rospy.init_node('figure_eight')
        self.speed = rospy.get_param('~speed', 0.8)
        self.steering = rospy.get_param('~steering', 0.35)
        self.plot = rospy.get_param('~plot', 'figure_eight.png')
        description = rospy.get_param('robot_description')
        self.geometry = ackermann_geometry(description)
        self.model = UrdfModel(description)
        self.odom = []
        self.scan = None
        rospy.Subscriber('/tianracer/odom', Odometry, self.on_odom)
        rospy.Subscriber('/scan', LaserScan, self.on_scan)
        self.cmd = rospy.Publisher('/tianracer/cmd_vel', Twist, queue_size=1)

    def on_odom(self, m):
        p = m.pose.pose
        self.odom.append((m.header.stamp.to_sec(), p.position.x, p.position.y, yaw(p.orientation),
                          m.twist.twist.angular.z))

    def on_scan(self, m):
        self.scan = m

    def run(self):
        rospy.wait_for_message('/tianracer/odom', Odometry, timeout=30)
        radius = self.geometry.wheelbase / math.tan(self.steering)
        loop_time = 2 * math.pi * radius / self.speed
        start_pose = self.odom[-1]
        commanded = [(start_pose[1], start_pose[2])]
        x, y, heading = start_pose[1], start_pose[2], start_pose[3]
        turn_rate = self.speed * math.tan(self.steering) / self.geometry.wheelbase
        rate = rospy.Rate(10)
        loops = []
        for steering in (self.steering, -self.steering):
            begin = rospy.get_rostime().to_sec()
            while not rospy.is_shutdown() and rospy.get_rostime().to_sec() - begin < loop_time:
                twist = Twist()
                twist.linear.x, twist.angular.z = self.speed, steering
                self.cmd.publish(twist)
                rate.sleep()
                dt = 0.1
                heading += self.speed * math.tan(steering) / self.geometry.wheelbase * dt
                x += self.speed * math.cos(heading) * dt
                y += self.speed * math.sin(heading) * dt
                commanded.append((x, y))
            # The loop is where the car turned at its steady rate for this steering, read from its own
            # odometry: a command that reached the plant late (a loaded machine, a fast pace) shifts
            # the loop in simulated time, not what it is. Its longest unbroken stretch: a command
            # later than cmdvel2gazebo's 0.2 s timeout (50 ms of wall time at four times real time)
            # stops the car with its wheels straight, and the turn after it is an arc about another
            # centre.
            sign = 1.0 if steering > 0 else -1.0
            loops.append(longest_run([(px, py, abs(sign * rate_z - turn_rate) < 0.1 * turn_rate)
                                      for t, px, py, _, rate_z in self.odom if begin <= t <= begin + loop_time + 3.0]))
        self.cmd.publish(Twist())
        rospy.sleep(1.0)

        actual = [(px, py) for t, px, py, _, _ in self.odom if t >= start_pose[0]]
        length = sum(math.hypot(b[0] - a[0], b[1] - a[1]) for a, b in zip(actual, actual[1:]))
        end_error = math.hypot(actual[-1][0] - start_pose[1], actual[-1][1] - start_pose[2])
        print('figure-eight at %.2f m/s, steering %.3f rad: ideal radius %.3f m' % (self.speed, self.steering, radius))
        for name, points in zip(('left loop', 'right loop'), loops):
            measured = circle_radius(points)
            print('  %s: radius %.3f m (error %+.1f %%)' % (name, measured, 100 * (measured / radius - 1)))
        print('  path length %.2f m (ideal %.2f m); back at the start within %.3f m'
              % (length, 2 * 2 * math.pi * radius, end_error))
        self.write_plot(commanded, actual)
        print('  plot: %s' % self.plot)

    def write_plot(self, commanded, actual):
        import matplotlib
        matplotlib.use('Agg')
        import matplotlib.pyplot as plt
        figure, axes = plt.subplots(figsize=(7, 7))
        axes.plot(*zip(*commanded), '--', label='commanded (bicycle model)')
        axes.plot(*zip(*actual), label='actual (odom)')
        if self.scan is not None and self.odom:
            _, px, py, heading, _ = self.odom[-1]
            # the lidar's place on the car, from the URDF (the scan is in its frame)
            joint = next(j for j, e in self.model.joints.items() if e.find('child').get('link') == self.scan.header.frame_id)
            ox, oy = self.model.joint_position(joint)[:2]
            lx = px + ox * math.cos(heading) - oy * math.sin(heading)
            ly = py + ox * math.sin(heading) + oy * math.cos(heading)
            points = [(lx + r * math.cos(heading + self.scan.angle_min + i * self.scan.angle_increment),
                       ly + r * math.sin(heading + self.scan.angle_min + i * self.scan.angle_increment))
                      for i, r in enumerate(self.scan.ranges) if math.isfinite(r)]
            if points:
                axes.scatter(*zip(*points), s=2, c='k', label='last lidar scan')
        axes.set_aspect('equal')
        axes.set_xlabel('x (m)')
        axes.set_ylabel('y (m)')
        axes.set_title('Tianracer figure-eight')
        axes.legend(loc='lower left')
        figure.savefig(self.plot, dpi=100)


if __name__ == '__main__':
    try:
        FigureEight().run()
    except rospy.ROSInterruptException:
        pass
