"""Differential drives through the node: libgazebo_ros_diff_drive.so spawned by spawn_model (its '/'
namespace written into the plugin, as upstream's) drives on /cmd_vel and publishes /odom, odom ->
base_footprint on /tf and the wheels' joint_states, the only odometry of the robot; the same robot with
gazebo_ros_control and diff_drive_controller started by the spawner. A skid-steer robot (with hector's
GPS and IMU) and a holonomic base in one world, each in its spawn namespace; a gripper whose second finger follows the
first by the mimic joint plugin's PID, its gains from the parameter server. gazebo_ros_range's
sensor_msgs/Range against a wall at a known distance. A turtlebot3-like diff-drive robot and the
tutorial's car together in one world, each driven on its own topics. gazebo_ros_force's Wrench topic
and gazebo_ros_f3d's WrenchStamped of it."""
import os

import pytest
import yaml

from plant_helpers import (DIFF_BOT, DIFF_DRIVE_CONTROLLERS, box_model, diff_bot_with_gazebo_ros_control, f3d_bot,
                           gripper, planar_bot, sdf_world, skid_bot)
from tianracer_description.ros_harness import spawn_urdf, spawn_with_controllers, start_plant
from tianracer_description.tianracer import TUTORIAL_CONTROLLERS

pytestmark = pytest.mark.ros


def test_diff_drive_drives_on_cmd_vel_and_publishes_odometry_tf_and_joint_states(ros):
    plant = start_plant(ros)
    ros.run(['rosparam', 'set', '/robot_description', '--textfile', DIFF_BOT])
    spawn_urdf(ros, plant, '/robot_description', 'diff_bot')
    seen = ros.python("""
        import json, rospy, tf2_ros
        from gazebo_msgs.msg import ModelStates
        from geometry_msgs.msg import Twist
        from nav_msgs.msg import Odometry
        from sensor_msgs.msg import JointState
        from tianracer_description.ros_harness import connected_publisher
        rospy.init_node('probe')
        odometry = []
        rospy.Subscriber('/odom', Odometry, odometry.append)
        buffer = tf2_ros.Buffer()
        listener = tf2_ros.TransformListener(buffer)
        pub = connected_publisher('/cmd_vel', Twist, queue_size=1)
        twist = Twist()
        twist.linear.x, twist.angular.z = 0.2, 0.5
        start = rospy.wait_for_message('/gazebo/model_states', ModelStates, 30)
        for _ in range(30):
            pub.publish(twist)
            rospy.sleep(0.1)
        joints = rospy.wait_for_message('/joint_states', JointState, 10)
        states = rospy.wait_for_message('/gazebo/model_states', ModelStates, 10)
        last = odometry[-1]
        tf = buffer.lookup_transform('odom', 'base_footprint', rospy.Time(0), rospy.Duration(5))
        i = states.name.index('diff_bot')
        print(json.dumps({
            'frames': sorted({(m.header.frame_id, m.child_frame_id) for m in odometry}),
            'covariances': sorted({(m.pose.covariance[0], m.pose.covariance[35]) for m in odometry}),
            'linear': last.twist.twist.linear.x, 'angular': last.twist.twist.angular.z,
            'odom_xy': [last.pose.pose.position.x, last.pose.pose.position.y],
            'model_xy': [states.pose[i].position.x, states.pose[i].position.y],
            'start_xy': [start.pose[start.name.index('diff_bot')].position.x,
                         start.pose[start.name.index('diff_bot')].position.y],
            'tf_x': tf.transform.translation.x,
            'joints': list(joints.name), 'positions': len(joints.position)}))
    """, timeout=90)
    assert seen['frames'] == [['odom', 'base_footprint']], "spawn_model's '/' namespace: no prefix"
    assert seen['covariances'] == [[1e-05, 0.001]], "every /odom message is the plugin's: the plant's own is off"
    assert seen['linear'] == pytest.approx(0.2, rel=0.1) and seen['angular'] == pytest.approx(0.5, rel=0.1)
    moved = [m - s for m, s in zip(seen['model_xy'], seen['start_xy'])]
    assert abs(moved[0]) + abs(moved[1]) > 0.2, 'the robot drove'
    assert seen['odom_xy'] == pytest.approx(seen['model_xy'], abs=0.05), 'world odometry: the model pose'
    assert abs(seen['tf_x'] - seen['odom_xy'][0]) < 0.1
    assert seen['joints'] == ['wheel_left_joint', 'wheel_right_joint'] and seen['positions'] == 2


