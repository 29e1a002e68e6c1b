"""Helpers for the tests that drive the plant through its Python module (no ROS master)."""
import math
import os
import struct

import numpy as np

from suite_paths import FIXTURES
from tianracer_description import bullet_plant
from tianracer_description.tianracer import STEERING_JOINTS


# Names one of Embree's kernels' instruction sets for the worlds made after it is set
# (include/bullet_plant/ray_kernels.h); the embree_isa fixture (conftest.py) sets it.
ISA_VARIABLE = 'TIANRACER_EMBREE_ISA'
ISAS_RUN = set()  # the ISAs tests of this session ran on, for the closing summary


def embree_isas():
    """The instruction sets of Embree's kernels this CPU runs, narrowest first (sse2 ... avx512)."""
    return bullet_plant.embree_isas()


# The Gazebo-style package the tests ship (test/fixtures/gazebo_pkg) and its mesh track world.

TRACK_WORLD = os.path.join(FIXTURES, 'gazebo_pkg', 'worlds', 'track.world')


def find_fixture_packages(monkeypatch):
    """The fixture packages on ROS_PACKAGE_PATH: model://race_track resolves through their export."""
    monkeypatch.setenv('ROS_PACKAGE_PATH', FIXTURES + os.pathsep + os.environ['ROS_PACKAGE_PATH'])


def sdf_world(models='', step=0.001):
    """SDF text of a world with a ground plane, the given <model> elements and physics step."""
    return f"""<?xml version="1.0"?>
<sdf version="1.6"><world name="test">
  <include><uri>model://ground_plane</uri></include>
  <physics type="ode"><max_step_size>{step}</max_step_size><real_time_factor>1</real_time_factor></physics>
  {models}
</world></sdf>"""


def box_model(name, size, xyz, yaw=0.0, visual=False):
    """A static box; with `visual`, seen by cameras and gpu_ray lidars too (they see visuals)."""
    sx, sy, sz = size
    x, y, z = xyz
    box = f'<geometry><box><size>{sx} {sy} {sz}</size></box></geometry>'
    seen = f'<visual name="visual">{box}</visual>' if visual else ''
    return f"""<model name="{name}"><static>true</static><pose>{x} {y} {z} 0 0 {yaw}</pose>
  <link name="link"><collision name="collision">{box}</collision>{seen}</link>
</model>"""


def make_world(control_config, sdf=None):
    world = bullet_plant.World.from_sdf(sdf) if sdf else bullet_plant.World()
    world.echo = False
    world.load_params(control_config)
    return world


def hold_steering(robot, angle=0.0):
    """Hold both steering hinges with the tutorial's steering gains (p 4, d 1) as an implicit servo."""
    for joint in STEERING_JOINTS:
        robot.set_effort_law(joint, stiffness=4.0, position_target=angle, damping=1.0)


def logged(world, level, clear=False):
    """The texts of the world's log messages at `level` ('ERROR', 'WARN', 'INFO'); `clear` empties the
    log, so that a later call sees only what came after."""
    return [text for at, text in world.messages(clear=clear) if at == level]


def yaw_of(pose):
    qx, qy, qz, qw = pose[3:7]
    return math.atan2(2 * (qw * qz + qx * qy), 1 - 2 * (qy * qy + qz * qz))


def all_state(world, robot):
    """Every number the plant reports for a robot, for finiteness and determinism checks."""
    values = list(robot.base_pose())
    linear, angular = robot.base_twist()
    values += list(linear) + list(angular)
    for joint in robot.joint_names:
        values += list(robot.joint_state(joint))
    return np.array(values + [world.time])


def box_stl(path, low, high):
    """A box from corner `low` to corner `high` as a binary STL (12 triangles); returns path."""
    (x0, y0, z0), (x1, y1, z1) = low, high
    corners = [(x, y, z) for x in (x0, x1) for y in (y0, y1) for z in (z0, z1)]
    faces = [(0, 1, 3), (0, 3, 2), (4, 6, 7), (4, 7, 5), (0, 4, 5), (0, 5, 1),
             (2, 3, 7), (2, 7, 6), (0, 2, 6), (0, 6, 4), (1, 5, 7), (1, 7, 3)]
    with open(path, 'wb') as f:
        f.write(b'\0' * 80 + struct.pack('<I', len(faces)))
        for face in faces:
            f.write(struct.pack('<3f', 0, 0, 0))
            for i in face:
                f.write(struct.pack('<3f', *corners[i]))
            f.write(b'\0\0')
    return path


