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
    ros.set_param('/robot_description', textfile=str(tmp_path / 'box.urdf'))
    spawn_urdf(ros, plant, '/robot_description', 'hog_box')
    seen = ros.probe('model_plugins/probes/a_static_transform_moves_the_box.py', timeout=60)
    assert seen['box'] == pytest.approx([0.8, 0.0, 1.5], abs=0.01)
    assert seen['actual'] == pytest.approx(seen['box'], abs=0.02)