def test_diff_drive_controller_through_gazebo_ros_control_and_the_spawner(ros, tmp_path):
    (tmp_path / 'diff_bot.urdf').write_text(diff_bot_with_gazebo_ros_control())
    (tmp_path / 'controllers.yaml').write_text(yaml.safe_dump(DIFF_DRIVE_CONTROLLERS))
    spawner = spawn_with_controllers(ros, start_plant(ros), str(tmp_path / 'diff_bot.urdf'),
                                     str(tmp_path / 'controllers.yaml'), '/diff_bot', 'diff_bot',
                                     ['joint_state_controller', 'mobile_base_controller'])
    seen = ros.python("""
        import json, rospy
        from geometry_msgs.msg import Twist
        from nav_msgs.msg import Odometry
        from tianracer_description.ros_harness import connected_publisher
        rospy.init_node('probe')
        pub = connected_publisher('/diff_bot/mobile_base_controller/cmd_vel', Twist, queue_size=1)
        # Read while the commands still come: 0.5 s after the last one (cmd_vel_timeout) the controller stops.
        latest = []
        rospy.Subscriber('/diff_bot/mobile_base_controller/odom', Odometry, latest.append)
        twist = Twist()
        twist.linear.x, twist.angular.z = 0.2, 0.5
        for _ in range(30):
            pub.publish(twist)
            rospy.sleep(0.1)
        odom = latest[-1]
        print(json.dumps({'frames': [odom.header.frame_id, odom.child_frame_id],
                          'linear': odom.twist.twist.linear.x, 'angular': odom.twist.twist.angular.z,
                          'x': odom.pose.pose.position.x}))
    """, timeout=90)
    spawner.stop()
    assert seen['frames'] == ['odom', 'base_footprint']
    assert seen['linear'] == pytest.approx(0.2, rel=0.1) and seen['angular'] == pytest.approx(0.5, rel=0.1)
    assert seen['x'] > 0.1, 'it drove'


