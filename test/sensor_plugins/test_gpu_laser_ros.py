"""gazebo_ros_gpu_laser through the node: a <sensor type="gpu_ray"> on a box 1.5 m before a wall,
which it sees by its visual (as Gazebo's renders it) and not by its collision, and the same lidar's
scan in a world whose wall has a collision only. Upstream's library of the plugin runs this test in
place of the plant's own (test_upstream_gazebo_plugins.py): not in a world with gazebo_ros_laser, as
both define class GazeboRosLaser and, loaded into one process as Gazebo loads plugins, the second
takes the first's code (gazebo_ros_pkgs issue #768: the plant loads plugin files as Gazebo does)."""
import math

import pytest

from plant_helpers import box_model, sdf_world
from ros_harness import start_plant

pytestmark = pytest.mark.ros

ANGLES = [-0.4 + 0.1 * i for i in range(9)]
PROBE = """<model name="probe"><pose>0 0 0.1 0 0 0</pose><link name="base">
    <inertial><mass>2</mass><inertia><ixx>0.0133</ixx><iyy>0.0133</iyy><izz>0.0133</izz></inertia></inertial>
    <collision name="shell"><geometry><box><size>0.2 0.2 0.2</size></box></geometry></collision>
    <sensor type="gpu_ray" name="gpu_lidar"><pose>0.1 0 0.05 0 0 0</pose><update_rate>20</update_rate>
      <ray><scan><horizontal><samples>9</samples><min_angle>-0.4</min_angle><max_angle>0.4</max_angle></horizontal></scan>
        <range><min>0.1</min><max>5</max></range></ray>
      <plugin name="gpu_lidar_plugin" filename="libgazebo_ros_gpu_laser.so"><topicName>gpu_scan</topicName>
        <frameName>base</frameName></plugin>
    </sensor>
  </link></model>"""


@pytest.mark.parametrize('visual', [True, False], ids=['wall_seen', 'wall_of_collision_only'])
def test_a_gpu_ray_lidar_scans_what_is_seen(ros, tmp_path, visual):
    (tmp_path / 'gpu.world').write_text(sdf_world(PROBE + box_model('wall', (0.2, 2.0, 1.0), (1.5, 0, 0.5),
                                                                    visual=visual)))
    start_plant(ros, str(tmp_path / 'gpu.world'))
    scan = ros.probe('sensor_plugins/probes/messages_after.py', 0.5, '/gpu_scan', timeout=60)['/gpu_scan']
    assert scan['type'] == 'sensor_msgs/LaserScan' and scan['frame'] == 'base'
    assert len(scan['ranges']) == 9
    if visual:
        # the wall's face 1.3 m before the lidar, farther off-axis
        assert scan['ranges'] == pytest.approx([1.3 / math.cos(a) for a in ANGLES], abs=5e-3)
    else:
        assert scan['ranges'] == [None] * 9, 'nothing seen: +inf'
