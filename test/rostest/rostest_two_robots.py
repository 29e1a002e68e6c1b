#!/usr/bin/python3
"""Two cars in one world (test/two_robots.test): each publishes its joint states at 50 Hz (hztest's rule,
in simulated time) and runs the tutorial's five controllers in its own namespace, and commanding one
car's wheels moves that car only."""
import math
import os
import sys
import time
import unittest

import rospy
import rostest
from nav_msgs.msg import Odometry
from std_msgs.msg import Float64

from tianracer_description.tianracer import REAR_WHEEL_CONTROLLERS, TUTORIAL_CONTROLLERS

sys.path.insert(0, os.path.join(os.path.dirname(os.path.realpath(__file__)), os.pardir, 'helpers'))
from ros_harness import TopicRates, connected_publisher, running_controllers  # noqa: E402  (the test harness, test/helpers)

CARS = ('/car1/tianracer', '/car2/tianracer')


class TwoRobots(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('two_robots_checks', anonymous=True)
        cls.position = {}
        for car in CARS:
            rospy.Subscriber(car + '/odom', Odometry, lambda m, car=car: cls.position.__setitem__(
                car, (m.pose.pose.position.x, m.pose.pose.position.y)))
        cls.rates = TopicRates([car + '/joint_states' for car in CARS])

    def test_0_each_car_publishes_its_joint_states_at_50_hz(self):
        for topic, rate in self.rates.measure(3.0).items():
            self.assertIsNotNone(rate, topic + ': fewer than two messages')
            self.assertLessEqual(abs(rate - 50.0), 2.5, '%s at %.2f Hz' % (topic, rate))

    def test_1_each_car_runs_the_five_controllers_in_its_namespace(self):
        for car in CARS:
            self.assertEqual(sorted(running_controllers(car, len(TUTORIAL_CONTROLLERS))), sorted(TUTORIAL_CONTROLLERS), car)

    def test_2_commanding_one_car_moves_that_car_only(self):
        for car in CARS:
            running_controllers(car, len(TUTORIAL_CONTROLLERS))
        # the controllers connected, so that the 2 s measured start with the command
        publishers = [connected_publisher(CARS[0] + '/' + c + '/command', Float64, queue_size=1, latch=True)
                      for c in REAR_WHEEL_CONTROLLERS]
        while not all(car in self.position for car in CARS):
            time.sleep(0.05)
        start = dict(self.position)
        for publisher in publishers:
            publisher.publish(Float64(31.25))  # 1 m/s
        end = rospy.get_rostime().to_sec() + 2.0
        while rospy.get_rostime().to_sec() < end and not rospy.is_shutdown():
            time.sleep(0.05)
        moved = {car: math.dist(start[car], self.position[car]) for car in CARS}
        self.assertGreater(moved[CARS[0]], 1.0, moved)
        self.assertLess(moved[CARS[1]], 0.01, moved)


if __name__ == '__main__':
    rostest.rosrun('tianracer_description', 'two_robots', TwoRobots, sys.argv)
