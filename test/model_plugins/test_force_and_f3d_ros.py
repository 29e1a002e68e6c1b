"""libgazebo_ros_force and libgazebo_ros_f3d through the node: gazebo_ros_force's Wrench topic and
gazebo_ros_f3d's WrenchStamped of it."""
import pytest

from plant_helpers import f3d_bot
from ros_harness import spawn_urdf, start_plant

pytestmark = pytest.mark.ros


def test_force_plugin_takes_its_wrench_from_ros_and_f3d_reports_it(ros, tmp_path):
    (tmp_path / 'pushed.urdf').write_text(f3d_bot())
    plant = start_plant(ros)
    ros.run(['rosparam', 'set', '/robot_description', '--textfile', str(tmp_path / 'pushed.urdf')])
    spawn_urdf(ros, plant, '/robot_description', 'pushed')
    seen = ros.python("""
        import json, rospy
        from gazebo_msgs.srv import GetModelState
        from geometry_msgs.msg import Wrench, WrenchStamped
        from ros_harness import connected_publisher
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