# A robot with one plugin of each kind the plant reads, parameters set away from their defaults, and
# one plugin it does not simulate (test_sensor_plugins.py, test_sensor_plugins_ros.py).
PLUGIN_URDF = """<robot name="probe">
  <link name="base_footprint"/>
  <link name="scanner"><collision><geometry><box size="0.05 0.05 0.05"/></geometry></collision></link>
  <joint name="scanner_joint" type="fixed"><parent link="base_footprint"/><child link="scanner"/>
    <origin xyz="0 0 0.1"/></joint>
  <gazebo reference="scanner">
    <sensor type="ray" name="front_laser"><update_rate>10</update_rate>
      <ray><scan><horizontal><samples>5</samples><min_angle>-1</min_angle><max_angle>1</max_angle></horizontal></scan>
        <range><min>0.1</min><max>5</max></range></ray>
      <plugin name="laser" filename="libgazebo_ros_gpu_laser.so">
        <topicName>/shared/laser</topicName><frameName>/scanner</frameName></plugin>
    </sensor>
    <sensor type="camera" name="eye"><update_rate>30</update_rate>
      <camera><horizontal_fov>1.0</horizontal_fov><image><width>8</width><height>6</height></image></camera>
      <plugin name="eye_controller" filename="libgazebo_ros_camera.so">
        <robotNamespace>/other</robotNamespace><cameraName>front</cameraName><imageTopicName>rgb</imageTopicName>
        <frameName>eye_frame</frameName><updateRate>5</updateRate></plugin>
    </sensor>
    <sensor type="ray" name="sonar"><update_rate>10</update_rate>
      <ray><scan><horizontal><samples>1</samples></horizontal></scan><range><min>0.1</min><max>2</max></range></ray>
      <plugin name="sonar_plugin" filename="libacme_sonar_plugin.so"><topicName>sonar</topicName></plugin>
    </sensor>
  </gazebo>
  <gazebo>
    <plugin name="truth" filename="libgazebo_ros_p3d.so">
      <bodyName>base_footprint</bodyName><topicName>ground_truth</topicName><updateRate>50</updateRate></plugin>
    <plugin name="body_imu" filename="libgazebo_ros_imu.so">
      <bodyName>scanner</bodyName><topicName>imu_raw</topicName><updateRate>200</updateRate></plugin>
  </gazebo>
</robot>"""


def with_plugin_params(urdf, plugin, **params):
    """URDF text with the parameters of its <plugin name="plugin"> replaced or added (None removes one)."""
    start = urdf.index(f'<plugin name="{plugin}"')
    end = urdf.index('</plugin>', start)
    block = urdf[start:end]
    for key, value in params.items():
        element = '' if value is None else f'<{key}>{value}</{key}>'
        if f'<{key}>' in block:
            block = block[:block.index(f'<{key}>')] + element + block[block.index(f'</{key}>') + len(key) + 3:]
        else:
            block += element
    return urdf[:start] + block + urdf[end:]


def fixture_urdf(name, plugin, **params):
    """The text of test/fixtures/urdf/<name>.urdf with its <plugin name="plugin">'s parameters changed."""
    with open(os.path.join(FIXTURES, 'urdf', name + '.urdf')) as f:
        return with_plugin_params(f.read(), plugin, **params)


# Small robots written for the tests, one per gazebo_plugins drive, as robot makers configure them.
DIFF_BOT = os.path.join(FIXTURES, 'urdf', 'diff_bot.urdf')
# The fixtures' wheels, as their URDFs write them: diff_bot's and skid_bot's radius and separation.
DIFF_RADIUS, DIFF_SEPARATION = 0.035, 0.30
SKID_RADIUS, SKID_SEPARATION = 0.04, 0.26


def spawned(urdf=None, namespace='', name='diff_bot', params=None):
    """A world with one robot (the diff_bot unless `urdf` is given) settled on the ground for 0.2 s."""
    world = bullet_plant.World()
    world.echo = False
    if params:
        world.load_params(params)
    robot = world.spawn(urdf or diff_bot(), name, namespace=namespace)
    world.step(200)  # settle on the ground
    return world, robot


def diff_bot(**params):
    """diff_bot.urdf with its diff drive plugin's parameters replaced, added or (None) removed."""
    return fixture_urdf('diff_bot', 'diff_drive', **params)


def skid_bot(**params):
    """skid_bot.urdf (four wheels, as agilex limo and rosbot) with its skid steer plugin's parameters changed."""
    return fixture_urdf('skid_bot', 'skid_steer_drive', **params)


