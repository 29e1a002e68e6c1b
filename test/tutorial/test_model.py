"""The car's model: xacro through the compat package, parsed by urdfdom, with the tutorial's joints,
the geometry its converter assumes, transmissions, the gazebo_ros_control block and the sensors."""
import math
import os
import subprocess
import xml.etree.ElementTree as ET

import numpy as np
import pytest
import yaml

from tianracer_description.tianracer import PACKAGE, run_xacro
from tianracer_description.urdf_geometry import UrdfModel, _rpy_matrix, ackermann_geometry

WHEEL_JOINTS = ['left_rear_wheel_joint', 'right_rear_wheel_joint',
                'left_front_wheel_joint', 'right_front_wheel_joint']
HINGE_JOINTS = ['left_steering_hinge_joint', 'right_steering_hinge_joint']


@pytest.fixture(scope='module')
def robot(urdf_xml):
    return ET.fromstring(urdf_xml)


@pytest.fixture(scope='module')
def model(urdf_xml):
    return UrdfModel(urdf_xml)


def gazebo_block(robot, link):
    blocks = [g for g in robot.findall('gazebo') if g.get('reference') == link]
    assert blocks, 'no <gazebo reference="%s"> block' % link
    return blocks


def sensor(robot, link, sensor_type):
    for block in gazebo_block(robot, link):
        for s in block.findall('sensor'):
            if s.get('type') == sensor_type:
                return s
    pytest.fail('no <sensor type="%s"> in the gazebo block of %s' % (sensor_type, link))


def test_launch_file_xacro_command_gives_robot_description():
    """The tutorial's <param command="$(find xacro)/xacro --inorder ..."/> line, evaluated by roslaunch."""
    launch = os.path.join(PACKAGE, 'test', 'launch', 'robot_description.launch')
    result = subprocess.run(['roslaunch', '--dump-params', launch], capture_output=True, text=True)
    assert result.returncode == 0, result.stderr
    description = yaml.safe_load(result.stdout)['/robot_description']
    assert ET.fromstring(description).get('name') == 'tianracer'


def test_urdfdom_parses_the_model(urdf_xml, tmp_path):
    urdf = tmp_path / 'tianracer.urdf'
    urdf.write_text(urdf_xml)
    result = subprocess.run(['check_urdf', str(urdf)], capture_output=True, text=True)
    assert result.returncode == 0, result.stdout + result.stderr
    assert 'Successfully Parsed XML' in result.stdout
    assert 'root Link: base_footprint' in result.stdout


def test_xacro_find_of_a_missing_package_names_it(tmp_path):
    broken = tmp_path / 'broken.xacro'
    broken.write_text('<robot name="x" xmlns:xacro="http://www.ros.org/wiki/xacro">'
                      '<xacro:include filename="$(find no_such_package_here)/x.xacro"/></robot>')
    result = run_xacro(str(broken))
    assert result.returncode != 0
    assert 'no_such_package_here' in result.stderr


def test_root_and_body_links(model):
    assert model._joint_of_child.get('base_footprint') is None, 'base_footprint must be the root'
    assert model.joint('base_footprint_joint').find('child').get('link') == 'base_link'
    assert model.joint('chassis_joint').find('parent').get('link') == 'base_link'


@pytest.mark.parametrize('joint', WHEEL_JOINTS)
def test_wheel_joints_are_continuous_about_y(model, joint):
    assert model.joint(joint).get('type') == 'continuous'
    assert np.allclose([float(v) for v in model.joint(joint).find('axis').get('xyz').split()], [0, 1, 0])


@pytest.mark.parametrize('joint', HINGE_JOINTS)
def test_steering_hinges_are_revolute_about_z_within_06(model, joint):
    assert model.joint(joint).get('type') == 'revolute'
    assert np.allclose([float(v) for v in model.joint(joint).find('axis').get('xyz').split()], [0, 0, 1])
    assert model.joint_limits(joint) == pytest.approx((-0.6, 0.6))
    limit = model.joint(joint).find('limit')
    assert float(limit.get('effort')) > 0 and float(limit.get('velocity')) > 0


