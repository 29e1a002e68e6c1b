"""libgazebo_ros_skid_steer_drive.so and libgazebo_ros_planar_move.so through the node: a skid-steer
robot (with hector's GPS and IMU) and a holonomic base in one world, each in its spawn namespace."""
import pytest

from plant_helpers import planar_bot, skid_bot
from ros_harness import spawn_urdf, start_plant

pytestmark = pytest.mark.ros


@pytest.mark.slow
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
        from ros_harness import connected_publisher
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
