"""Differential drives through the node: libgazebo_ros_diff_drive.so spawned by spawn_model (its '/'
namespace written into the plugin, as upstream's) drives on /cmd_vel and publishes /odom, odom ->
base_footprint on /tf and the wheels' joint_states, the only odometry of the robot; the same robot with
gazebo_ros_control and diff_drive_controller started by the spawner."""
import pytest
import yaml

from plant_helpers import DIFF_BOT, DIFF_DRIVE_CONTROLLERS, diff_bot_with_gazebo_ros_control
from tianracer_description.ros_harness import spawn_urdf, start_plant

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
        rospy.init_node('probe')
        odometry = []
        rospy.Subscriber('/odom', Odometry, odometry.append)
        buffer = tf2_ros.Buffer()
        listener = tf2_ros.TransformListener(buffer)
        pub = rospy.Publisher('/cmd_vel', Twist, queue_size=1)
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
    plant = start_plant(ros)
    ros.run(['rosparam', 'set', '/diff_bot/robot_description', '--textfile', str(tmp_path / 'diff_bot.urdf')])
    ros.run(['rosparam', 'load', str(tmp_path / 'controllers.yaml')])
    spawn_urdf(ros, plant, '/diff_bot/robot_description', 'diff_bot')
    spawner = ros.start(['rosrun', 'controller_manager', 'spawner', '__ns:=/diff_bot', 'joint_state_controller',
                         'mobile_base_controller'], 'spawner')
    ros.wait_for_controllers(2, namespace='/diff_bot')
    seen = ros.python("""
        import json, rospy
        from geometry_msgs.msg import Twist
        from nav_msgs.msg import Odometry
        rospy.init_node('probe')
        pub = rospy.Publisher('/diff_bot/mobile_base_controller/cmd_vel', Twist, queue_size=1)
        twist = Twist()
        twist.linear.x, twist.angular.z = 0.2, 0.5
        for _ in range(30):
            pub.publish(twist)
            rospy.sleep(0.1)
        odom = rospy.wait_for_message('/diff_bot/mobile_base_controller/odom', Odometry, 10)
        print(json.dumps({'frames': [odom.header.frame_id, odom.child_frame_id],
                          'linear': odom.twist.twist.linear.x, 'angular': odom.twist.twist.angular.z,
                          'x': odom.pose.pose.position.x}))
    """, timeout=90)
    spawner.stop()
    assert seen['frames'] == ['odom', 'base_footprint']
    assert seen['linear'] == pytest.approx(0.2, rel=0.1) and seen['angular'] == pytest.approx(0.5, rel=0.1)
    assert seen['x'] > 0.1, 'it drove'
