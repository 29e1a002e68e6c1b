"""libgazebo_ros_force and libgazebo_ros_f3d through the node: gazebo_ros_force's Wrench topic and
gazebo_ros_f3d's WrenchStamped of it."""
import pytest

from plant_helpers import f3d_bot
from ros_harness import spawn_urdf, start_plant

pytestmark = pytest.mark.ros


def test_force_plugin_takes_its_wrench_from_ros_and_f3d_reports_it(ros, tmp_path):
    (tmp_path / 'pushed.urdf').write_text(f3d_bot())
    plant = start_plant(ros)
    ros.set_param('/robot_description', textfile=str(tmp_path / 'pushed.urdf'))
    spawn_urdf(ros, plant, '/robot_description', 'pushed')
    seen = ros.probe('model_plugins/probes/force_plugin_takes_its_wrench_from_ros_and_f3d_reports_it.py', timeout=60)
    assert seen['rise'] > 0.3, 'geometry_msgs/Wrench on /force lifted the 5 kg base (2.2 m/s^2 net)'
    assert seen['frame'] == 'world' and seen['force'] == [0, 0, 60.0] and seen['stamped'] > 1.0, \
        'gazebo_ros_f3d: the pushed wrench on /force_truth, stamped with sim time'
    assert seen['both'] == [5.0, 0, 60.0]
