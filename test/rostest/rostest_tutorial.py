#!/usr/bin/python3
"""The tutorial's checks as a rostest node (test/tutorial.test): the sensors, the state and the clock
publish at their rates (hztest's rule, in simulated time), the five controllers run, the tutorial's
Twist drives the circle of the car's geometry, and the dead man's switch stops the car."""
import math
import os
import sys
import unittest

import rospy
import rostest
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry
from std_msgs.msg import Float64

from tianracer_description.ackermann import max_ideal_steering
from tianracer_description.path_metrics import circle_radius
from tianracer_description.tianracer import TUTORIAL_CONTROLLERS
from tianracer_description.urdf_geometry import ackermann_geometry

sys.path.insert(0, os.path.join(os.path.dirname(os.path.realpath(__file__)), os.pardir, 'helpers'))
from ros_harness import TopicRates, running_controllers  # noqa: E402  (the test harness, test/helpers)


# topic: (Hz, allowed error), as the tutorial's world and YAML set them
RATES = {'/scan': (40.0, 2.0), '/tianracer/joint_states': (50.0, 2.5), '/tianracer/odom': (50.0, 2.5),
         '/clock': (100.0, 5.0), '/camera/image_raw': (30.0, 3.0)}


def sim_now():
    return rospy.get_rostime().to_sec()


def wait_sim(seconds):
    end = sim_now() + seconds
    while not rospy.is_shutdown() and sim_now() < end:
        rospy.sleep(0.01)


class Tutorial(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('tutorial_checks', anonymous=True)
        cls.odom, cls.wheel = [], []
        rospy.Subscriber('/tianracer/odom', Odometry, lambda m: cls.odom.append(
            (m.header.stamp.to_sec(), m.pose.pose.position.x, m.pose.pose.position.y, m.twist.twist.linear.x)))
        rospy.Subscriber('/tianracer/rear_left_velocity_controller/command', Float64,
                         lambda m: cls.wheel.append((sim_now(), m.data)))
        cls.cmd_vel = rospy.Publisher('/tianracer/cmd_vel', Twist, queue_size=1)
        cls.rates = TopicRates(RATES)
        cls.running = running_controllers('/tianracer', len(TUTORIAL_CONTROLLERS))

    def test_0_the_topics_publish_at_their_rates(self):
        rates = self.rates.measure(3.0)
        for topic, (hz, error) in RATES.items():
            self.assertIsNotNone(rates[topic], topic + ': fewer than two messages')
            self.assertLessEqual(abs(rates[topic] - hz), error, '%s at %.2f Hz, not %g +- %g' % (topic, rates[topic], hz, error))

    def test_1_the_five_controllers_run(self):
        self.assertEqual(sorted(self.running), sorted(TUTORIAL_CONTROLLERS))

    def test_2_the_tutorials_twist_drives_the_circle_and_the_dead_mans_switch_stops_the_car(self):
        twist = Twist()
        twist.linear.x, twist.angular.z = 1.0, 1.0   # the tutorial's rostopic pub line, at 10 Hz
        start = sim_now()
        rate = rospy.Rate(10)
        while sim_now() - start < 8.0 and not rospy.is_shutdown():
            self.cmd_vel.publish(twist)
            last_twist = sim_now()
            rate.sleep()
        circle = [(x, y) for t, x, y, v in self.odom if start + 3.0 <= t <= last_twist]
        wait_sim(2.0)

        g = ackermann_geometry(rospy.get_param('/robot_description'))
        expected = g.wheelbase / math.tan(max_ideal_steering(g.wheelbase, g.front_track, g.max_steer))
        self.assertGreater(len(circle), 100)
        radius = circle_radius(circle)
        self.assertLess(abs(radius - expected) / expected, 0.05, 'radius %.3f m, geometry %.3f m' % (radius, expected))
        stopped = [t for t, value in self.wheel if t > last_twist and value == 0.0]
        self.assertTrue(stopped, 'the wheels were never commanded to 0')
        # ~timeout 0.2 s + one 10 Hz cycle of the converter + the two messages' delivery when loaded
        self.assertLessEqual(stopped[0] - last_twist, 0.35, "the dead man's switch took %.2f s" % (stopped[0] - last_twist))
        self.assertLess(abs(self.odom[-1][3]), 0.05, 'the car stops')


if __name__ == '__main__':
    rostest.rosrun('tianracer_description', 'tutorial_drive', Tutorial, sys.argv)