def test_skid_steer_and_planar_move_robots_in_their_spawn_namespaces(ros, tmp_path):
    (tmp_path / 'skid_bot.urdf').write_text(skid_bot())
    (tmp_path / 'planar_bot.urdf').write_text(planar_bot(robotBaseFrame='planar_base'))
    plant = start_plant(ros)
    ros.run(['rosparam', 'set', '/skid_bot/robot_description', '--textfile', str(tmp_path / 'skid_bot.urdf')])
    ros.run(['rosparam', 'set', '/planar_bot/robot_description', '--textfile', str(tmp_path / 'planar_bot.urdf')])
    spawn_urdf(ros, plant, '/skid_bot/robot_description', 'skid_bot', '-robot_namespace', '/skid_bot')
    spawn_urdf(ros, plant, '/planar_bot/robot_description', 'planar_bot', '-robot_namespace', '/planar_bot', '-y', '2')
    seen = ros.python("""
        import json, rospy, tf2_ros
        from geometry_msgs.msg import Twist
        from nav_msgs.msg import Odometry
        from sensor_msgs.msg import Imu, JointState, NavSatFix
        from tianracer_description.ros_harness import connected_publisher
        rospy.init_node('probe')
        buffer = tf2_ros.Buffer()
        listener = tf2_ros.TransformListener(buffer)
        skid = connected_publisher('/skid_bot/cmd_vel', Twist, queue_size=1)
        planar = connected_publisher('/planar_bot/cmd_vel', Twist, queue_size=1)
        forward, sideways = Twist(), Twist()
        forward.linear.x = 0.3
        sideways.linear.y = 0.2
        rospy.wait_for_message('/skid_bot/odom', Odometry, 30)
        skid_odoms = []
        rospy.Subscriber('/skid_bot/odom', Odometry, skid_odoms.append)
        for _ in range(20):
            skid.publish(forward)
            planar.publish(sideways)
            rospy.sleep(0.1)
        skid_odom = rospy.wait_for_message('/skid_bot/odom', Odometry, 10)
        planar_odom = rospy.wait_for_message('/planar_bot/odom', Odometry, 10)
        joints = rospy.wait_for_message('/skid_bot/joint_states', JointState, 10)
        fix = rospy.wait_for_message('/navsat/fix', NavSatFix, 10)
        rospy.sleep(0.2)
        # the skid bot still drives (skid_steer_drive has no timeout): compare the fix with the odometry of its time
        odom_at_fix = min(skid_odoms, key=lambda odom: abs((odom.header.stamp - fix.header.stamp).to_sec()))
        imu = rospy.wait_for_message('/imu/data', Imu, 10)
        # hector's IMU services: set_accel_bias shows on the bias topic, calibrate answers
        from geometry_msgs.msg import Vector3
        from hector_gazebo_plugins.srv import SetBias
        from std_srvs.srv import Empty
        rospy.ServiceProxy('/imu/data/set_accel_bias', SetBias)(Vector3(0.4, 0.0, 0.0))
        rospy.ServiceProxy('/imu/data/calibrate', Empty)()
        rospy.sleep(0.1)
        accel_bias = rospy.wait_for_message('/imu/data/bias', Imu, 10).linear_acceleration.x
        # at the odometry's stamp: planar_move has no command timeout, the bot still slides
        tf = buffer.lookup_transform('odom', 'planar_base', planar_odom.header.stamp, rospy.Duration(5))
        print(json.dumps({
            'skid': [skid_odom.header.frame_id, skid_odom.child_frame_id, skid_odom.twist.twist.linear.x,
                     skid_odom.pose.pose.position.x, skid_odom.pose.covariance[35]],
            'planar': [planar_odom.child_frame_id, planar_odom.twist.twist.linear.y, planar_odom.pose.pose.position.y],
            'tf_y': tf.transform.translation.y,
            'joints': list(joints.name), 'wheel_speeds': list(joints.velocity),
            'fix': [fix.header.frame_id, fix.latitude, fix.position_covariance_type, fix.position_covariance[0]],
            'x_at_fix': odom_at_fix.pose.pose.position.x,
            'imu': [imu.header.frame_id, imu.linear_acceleration.z, imu.angular_velocity_covariance[0]],
            'accel_bias': accel_bias}))
    """, timeout=90)
    frame, child, speed, x, yaw_covariance = seen['skid']
    assert (frame, child) == ('odom', 'base_footprint'), 'skid_steer_drive prefixes no frame'
    assert speed == pytest.approx(0.3, rel=0.05) and x > 0.2 and yaw_covariance == 0.01
    child, sideways, y = seen['planar']
    assert child == 'planar_base' and sideways == pytest.approx(0.2, rel=0.1) and y > 2.2, 'it moved sideways from y 2'
    assert seen['tf_y'] == pytest.approx(y, abs=0.1)
    assert seen['joints'][0] == 'front_left_wheel_joint' and seen['wheel_speeds'] == pytest.approx([7.5] * 4, rel=0.05)
    frame, latitude, covariance_type, covariance = seen['fix']
    assert frame == 'base_link' and covariance_type == 2 and covariance == pytest.approx(1e-8), \
        "hector's GPS in its own <robotNamespace> '/': /navsat/fix, drift^2 on the diagonal"
    assert seen['imu'][0] == 'base_link' and seen['imu'][1] == pytest.approx(9.8, abs=0.3), "hector's IMU on /imu/data"
    assert seen['imu'][2] == pytest.approx(0.005 ** 2)
    assert seen['accel_bias'] == pytest.approx(0.4, abs=0.02), 'set through /imu/data/set_accel_bias'
    assert (latitude - 49.9) * 111_260 == pytest.approx(seen['x_at_fix'], abs=0.02), 'about 111.26 km a degree of latitude at 49.9'


def test_the_mimic_joint_plugin_reads_its_pid_gains_from_the_parameter_server(ros, tmp_path):
    (tmp_path / 'gripper.urdf').write_text(gripper(hasPID='mimic_gains'))
    plant = start_plant(ros)
    ros.run(['rosparam', 'set', '/gripper/robot_description', '--textfile', str(tmp_path / 'gripper.urdf')])
    ros.run(['rosparam', 'set', '/mimic_gains', '{p: 100.0, i: 0.0, d: 4.0}'])
    ros.run(['rosparam', 'set', '/gripper/finger_controller',
             '{type: position_controllers/JointPositionController, joint: finger_joint}'])
    spawn_urdf(ros, plant, '/gripper/robot_description', 'gripper')
    spawner = ros.start(['rosrun', 'controller_manager', 'spawner', '__ns:=/gripper', 'finger_controller'], 'spawner')
    ros.wait_for_controllers(1, namespace='/gripper')
    seen = ros.python("""
        import json, rospy
        from gazebo_msgs.msg import LinkStates
        from std_msgs.msg import Float64
        from tianracer_description.ros_harness import connected_publisher
        rospy.init_node('probe')
        pub = connected_publisher('/gripper/finger_controller/command', Float64, queue_size=1, latch=True)
        pub.publish(Float64(0.03))
        rospy.sleep(2.0)
        links = rospy.wait_for_message('/gazebo/link_states', LinkStates, 10)
        y = {name.split('::')[1]: pose.position.y for name, pose in zip(links.name, links.pose)}
        print(json.dumps(y))
    """, timeout=60)
    spawner.stop()
    assert seen['finger_left'] == pytest.approx(0.01 + 0.03, abs=1e-3), 'the controller moved the first finger'
    assert seen['finger_right'] == pytest.approx(-0.01 - 0.03, abs=1e-3), 'the PID (gains at /mimic_gains) the second'
    assert 'not loaded' not in plant.log()


