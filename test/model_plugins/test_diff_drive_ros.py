"""libgazebo_ros_diff_drive.so through the node: the diff_bot spawned by spawn_model (its '/'
namespace written into the plugin, as upstream's) drives on /cmd_vel and publishes /odom, odom ->
base_footprint on /tf and the wheels' joint_states, the only odometry of the robot. A turtlebot3-like
diff-drive robot and the tutorial's car together in one world, each driven on its own topics."""
import os

import pytest

from plant_helpers import DIFF_BOT
from suite_paths import REPOSITORY
from ros_harness import spawn_urdf, start_plant
from tianracer_description.tianracer import TUTORIAL_CONTROLLERS

pytestmark = pytest.mark.ros


@pytest.mark.slow
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
        from ros_harness import connected_publisher
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

@pytest.mark.slow
def test_a_diff_drive_robot_and_the_tutorial_car_in_one_world(ros, tmp_path):
    arena = os.path.join(REPOSITORY, 'worlds', 'arena.world')
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
        from ros_harness import connected_publisher
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
