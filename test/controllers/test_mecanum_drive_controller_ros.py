"""A Ridgeback-like mecanum base through the node (test/fixtures/urdf/mecanum_bot.urdf): its
controllers started by the spawner, one Twist sent to the controller and to the force-based move
plugin as Ridgeback's relay does; the controller's wheel odometry and odom -> base_footprint on /tf
follow the command sideways and turning, the body moves with it, the wheels' joint_states carry the
inverse kinematics."""
import pytest
import yaml

from plant_helpers import MECANUM_CONTROLLERS, mecanum_bot
from ros_harness import spawn_with_controllers, start_plant
from test_mecanum_drive_controller import WHEELS, inverse_kinematics

pytestmark = pytest.mark.ros


@pytest.mark.slow
def test_mecanum_controller_through_the_spawner_with_the_body_moved_by_force_based_move(ros, tmp_path):
    (tmp_path / 'mecanum_bot.urdf').write_text(mecanum_bot())
    (tmp_path / 'controllers.yaml').write_text(yaml.safe_dump(MECANUM_CONTROLLERS))
    spawner = spawn_with_controllers(ros, start_plant(ros), str(tmp_path / 'mecanum_bot.urdf'),
                                     str(tmp_path / 'controllers.yaml'), '/mecanum_bot', 'mecanum_bot',
                                     ['joint_state_controller', 'mecanum_controller'])
    seen = ros.python("""
        import json, rospy, tf2_ros
        from gazebo_msgs.srv import GetModelState
        from geometry_msgs.msg import Twist
        from nav_msgs.msg import Odometry
        from sensor_msgs.msg import JointState
        from ros_harness import connected_publisher
        rospy.init_node('probe')
        buffer = tf2_ros.Buffer()
        listener = tf2_ros.TransformListener(buffer)
        to_controller = connected_publisher('/mecanum_bot/mecanum_controller/cmd_vel', Twist, queue_size=1)
        to_body = connected_publisher('/cmd_vel', Twist, queue_size=1)
        state = rospy.ServiceProxy('/gazebo/get_model_state', GetModelState)
        start = state('mecanum_bot', '').pose.position
        twist = Twist()
        twist.linear.y, twist.angular.z = 0.3, 0.2
        # Read while the commands still come: 0.25 s after the last one the controller brakes the wheels.
        latest = {}
        rospy.Subscriber('/mecanum_bot/mecanum_controller/odom', Odometry, lambda m: latest.__setitem__('odom', m))
        rospy.Subscriber('/mecanum_bot/joint_states', JointState, lambda m: latest.__setitem__('joints', m))
        for _ in range(30):
            to_controller.publish(twist)
            to_body.publish(twist)
            rospy.sleep(0.1)
        odom, joints = latest['odom'], latest['joints']
        tf = buffer.lookup_transform('odom', 'base_footprint', rospy.Time(0), rospy.Duration(5)).transform.translation
        end = state('mecanum_bot', '').pose.position
        t = odom.twist.twist
        print(json.dumps({'frames': [odom.header.frame_id, odom.child_frame_id], 'twist': [t.linear.x, t.linear.y, t.angular.z],
                          'odom_y': odom.pose.pose.position.y, 'tf_y': tf.y, 'moved_y': end.y - start.y,
                          'speeds': dict(zip(joints.name, joints.velocity))}))
    """, timeout=90)
    spawner.stop()
    assert seen['frames'] == ['odom', 'base_footprint']
    assert seen['twist'] == pytest.approx([0.0, 0.3, 0.2], abs=0.02)
    assert seen['odom_y'] > 0.5 and seen['tf_y'] == pytest.approx(seen['odom_y'], abs=0.1)
    assert seen['moved_y'] > 0.5, 'force_based_move moved the body sideways'
    assert [seen['speeds'][w] for w in WHEELS] == pytest.approx(inverse_kinematics(0.0, 0.3, 0.2), abs=0.05)