def planar_bot(**params):
    """planar_bot.urdf (a holonomic base, as agilex bunker) with its planar_move plugin's parameters changed."""
    return fixture_urdf('planar_bot', 'planar_move', **params)


def force_based_bot(**params):
    """planar_bot.urdf moved by hector's force_based_move instead of planar_move (gains for its 5 kg
    and 0.1 kg m^2, skids of friction 0.05), its parameters changed as the others'."""
    urdf = planar_bot()
    start, end = urdf.index('<plugin name="planar_move"'), urdf.index('</plugin>') + len('</plugin>')
    urdf = urdf[:start] + """<plugin name="force_based_move" filename="libgazebo_ros_force_based_move.so">
      <commandTopic>cmd_vel</commandTopic><odometryTopic>odom</odometryTopic><odometryFrame>odom</odometryFrame>
      <odometryRate>25.0</odometryRate><robotBaseFrame>base_footprint</robotBaseFrame>
      <x_velocity_p_gain>2000</x_velocity_p_gain><y_velocity_p_gain>2000</y_velocity_p_gain>
      <yaw_velocity_p_gain>50</yaw_velocity_p_gain></plugin>""" + urdf[end:]
    urdf = urdf.replace('<mu1>0.3</mu1><mu2>0.3</mu2>', '<mu1>0.05</mu1><mu2>0.05</mu2>')
    return with_plugin_params(urdf, 'force_based_move', **params)


def force_bot(**params):
    """planar_bot.urdf pushed by gazebo_plugins' force plugin (name 'push', Wrench on 'force' to
    base_link) instead of planar_move, its parameters changed as the others'."""
    urdf = planar_bot()
    start, end = urdf.index('<plugin name="planar_move"'), urdf.index('</plugin>') + len('</plugin>')
    block = '<plugin name="push" filename="libgazebo_ros_force.so"><bodyName>base_link</bodyName>' \
            '<topicName>force</topicName></plugin>'
    return with_plugin_params(urdf[:start] + block + urdf[end:], 'push', **params)


def f3d_bot(**params):
    """force_bot with gazebo_plugins' f3d (name 'f3d', WrenchStamped on 'force_truth') reporting
    base_link after the push, its parameters changed as the others'."""
    urdf = force_bot()
    end = urdf.index('</plugin>', urdf.index('<plugin name="push"')) + len('</plugin>')
    block = '<plugin name="f3d" filename="libgazebo_ros_f3d.so"><bodyName>base_link</bodyName>' \
            '<topicName>force_truth</topicName></plugin>'
    return with_plugin_params(urdf[:end] + block + urdf[end:], 'f3d', **params)


def tricycle_bot(**params):
    """tricycle_bot.urdf (a front wheel steered and driven, two free rear wheels) with its tricycle
    drive plugin's parameters changed."""
    return fixture_urdf('tricycle_bot', 'tricycle_drive', **params)


def gripper(**params):
    """gripper.urdf (two fingers, the second following the first, as turtlebot3_manipulation's) with
    its mimic joint plugin's parameters changed."""
    return fixture_urdf('gripper', 'mimic_finger', **params)


def diff_bot_with_gazebo_ros_control():
    """The same robot driven as Husky and Jackal are: velocity transmissions and gazebo_ros_control
    in /diff_bot instead of the diff drive plugin (DIFF_DRIVE_CONTROLLERS runs it)."""
    urdf = diff_bot()
    return urdf[:urdf.index('  <gazebo>\n    <plugin name="diff_drive"')] + """
  <transmission name="left_transmission"><type>transmission_interface/SimpleTransmission</type>
    <joint name="wheel_left_joint"><hardwareInterface>hardware_interface/VelocityJointInterface</hardwareInterface></joint>
    <actuator name="left_motor"><mechanicalReduction>1</mechanicalReduction></actuator></transmission>
  <transmission name="right_transmission"><type>transmission_interface/SimpleTransmission</type>
    <joint name="wheel_right_joint"><hardwareInterface>hardware_interface/VelocityJointInterface</hardwareInterface></joint>
    <actuator name="right_motor"><mechanicalReduction>1</mechanicalReduction></actuator></transmission>
  <gazebo><plugin name="gazebo_ros_control" filename="libgazebo_ros_control.so">
    <robotNamespace>/diff_bot</robotNamespace></plugin></gazebo>
</robot>"""


