"""gazebo_ros_joint_pose_trajectory through the node: the arm with the plugin spawned by spawn_model
(no controller running); a trajectory_msgs/JointTrajectory on /set_joint_trajectory poses it, read
back with gazebo_ros's /gazebo/get_joint_properties (which also answers "joint not found")."""
import pytest

from test_joint_pose_trajectory import PLUGIN
from plant_helpers import arm
from ros_harness import spawn_urdf, start_plant

pytestmark = pytest.mark.ros


def test_a_trajectory_on_the_topic_poses_the_arm(ros, tmp_path):
    (tmp_path / 'arm.urdf').write_text(arm().replace('</robot>', PLUGIN))
    plant = start_plant(ros)
    ros.run(['rosparam', 'set', '/robot_description', '--textfile', str(tmp_path / 'arm.urdf')])
    spawn_urdf(ros, plant, '/robot_description', 'arm')
    seen = ros.python("""
        import json, rospy
        from gazebo_msgs.srv import GetJointProperties
        from trajectory_msgs.msg import JointTrajectory, JointTrajectoryPoint
        from ros_harness import connected_publisher
        rospy.init_node('probe')
        joint = rospy.ServiceProxy('/gazebo/get_joint_properties', GetJointProperties)
        pub = connected_publisher('/set_joint_trajectory', JointTrajectory, queue_size=1, latch=True)
        t = JointTrajectory(joint_names=['shoulder', 'elbow'])
        t.header.frame_id = 'world'
        t.points.append(JointTrajectoryPoint(positions=[0.5, -0.3], time_from_start=rospy.Duration(0.3)))
        t.points.append(JointTrajectoryPoint(positions=[1.0, -0.6], time_from_start=rospy.Duration(5.0)))
        pub.publish(t)
        rospy.sleep(1.5)  # the second point is held 5 s with the physics off
        shoulder, elbow = joint('shoulder'), joint('elbow')
        print(json.dumps({'shoulder': list(shoulder.position), 'elbow': list(elbow.position),
                          'elbow_rate': list(elbow.rate), 'missing': [joint('nowhere').success, joint('nowhere').status_message]}))
    """, timeout=60)
    assert seen['shoulder'] == pytest.approx([1.0], abs=1e-5) and seen['elbow'] == pytest.approx([-0.6], abs=1e-5)
    assert seen['elbow_rate'] == [0.0]
    assert seen['missing'] == [False, 'GetJointProperties: joint not found']
