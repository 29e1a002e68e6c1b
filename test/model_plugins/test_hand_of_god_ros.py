"""gazebo_ros_hand_of_god through the node: the floating box of test_hand_of_god.py spawned by
spawn_model, a tf2_ros static transform world -> hog_desired sent the way a user does; the box goes
there (/gazebo/get_model_state) and world -> hog_actual appears on /tf."""
import pytest

from test_hand_of_god import BOX
from ros_harness import spawn_urdf, start_plant

pytestmark = pytest.mark.ros


def test_a_static_transform_moves_the_box(ros, tmp_path):
    (tmp_path / 'box.urdf').write_text(BOX % '<linkName>box</linkName>')
    plant = start_plant(ros)
    ros.run(['rosparam', 'set', '/robot_description', '--textfile', str(tmp_path / 'box.urdf')])
    spawn_urdf(ros, plant, '/robot_description', 'hog_box')
    seen = ros.python("""
        import json, rospy, tf2_ros
        from gazebo_msgs.srv import GetModelState
        from geometry_msgs.msg import TransformStamped
        rospy.init_node('probe')
        broadcaster = tf2_ros.StaticTransformBroadcaster()
        t = TransformStamped()
        t.header.stamp = rospy.Time.now()
        t.header.frame_id, t.child_frame_id = 'world', 'hog_desired'
        t.transform.translation.x, t.transform.translation.z = 0.8, 1.5
        t.transform.rotation.w = 1.0
        broadcaster.sendTransform(t)
        buffer = tf2_ros.Buffer()
        listener = tf2_ros.TransformListener(buffer)
        rospy.sleep(3.0)
        p = rospy.ServiceProxy('/gazebo/get_model_state', GetModelState)('hog_box', '').pose.position
        actual = buffer.lookup_transform('world', 'hog_actual', rospy.Time(0), rospy.Duration(5)).transform.translation
        print(json.dumps({'box': [p.x, p.y, p.z], 'actual': [actual.x, actual.y, actual.z]}))
    """, timeout=60)
    assert seen['box'] == pytest.approx([0.8, 0.0, 1.5], abs=0.01)
    assert seen['actual'] == pytest.approx(seen['box'], abs=0.02)
