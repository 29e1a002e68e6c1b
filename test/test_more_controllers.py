"""The controller types beyond the tutorial's (docs/interfaces.md section 12) on the car, through the
plant's Python module (no ROS master): the JointGroup controllers on the rear wheels and the
steering hinges."""
import pytest

from plant_helpers import make_world
from tianracer_description.tianracer import REAR_WHEEL_JOINTS, STEERING_JOINTS
from tianracer_description.urdf_geometry import ackermann_geometry


@pytest.fixture
def world(control_config):
    return make_world(control_config)


def test_joint_group_controllers_drive_the_wheels_and_hold_the_hinges(world, urdf_xml):
    steering_gains = {joint: {'pid': {'p': 4.0, 'd': 1.0}} for joint in STEERING_JOINTS}
    world.load_params({'tianracer': {
        'wheels': {'type': 'velocity_controllers/JointGroupVelocityController', 'joints': list(REAR_WHEEL_JOINTS)},
        'steering': dict(steering_gains, type='effort_controllers/JointGroupPositionController',
                         joints=list(STEERING_JOINTS))}})
    robot = world.spawn(urdf_xml, 'tianracer')
    manager = robot.controller_manager
    assert manager.spawn(['wheels', 'steering']) == (['wheels', 'steering'], True)
    world.step(2)  # started in the control loop: a command before that is reset by starting()
    claimed = {c['name']: c['claimed_resources'] for c in manager.list()}
    assert claimed['steering'] == [{'hardware_interface': 'hardware_interface::EffortJointInterface',
                                    'resources': list(STEERING_JOINTS)}]
    wheel_speed = 1.0 / ackermann_geometry(urdf_xml).wheel_radius   # 1 m/s
    targets = (0.25, 0.3)
    assert manager.command('wheels', [wheel_speed, wheel_speed])
    assert manager.command('steering', list(targets))
    assert not manager.command('steering', [0.1]), 'one value for two joints'
    world.step(3000)
    for joint in REAR_WHEEL_JOINTS:
        assert robot.joint_state(joint)[1] == pytest.approx(wheel_speed, rel=0.02), joint
    for joint, target in zip(STEERING_JOINTS, targets):
        # p 4, d 1: a first-order lag of 0.25 s, settled after 3 s
        assert robot.joint_state(joint)[0] == pytest.approx(target, abs=0.005), joint
    assert any('Dimension of command (1) does not match number of joints (2)! Not executing!' in text
               for level, text in world.messages() if level == 'ERROR')
