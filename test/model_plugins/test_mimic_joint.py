"""The mimic joint plugin on the plant, through its Python module (gripper.urdf): the second finger
follows the first, which gazebo_ros_control moves through a position transmission."""
import pytest

from plant_helpers import gripper, logged, spawned


def grip(params=None, **plugin):
    world, robot = spawned(gripper(**plugin), name='gripper', namespace='/', params=params)
    robot.set_command('finger_joint', 0.03)
    world.step(500)
    return world, robot


def test_the_mimic_joint_follows_by_position():
    world, robot = grip()
    assert robot.model_plugins == ['mimic_finger']
    assert robot.joint_state('finger_mimic_joint')[0] == pytest.approx(0.03, abs=1e-6)
    world, robot = grip(multiplier=0.5, offset=0.005)
    assert robot.joint_state('finger_mimic_joint')[0] == pytest.approx(0.02, abs=1e-6), '0.03 * 0.5 + 0.005'
    world, robot = grip(multiplier=-1.0, sensitiveness=0.05)
    assert robot.joint_state('finger_mimic_joint')[0] == pytest.approx(0.0, abs=1e-6), \
        'within sensitiveness of its target the plugin does nothing'


def test_the_mimic_joint_follows_by_effort_with_has_pid():
    gains = {'gazebo_ros_control': {'pid_gains': {'finger_mimic_joint': {'p': 100.0, 'i': 0.0, 'd': 4.0}}}}
    world, robot = grip(params=gains, hasPID='')
    assert robot.joint_state('finger_mimic_joint')[0] == pytest.approx(0.03, abs=1e-4)
    world, robot = grip(params=gains, hasPID='', maxEffort=0.01)
    # 10 mN on 50 g: 0.2 m/s^2, 25 mm in 0.5 s at most.
    assert 0.0 < robot.joint_state('finger_mimic_joint')[0] < 0.026
    world, robot = grip(params={'my_gains': {'p': 100.0, 'd': 4.0}}, hasPID='my_gains')
    assert robot.joint_state('finger_mimic_joint')[0] == pytest.approx(0.03, abs=1e-4), '<hasPID> names the gains'
    world, robot = grip(hasPID='')
    assert robot.model_plugins == []
    assert any("plugin 'mimic_finger' (libroboticsgroup_gazebo_mimic_joint_plugin.so) <hasPID>: No p gain specified "
               "for pid.  Namespace: /gazebo_ros_control/pid_gains/finger_mimic_joint" in m for m in logged(world, 'ERROR'))


def test_both_mimic_plugin_files_and_their_errors():
    urdf = gripper().replace('libroboticsgroup_gazebo_mimic', 'libroboticsgroup_upatras_gazebo_mimic')
    world, robot = spawned(urdf, name='gripper', namespace='/')
    assert robot.model_plugins == ['mimic_finger'], 'the newer file name'
    world, robot = spawned(gripper(mimicJoint=None), name='gripper')
    assert any("plugin 'mimic_finger' (libroboticsgroup_gazebo_mimic_joint_plugin.so) has no <mimicJoint>" in m
               for m in logged(world, 'ERROR'))
    world, robot = spawned(gripper(mimicJoint='finger_joint'), name='gripper')
    assert any("names joint 'finger_joint', which a gazebo_ros_control transmission drives already" in m
               for m in logged(world, 'ERROR'))
    world, robot = spawned(gripper(joint='thumb'), name='gripper')
    assert robot.model_plugins == [] and any("<joint> names 'thumb', which is no movable joint of 'gripper'" in m
                                             for m in logged(world, 'ERROR'))