DIFF_DRIVE_CONTROLLERS = {'diff_bot': {
    'joint_state_controller': {'type': 'joint_state_controller/JointStateController', 'publish_rate': 50},
    'mobile_base_controller': {
        'type': 'diff_drive_controller/DiffDriveController', 'left_wheel': 'wheel_left_joint',
        'right_wheel': 'wheel_right_joint', 'publish_rate': 50, 'base_frame_id': 'base_footprint',
        'pose_covariance_diagonal': [0.001, 0.001, 1e6, 1e6, 1e6, 1000.0],
        'twist_covariance_diagonal': [0.001, 0.001, 1e6, 1e6, 1e6, 1000.0],
        'linear': {'x': {'has_acceleration_limits': True, 'max_acceleration': 1.0}}}}}


def mecanum_bot():
    """mecanum_bot.urdf: a Ridgeback-like base (four frictionless mecanum wheels on velocity
    transmissions, gazebo_ros_control in /mecanum_bot, hector's force-based move on cmd_vel)."""
    return fixture_urdf('mecanum_bot', 'force_based_move')


MECANUM_CONTROLLERS = {'mecanum_bot': {
    'joint_state_controller': {'type': 'joint_state_controller/JointStateController', 'publish_rate': 50},
    'mecanum_controller': {
        'type': 'mecanum_drive_controller/MecanumDriveController', 'front_left_wheel_joint': 'front_left_wheel',
        'back_left_wheel_joint': 'rear_left_wheel', 'front_right_wheel_joint': 'front_right_wheel',
        'back_right_wheel_joint': 'rear_right_wheel', 'publish_rate': 50, 'cmd_vel_timeout': 0.25,
        'base_frame_id': 'base_footprint',
        'pose_covariance_diagonal': [0.001, 0.001, 1e6, 1e6, 1e6, 0.03],
        'twist_covariance_diagonal': [0.001, 0.001, 0.001, 1e6, 1e6, 0.03]}}}


ARM_JOINTS = ['shoulder', 'elbow', 'wrist']


def arm(interface='Position'):
    """arm.urdf (shoulder, elbow, continuous wrist, fixed to the world) with its transmissions on
    hardware_interface/<interface>JointInterface."""
    with open(os.path.join(FIXTURES, 'urdf', 'arm.urdf')) as f:
        return f.read().replace('PositionJointInterface', interface + 'JointInterface')


def arm_controllers(kind='position_controllers', **arm_controller):
    """The /arm controllers as a UR or TIAGo configuration has them: joint_state_controller and a
    <kind>/JointTrajectoryController of the three joints (gains for the velocity and effort kinds),
    its parameters updated by `arm_controller`."""
    controller = {'type': kind + '/JointTrajectoryController', 'joints': ARM_JOINTS,
                  'constraints': {'goal_time': 0.5, 'stopped_velocity_tolerance': 0.05,
                                  'shoulder': {'trajectory': 0.2, 'goal': 0.02},
                                  'elbow': {'trajectory': 0.2, 'goal': 0.02}},
                  'state_publish_rate': 25, 'action_monitor_rate': 10}
    if kind == 'effort_controllers':
        controller['gains'] = {'shoulder': {'p': 100.0, 'd': 2.0, 'i': 0.0, 'i_clamp': 1.0},
                               'elbow': {'p': 400.0, 'd': 20.0, 'i': 0.0, 'i_clamp': 1.0},
                               'wrist': {'p': 2.0, 'd': 0.05, 'i': 0.0, 'i_clamp': 1.0}}
    if kind == 'velocity_controllers':
        controller['gains'] = {j: {'p': 20.0, 'd': 0.0, 'i': 0.0, 'i_clamp': 1.0} for j in ARM_JOINTS}
        controller['velocity_ff'] = {j: 1.0 for j in ARM_JOINTS}
    controller.update(arm_controller)
    return {'arm': {'joint_state_controller': {'type': 'joint_state_controller/JointStateController',
                                               'publish_rate': 50},
                    'arm_controller': controller}}


def start_arm(ros, tmp_path, kind='position_controllers', urdf=None):
    """The node on `ros` with the arm spawned under /arm and its joint_state_controller and
    arm_controller started by the spawner (the ROS tests of the arm's controllers and sensors)."""
    import yaml
    from ros_harness import spawn_with_controllers, start_plant
    (tmp_path / 'arm.urdf').write_text(urdf or arm({'position_controllers': 'Position', 'effort_controllers': 'Effort'}[kind]))
    (tmp_path / 'controllers.yaml').write_text(yaml.safe_dump(arm_controllers(kind)))
    plant = start_plant(ros)
    spawn_with_controllers(ros, plant, str(tmp_path / 'arm.urdf'), str(tmp_path / 'controllers.yaml'), '/arm', 'arm',
                           ['joint_state_controller', 'arm_controller'])
    return plant
