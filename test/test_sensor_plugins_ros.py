"""The gazebo_ros plugins on ROS: topics in the plugin's namespace, a tf_prefix parameter found from
it, gazebo_ros_p3d and gazebo_ros_imu messages, an unknown plugin named once in the node's log."""
import pytest

from plant_helpers import PLUGIN_URDF
from tianracer_description.ros_harness import spawn_urdf, start_plant

pytestmark = pytest.mark.ros


def first_message(ros, topic):
    return ros.python(f"""
        import json, rospy, rostopic
        rospy.init_node('probe', anonymous=True)
        cls, name, _ = rostopic.get_topic_class({topic!r}, blocking=True)
        m = rospy.wait_for_message({topic!r}, cls, timeout=30)
        out = {{'frame': m.header.frame_id, 'type': m._type}}
        if hasattr(m, 'child_frame_id'):
            out['child'] = m.child_frame_id
        print(json.dumps(out))
    """, timeout=60)


def test_plugins_publish_in_their_namespaces_with_their_frames(ros, tmp_path):
    plant = start_plant(ros)
    urdf = tmp_path / 'probe.urdf'
    urdf.write_text(PLUGIN_URDF)
    ros.run(['rosparam', 'set', '/probe_description', '--textfile', str(urdf)])
    ros.run(['rosparam', 'set', '/other/tf_prefix', 'custom'])      # found by the camera's searchParam
    ros.run(['rosparam', 'set', '/robot_a/tf_prefix', 'truth_prefix'])  # read by gazebo_ros_p3d
    spawn_urdf(ros, plant, '/probe_description', 'probe', '-robot_namespace', '/robot_a')
    assert first_message(ros, '/shared/laser') == {'frame': 'scanner', 'type': 'sensor_msgs/LaserScan'}
    assert first_message(ros, '/other/front/rgb') == {'frame': 'custom/eye_frame', 'type': 'sensor_msgs/Image'}
    assert first_message(ros, '/robot_a/ground_truth') == {'frame': 'truth_prefix/world', 'child': 'base_footprint',
                                                           'type': 'nav_msgs/Odometry'}
    assert first_message(ros, '/robot_a/imu_raw') == {'frame': 'scanner', 'type': 'sensor_msgs/Imu'}
    log = plant.log()
    assert log.count('libgazebo_ros_range.so') == 1, log
