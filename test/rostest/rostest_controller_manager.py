#!/usr/bin/python3
"""The controller manager's six services through rospy (test/controller_manager.test): load, list,
switch with its strictness rules, resource conflicts, unload, reload_controller_libraries."""
import sys
import unittest

import rospy
import rostest
from controller_manager_msgs.srv import (ListControllers, ListControllerTypes, LoadController,
                                         ReloadControllerLibraries, SwitchController, UnloadController)

NS = '/tianracer/controller_manager/'
BEST_EFFORT, STRICT = SwitchController._request_class.BEST_EFFORT, SwitchController._request_class.STRICT


class ControllerManagerServices(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node('controller_manager_checks', anonymous=True)
        services = dict(load=LoadController, unload=UnloadController, switch=SwitchController,
                        list=ListControllers, types=ListControllerTypes, reload=ReloadControllerLibraries)
        names = dict(load='load_controller', unload='unload_controller', switch='switch_controller',
                     list='list_controllers', types='list_controller_types', reload='reload_controller_libraries')
        for key, kind in services.items():
            rospy.wait_for_service(NS + names[key], 60.0)
            setattr(cls, key, rospy.ServiceProxy(NS + names[key], kind))

    def states(self):
        return {c.name: c.state for c in self.list().controller}

    def switch_ok(self, start=(), stop=(), strictness=STRICT):
        return self.switch(start_controllers=list(start), stop_controllers=list(stop), strictness=strictness,
                           start_asap=False, timeout=5.0).ok

    def test_1_load_and_its_errors(self):
        self.assertTrue(self.load('joint_state_controller').ok)
        self.assertFalse(self.load('joint_state_controller').ok, 'already loaded')
        self.assertFalse(self.load('not_configured').ok, 'no type on the parameter server')
        self.assertFalse(self.load('unknown_type').ok, 'a type that does not exist')
        self.assertEqual(self.states(), {'joint_state_controller': 'initialized'})
        types = self.types()
        self.assertIn('velocity_controllers/JointVelocityController', types.types)
        self.assertEqual(set(types.base_classes), {'controller_interface::ControllerBase'})

    def test_2_switch_strictness(self):
        self.assertFalse(self.switch_ok(start=['ghost']), 'STRICT: an unknown name fails')
        self.assertTrue(self.switch_ok(start=['ghost'], strictness=BEST_EFFORT), 'BEST_EFFORT skips it')
        self.assertTrue(self.switch_ok(start=['joint_state_controller']))
        self.assertEqual(self.states()['joint_state_controller'], 'running')
        self.assertFalse(self.switch_ok(start=['joint_state_controller']), 'STRICT: already running')
        self.assertFalse(self.switch_ok(start=['joint_state_controller'], stop=['joint_state_controller'],
                                        strictness=BEST_EFFORT), 'running and in both lists')
        # ros_control 0.20 with a stopped controller in both lists: STRICT refuses (a double stop),
        # BEST_EFFORT starts it.
        self.assertTrue(self.switch_ok(stop=['joint_state_controller']))
        self.assertFalse(self.switch_ok(start=['joint_state_controller'], stop=['joint_state_controller']),
                         'STRICT: stopped and in both lists')
        self.assertEqual(self.states()['joint_state_controller'], 'stopped')
        self.assertTrue(self.switch_ok(start=['joint_state_controller'], stop=['joint_state_controller'],
                                       strictness=BEST_EFFORT), 'BEST_EFFORT: stopped and in both lists')
        self.assertEqual(self.states()['joint_state_controller'], 'running')

    def test_3_resource_conflicts(self):
        self.assertTrue(self.load('rear_right_velocity_controller').ok)
        self.assertTrue(self.load('second_right_wheel').ok)
        self.assertFalse(self.switch_ok(start=['rear_right_velocity_controller', 'second_right_wheel']),
                         'two controllers claiming right_rear_wheel_joint')
        self.assertTrue(self.switch_ok(start=['rear_right_velocity_controller']))
        claimed = {c.name: [(r.hardware_interface, list(r.resources)) for r in c.claimed_resources]
                   for c in self.list().controller}
        self.assertEqual(claimed['rear_right_velocity_controller'],
                         [('hardware_interface::VelocityJointInterface', ['right_rear_wheel_joint'])])

    def test_4_unload_and_reload(self):
        self.assertFalse(self.unload('rear_right_velocity_controller').ok, 'still running')
        self.assertTrue(self.switch_ok(stop=['rear_right_velocity_controller']))
        self.assertTrue(self.unload('rear_right_velocity_controller').ok)
        self.assertFalse(self.unload('rear_right_velocity_controller').ok, 'no longer loaded')
        self.assertFalse(self.reload(force_kill=False).ok, 'controllers are loaded')
        self.assertTrue(self.reload(force_kill=True).ok)
        self.assertEqual(self.states(), {})


if __name__ == '__main__':
    rostest.rosrun('tianracer_description', 'controller_manager_services', ControllerManagerServices, sys.argv)
