"""The tutorial's controller YAML: it loads, names the five controllers with the tutorial's types,
joints and gains, the pid_gains of both rear wheels, and every controller's joint exists in the
URDF with the hardware interface its type needs."""
import xml.etree.ElementTree as ET

import pytest

# The tutorial's controllers under /tianracer, exactly as printed.
TUTORIAL_CONTROLLERS = {
    'joint_state_controller': ('joint_state_controller/JointStateController', None, None),
    'rear_right_velocity_controller': ('velocity_controllers/JointVelocityController',
                                       'right_rear_wheel_joint', {'p': 100.0, 'i': 0.01, 'd': 10.0}),
    'rear_left_velocity_controller': ('velocity_controllers/JointVelocityController',
                                      'left_rear_wheel_joint', {'p': 100.0, 'i': 0.01, 'd': 10.0}),
    'front_right_steering_position_controller': ('effort_controllers/JointPositionController',
                                                 'right_steering_hinge_joint', {'p': 4.0, 'i': 2.0, 'd': 1.0}),
    'front_left_steering_position_controller': ('effort_controllers/JointPositionController',
                                                'left_steering_hinge_joint', {'p': 4.0, 'i': 2.0, 'd': 1.0}),
}

# The joint interface each ros_controllers package's controllers claim.
INTERFACE_OF_PACKAGE = {
    'velocity_controllers': 'hardware_interface/VelocityJointInterface',
    'effort_controllers': 'hardware_interface/EffortJointInterface',
    'position_controllers': 'hardware_interface/PositionJointInterface',
}


@pytest.fixture(scope='module')
def tianracer(control_config):
    assert list(control_config) == ['tianracer']
    return control_config['tianracer']


def test_names_the_tutorials_five_controllers(tianracer):
    controllers = {name: c for name, c in tianracer.items() if name != 'gazebo_ros_control'}
    assert list(controllers) == list(TUTORIAL_CONTROLLERS)
    for name, (ctrl_type, joint, pid) in TUTORIAL_CONTROLLERS.items():
        assert controllers[name]['type'] == ctrl_type
        assert controllers[name].get('joint') == joint
        assert controllers[name].get('pid') == pid


def test_joint_state_controller_publish_rate(tianracer):
    assert tianracer['joint_state_controller']['publish_rate'] == 50


def test_pid_gains_for_both_rear_wheels(tianracer):
    assert tianracer['gazebo_ros_control']['pid_gains'] == {
        'right_rear_wheel_joint': {'p': 100.0, 'i': 0.5, 'd': 0.0},
        'left_rear_wheel_joint': {'p': 100.0, 'i': 0.5, 'd': 0.0},
    }


def test_each_controllers_joint_has_the_interface_its_type_needs(tianracer, urdf_xml):
    robot = ET.fromstring(urdf_xml)
    joints = {j.get('name') for j in robot.findall('joint')}
    interfaces = {t.find('joint').get('name'): t.find('joint/hardwareInterface').text
                  for t in robot.findall('transmission')}
    for name, controller in tianracer.items():
        if 'joint' not in controller:
            continue
        assert controller['joint'] in joints, name
        package = controller['type'].split('/')[0]
        assert interfaces.get(controller['joint']) == INTERFACE_OF_PACKAGE[package], name


def test_pid_gains_name_velocity_joints(tianracer, urdf_xml):
    robot = ET.fromstring(urdf_xml)
    interfaces = {t.find('joint').get('name'): t.find('joint/hardwareInterface').text
                  for t in robot.findall('transmission')}
    for joint in tianracer['gazebo_ros_control']['pid_gains']:
        assert interfaces.get(joint) == 'hardware_interface/VelocityJointInterface', joint