def test_rear_wheels_have_effort_and_velocity_limits(model):
    for joint in WHEEL_JOINTS[:2]:
        limit = model.joint(joint).find('limit')
        assert float(limit.get('effort')) > 0 and float(limit.get('velocity')) > 0


def test_geometry_is_the_tutorial_converters(urdf_xml):
    geometry = ackermann_geometry(urdf_xml)
    assert geometry.wheelbase == pytest.approx(0.261, abs=1e-9)
    assert geometry.rear_track == pytest.approx(0.1632, abs=1e-9)
    assert geometry.front_track == pytest.approx(0.1632, abs=1e-9)
    assert geometry.wheel_radius == pytest.approx(0.032, abs=1e-9)
    assert geometry.max_steer == pytest.approx(0.6)


def test_front_wheels_are_centred_on_their_hinge_axes(model):
    for side in ('left', 'right'):
        wheel = model.joint_position(side + '_front_wheel_joint')
        hinge = model.joint_position(side + '_steering_hinge_joint')
        assert wheel[:2] == pytest.approx(hinge[:2], abs=1e-12)


def test_wheels_touch_the_ground_at_rest(model):
    """Every wheel centre is one wheel radius above base_footprint (the ground)."""
    for joint in WHEEL_JOINTS:
        assert model.joint_position(joint)[2] == pytest.approx(model.wheel_radius(joint), abs=1e-12)


def test_transmissions_give_the_interfaces_the_tutorials_controllers_need(robot):
    interfaces = {}
    for transmission in robot.findall('transmission'):
        assert transmission.find('type').text == 'transmission_interface/SimpleTransmission'
        joint = transmission.find('joint')
        interfaces[joint.get('name')] = joint.find('hardwareInterface').text
    assert interfaces == {
        'left_rear_wheel_joint': 'hardware_interface/VelocityJointInterface',
        'right_rear_wheel_joint': 'hardware_interface/VelocityJointInterface',
        'left_steering_hinge_joint': 'hardware_interface/EffortJointInterface',
        'right_steering_hinge_joint': 'hardware_interface/EffortJointInterface',
        # passive: never commanded, there for their joint states (TF of the front wheels)
        'left_front_wheel_joint': 'hardware_interface/EffortJointInterface',
        'right_front_wheel_joint': 'hardware_interface/EffortJointInterface',
    }


def test_gazebo_ros_control_plugin_namespace(robot):
    plugins = [p for g in robot.findall('gazebo') if g.get('reference') is None
               for p in g.findall('plugin') if p.get('filename') == 'libgazebo_ros_control.so']
    assert len(plugins) == 1
    assert plugins[0].find('robotNamespace').text == '/tianracer'


@pytest.mark.parametrize('link', ['left_rear_wheel', 'right_rear_wheel', 'left_front_wheel', 'right_front_wheel'])
def test_wheels_have_friction_tags(robot, link):
    block = gazebo_block(robot, link)[0]
    assert float(block.find('mu1').text) > 0.5 and float(block.find('mu2').text) > 0.5


def test_lidar_is_the_tianracers(robot, model):
    lidar = sensor(robot, 'laser_link', 'ray')
    assert float(lidar.find('update_rate').text) == 40
    horizontal = lidar.find('ray/scan/horizontal')
    assert int(horizontal.find('samples').text) == 1081
    assert float(horizontal.find('min_angle').text) == -2.356
    assert float(horizontal.find('max_angle').text) == 2.356
    assert float(lidar.find('ray/range/min').text) == 0.1
    assert float(lidar.find('ray/range/max').text) == 10.0
    assert lidar.find('ray/noise/type').text == 'gaussian'
    assert float(lidar.find('ray/noise/stddev').text) == 0.01
    plugin = lidar.find('plugin')
    assert plugin.get('filename') == 'libgazebo_ros_laser.so'
    assert plugin.find('topicName').text == 'scan'
    assert plugin.find('frameName').text in model.links


