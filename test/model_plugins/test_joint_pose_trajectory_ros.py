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
    ros.set_param('/robot_description', textfile=str(tmp_path / 'arm.urdf'))
    spawn_urdf(ros, plant, '/robot_description', 'arm')
    seen = ros.probe('model_plugins/probes/a_trajectory_on_the_topic_poses_the_arm.py', timeout=60)
    assert seen['shoulder'] == pytest.approx([1.0], abs=1e-5) and seen['elbow'] == pytest.approx([-0.6], abs=1e-5)
    assert seen['elbow_rate'] == [0.0]
    assert seen['missing'] == [False, 'GetJointProperties: joint not found']