def test_range_sensor_reports_the_nearest_ray_to_a_wall(ros, tmp_path):
    # The wall's face at x = 0.7; the skid_bot's range sensor 0.15 m ahead of its origin.
    (tmp_path / 'wall.world').write_text(sdf_world(box_model('wall', (0.1, 2.0, 0.5), (0.75, 0.0, 0.25))))
    (tmp_path / 'skid_bot.urdf').write_text(skid_bot())
    plant = start_plant(ros, str(tmp_path / 'wall.world'))
    ros.run(['rosparam', 'set', '/robot_description', '--textfile', str(tmp_path / 'skid_bot.urdf')])
    spawn_urdf(ros, plant, '/robot_description', 'skid_bot')
    seen = ros.python("""
        import json, rospy
        from geometry_msgs.msg import Twist
        from nav_msgs.msg import Odometry
        from sensor_msgs.msg import Range
        from tianracer_description.ros_harness import connected_publisher
        rospy.init_node('probe')
        before = rospy.wait_for_message('/range/fr', Range, 30)
        pub = connected_publisher('/cmd_vel', Twist, queue_size=1)
        twist = Twist()
        twist.linear.x = 0.2
        for _ in range(10):
            pub.publish(twist)
            rospy.sleep(0.1)
        pub.publish(Twist())
        rospy.sleep(0.5)
        after = rospy.wait_for_message('/range/fr', Range, 10)
        x = rospy.wait_for_message('/odom', Odometry, 10).pose.pose.position.x
        print(json.dumps({'frame': before.header.frame_id, 'radiation': before.radiation_type,
                          'fov': before.field_of_view, 'limits': [before.min_range, before.max_range],
                          'before': before.range, 'after': after.range, 'x': x}))
    """, timeout=60)
    assert seen['frame'] == 'range_front' and seen['radiation'] == 1, 'infrared'
    assert seen['fov'] == pytest.approx(0.26) and seen['limits'] == pytest.approx([0.02, 0.9])
    assert seen['before'] == pytest.approx(0.55, abs=0.005), 'the straight-ahead ray: 0.7 - 0.15 m'
    assert seen['after'] == pytest.approx(0.55 - seen['x'], abs=0.01) and seen['x'] > 0.1, 'it drove toward the wall'


