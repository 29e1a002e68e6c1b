"""gazebo_ros_ft_sensor through the node: the arm with its force/torque sensors (test_ft_sensor.py's
URDF) spawned and held by its controllers; /elbow_ft carries the weight hanging below the elbow
(pointing down: Gazebo's sign) as
geometry_msgs/WrenchStamped in the forearm's frame, stamped with sim time, and a Wrench on /push
shows in it."""
import pytest

from plant_helpers import start_arm
from test_ft_sensor import G, FOREARM, HAND, arm_with_ft_sensors_urdf

pytestmark = pytest.mark.ros


@pytest.mark.slow
def test_wrench_stamped_of_the_elbow_with_a_push(ros, tmp_path):
    start_arm(ros, tmp_path, urdf=arm_with_ft_sensors_urdf())
    seen = ros.probe('model_plugins/probes/wrench_stamped_of_the_elbow_with_a_push.py', timeout=60)
    held, pushed = seen['held'], seen['pushed']
    weight = (FOREARM[0] + HAND[0]) * G
    assert held['frame'] == 'forearm' and held['stamp'] > 0.5
    assert held['force'] == pytest.approx([0, 0, -weight], abs=0.05)
    assert pushed['force'] == pytest.approx([0, 5.0, -weight], abs=0.05)
    assert pushed['torque'][2] == pytest.approx(5.0 * HAND[1][0], abs=0.02), 'the push about the elbow'
