"""gazebo_plugins' model plugins through the node: libgazebo_ros_diff_drive.so spawned by spawn_model
(its '/' namespace written into the plugin, as upstream's) drives on /cmd_vel and publishes /odom,
odom -> base_footprint on /tf and the wheels' joint_states, the only odometry of the robot."""
import os

import pytest

from plant_helpers import FIXTURES
from tianracer_description.ros_harness import spawn_urdf, start_plant

pytestmark = pytest.mark.ros

DIFF_BOT = os.path.join(FIXTURES, 'urdf', 'diff_bot.urdf')


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
