#!/usr/bin/python3
"""The simulator's gazebo_ros services (test/simulator.test): pause and unpause stop and restart
simulated time, reset_simulation takes it back to 0, spawn_urdf_model and delete_model add and
remove a car with gazebo_ros's success flags and status messages."""
import sys
import time
import unittest

import rospy
import rostest
from geometry_msgs.msg import Pose
from rosgraph_msgs.msg import Clock
from std_srvs.srv import Empty
from gazebo_msgs.srv import DeleteModel, SpawnModel

GAZEBO = '/gazebo/'


class SimulatorServices(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('simulator_checks', anonymous=True)
        cls.clock = []
        rospy.Subscriber('/clock', Clock, lambda m: cls.clock.append(m.clock.to_sec()))
        for name, kind in (('pause_physics', Empty), ('unpause_physics', Empty), ('reset_simulation', Empty),
                           ('spawn_urdf_model', SpawnModel), ('delete_model', DeleteModel)):
            rospy.wait_for_service(GAZEBO + name, 60.0)
            setattr(cls, name, rospy.ServiceProxy(GAZEBO + name, kind))

    def latest_clock_after(self, wall_seconds):
        time.sleep(wall_seconds)
        return self.clock[-1]

    def clock_shows(self, condition, wall_timeout=20.0):
        """Whether the latest /clock meets condition within wall_timeout (generous: the machine may be loaded)."""
        end = time.monotonic() + wall_timeout
        while time.monotonic() < end:
            if self.clock and condition(self.clock[-1]):
                return True
            time.sleep(0.02)
        return False

    def clock_reaches(self, sim_seconds):
        return self.clock_shows(lambda now: now >= sim_seconds)

    def spawn(self, name):
        pose = Pose()
        pose.orientation.w = 1.0
        return self.spawn_urdf_model(model_name=name, model_xml=rospy.get_param('/robot_description'),
                                     robot_namespace='', initial_pose=pose, reference_frame='world')

    def test_1_pause_stops_simulated_time_and_unpause_restarts_it(self):
        self.assertTrue(self.clock_reaches(0.1))
        self.pause_physics()
        paused_at = self.latest_clock_after(0.3)
        self.assertEqual(self.latest_clock_after(1.0), paused_at)
        self.unpause_physics()
        self.assertTrue(self.clock_reaches(paused_at + 0.5))

    def test_2_reset_simulation_takes_time_back_to_zero(self):
        self.assertTrue(self.clock_reaches(1.0))
        self.reset_simulation()
        self.assertTrue(self.clock_shows(lambda now: now < 1.0), self.clock[-1])

    def test_3_spawn_and_delete_with_their_flags(self):
        first = self.spawn('car')
        self.assertTrue(first.success, first.status_message)
        self.assertEqual(first.status_message, 'SpawnModel: Successfully spawned entity')
        again = self.spawn('car')
        self.assertFalse(again.success)
        self.assertEqual(again.status_message, 'SpawnModel: Failure - entity already exists.')
        self.assertTrue(self.delete_model(model_name='car').success)
        gone = self.delete_model(model_name='car')
        self.assertFalse(gone.success)
        self.assertEqual(gone.status_message, 'DeleteModel: model does not exist')


if __name__ == '__main__':
    rostest.rosrun('tianracer_description', 'simulator_services', SimulatorServices, sys.argv)