def test_colour_camera_block(robot, model):
    camera = sensor(robot, 'camera_link', 'camera')
    plugin = camera.find('plugin')
    assert plugin.get('filename') == 'libgazebo_ros_camera.so'
    for tag in ('cameraName', 'imageTopicName', 'cameraInfoTopicName'):
        assert plugin.find(tag).text
    assert plugin.find('frameName').text in model.links
    width, height = (int(camera.find('camera/image/' + t).text) for t in ('width', 'height'))
    rays_per_second = width * height * float(camera.find('update_rate').text)
    assert 0 < rays_per_second <= 1e6, 'colour camera too large to ray-cast on 2 cores'
    assert 0 < float(camera.find('camera/horizontal_fov').text) < math.pi


def test_depth_camera_block(robot, model):
    depth = sensor(robot, 'depth_camera_link', 'depth')
    plugin = depth.find('plugin')
    assert plugin.get('filename') == 'libgazebo_ros_openni_kinect.so'
    for tag in ('cameraName', 'imageTopicName', 'cameraInfoTopicName', 'depthImageTopicName',
                'depthImageCameraInfoTopicName', 'pointCloudTopicName'):
        assert plugin.find(tag).text
    assert plugin.find('frameName').text in model.links
    width, height = (int(depth.find('camera/image/' + t).text) for t in ('width', 'height'))
    assert 0 < width * height * float(depth.find('update_rate').text) <= 0.5e6


def test_optical_frames_follow_the_image_convention(model):
    """z forward, x right, y down: the optical z axis is the camera link's x axis."""
    for camera in ('camera', 'depth_camera'):
        optical = model.joint_frame(camera + '_optical_joint')[:3, :3]
        body = model.joint_frame(camera + '_joint')[:3, :3]
        in_body = body.T @ optical
        assert in_body[:, 2] == pytest.approx([1, 0, 0], abs=1e-12)   # optical z = forward
        assert in_body[:, 0] == pytest.approx([0, -1, 0], abs=1e-12)  # optical x = right
        assert in_body[:, 1] == pytest.approx([0, 0, -1], abs=1e-12)  # optical y = down


def test_total_mass_is_a_1_10_cars(robot):
    total = sum(float(link.find('inertial/mass').get('value'))
                for link in robot.findall('link') if link.find('inertial') is not None)
    assert 2.0 <= total <= 3.5


def _solid_inertia(geometry, mass):
    """Inertia about the centre of a solid shape, in the shape's own frame."""
    if geometry.tag == 'box':
        x, y, z = (float(v) for v in geometry.get('size').split())
        return mass / 12.0 * np.diag([y*y + z*z, x*x + z*z, x*x + y*y])
    if geometry.tag == 'cylinder':
        r, h = float(geometry.get('radius')), float(geometry.get('length'))
        across = mass * (3*r*r + h*h) / 12.0
        return np.diag([across, across, mass * r*r / 2.0])
    if geometry.tag == 'sphere':
        r = float(geometry.get('radius'))
        return np.eye(3) * 2.0 * mass * r*r / 5.0
    raise AssertionError('unexpected shape %s' % geometry.tag)


def test_inertias_are_those_of_each_links_shape(robot):
    """Each inertia is that of a solid of the link's collision (or visual) shape and mass."""
    checked = 0
    for link in robot.findall('link'):
        inertial = link.find('inertial')
        if inertial is None:
            continue
        shape = link.find('collision') if link.find('collision') is not None else link.find('visual')
        geometry = list(shape.find('geometry'))[0]
        origin = shape.find('origin')
        rpy = [float(v) for v in origin.get('rpy').split()] if origin is not None else [0, 0, 0]
        rotation = _rpy_matrix(*rpy)
        mass = float(inertial.find('mass').get('value'))
        expected = rotation @ _solid_inertia(geometry, mass) @ rotation.T
        i = inertial.find('inertia').attrib
        actual = np.array([[float(i['ixx']), float(i['ixy']), float(i['ixz'])],
                           [float(i['ixy']), float(i['iyy']), float(i['iyz'])],
                           [float(i['ixz']), float(i['iyz']), float(i['izz'])]])
        assert actual == pytest.approx(expected, rel=1e-9, abs=1e-15), link.get('name')
        checked += 1
    assert checked >= 9