def test_a_diff_drive_robot_and_the_tutorial_car_in_one_world(ros, tmp_path):
    arena = os.path.join(os.path.dirname(os.path.abspath(__file__)), os.pardir, 'worlds', 'arena.world')
    car = ros.start(['roslaunch', 'tianracer_description', 'tianracer_world.launch', 'gui:=false',
                     'world_name:=' + os.path.abspath(arena)], 'tianracer_world')
    ros.wait_for_controllers(len(TUTORIAL_CONTROLLERS))
    (tmp_path / 'diff_bot.urdf').write_text(open(DIFF_BOT).read())
    ros.run(['rosparam', 'set', '/tb3/robot_description', '--textfile', str(tmp_path / 'diff_bot.urdf')])
    spawn_urdf(ros, car, '/tb3/robot_description', 'tb3', '-robot_namespace', '/tb3', '-x', '-1', '-y', '-1.5')
    seen = ros.python("""
        import json, rospy, tf2_ros
        from gazebo_msgs.msg import ModelStates
        from geometry_msgs.msg import Twist
        from sensor_msgs.msg import LaserScan
        from tianracer_description.ros_harness import connected_publisher
        rospy.init_node('probe')
        buffer = tf2_ros.Buffer()
        listener = tf2_ros.TransformListener(buffer)
        def positions():
            states = rospy.wait_for_message('/gazebo/model_states', ModelStates, 10)
            return {name: [pose.position.x, pose.position.y] for name, pose in zip(states.name, states.pose)}
        scan = rospy.wait_for_message('/tb3/scan', LaserScan, 30)
        before = positions()
        car, tb3 = connected_publisher('/tianracer/cmd_vel', Twist, queue_size=1), connected_publisher('/tb3/cmd_vel', Twist, queue_size=1)
        fast, slow = Twist(), Twist()
        fast.linear.x, slow.linear.x = 0.5, 0.2
        for _ in range(25):
            car.publish(fast)
            tb3.publish(slow)
            rospy.sleep(0.1)
        after = positions()
        tf = buffer.lookup_transform('tb3/odom', 'tb3/base_footprint', rospy.Time(0), rospy.Duration(5))
        print(json.dumps({'before': before, 'after': after, 'scan_frame': scan.header.frame_id,
                          'scan_hits': sum(1 for r in scan.ranges if r < 3.5), 'tb3_tf_x': tf.transform.translation.x}))
    """, timeout=90)
    moved = {name: seen['after'][name][0] - seen['before'][name][0] for name in ('tianracer', 'tb3')}
    assert moved['tianracer'] > 0.5, moved
    assert 0.25 < moved['tb3'] < 0.6, moved
    assert abs(seen['after']['tb3'][1] + 1.5) < 0.05, 'each robot drives on its own topic: tb3 kept its line'
    assert seen['scan_frame'] == 'tb3/base_scan', "gazebo_ros_laser's frame resolves against its namespace"
    assert seen['scan_hits'] > 100, 'the arena walls and the car around it'
    assert seen['tb3_tf_x'] == pytest.approx(seen['after']['tb3'][0], abs=0.15), \
        "the diff drive's frames carry its namespace: tb3/odom -> tb3/base_footprint"


def test_force_plugin_takes_its_wrench_from_ros_and_f3d_reports_it(ros, tmp_path):
    (tmp_path / 'pushed.urdf').write_text(f3d_bot())
    plant = start_plant(ros)
    ros.run(['rosparam', 'set', '/robot_description', '--textfile', str(tmp_path / 'pushed.urdf')])
    spawn_urdf(ros, plant, '/robot_description', 'pushed')
    seen = ros.python("""
        import json, rospy
        from gazebo_msgs.srv import GetModelState
        from geometry_msgs.msg import Wrench, WrenchStamped
        from tianracer_description.ros_harness import connected_publisher
        rospy.init_node('probe')
        state = rospy.ServiceProxy('/gazebo/get_model_state', GetModelState)
        pub = connected_publisher('/force', Wrench, queue_size=1, latch=True)
        wrench = Wrench()
        wrench.force.z = 60.0
        before = state('pushed', '').pose.position.z
        pub.publish(wrench)
        rospy.sleep(1.0)
        truth = rospy.wait_for_message('/force_truth', WrenchStamped, 10)
        # gazebo_ros's apply_body_wrench runs before the model plugins: f3d sees the sum
        from gazebo_msgs.srv import ApplyBodyWrench
        apply = rospy.ServiceProxy('/gazebo/apply_body_wrench', ApplyBodyWrench)
        extra = Wrench()
        extra.force.x = 5.0
        apply('pushed::base_link', '', None, extra, rospy.Time(0), rospy.Duration(-1))
        rospy.sleep(0.2)
        both = rospy.wait_for_message('/force_truth', WrenchStamped, 10).wrench.force
        print(json.dumps({'both': [both.x, both.y, both.z], 'rise': state('pushed', '').pose.position.z - before, 'frame': truth.header.frame_id,
                          'force': [truth.wrench.force.x, truth.wrench.force.y, truth.wrench.force.z],
                          'stamped': truth.header.stamp.to_sec()}))
    """, timeout=60)
    assert seen['rise'] > 0.3, 'geometry_msgs/Wrench on /force lifted the 5 kg base (2.2 m/s^2 net)'
    assert seen['frame'] == 'world' and seen['force'] == [0, 0, 60.0] and seen['stamped'] > 1.0, \
        'gazebo_ros_f3d: the pushed wrench on /force_truth, stamped with sim time'
    assert seen['both'] == [5.0, 0, 60.0]
