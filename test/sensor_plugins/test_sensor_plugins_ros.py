"""The gazebo_ros plugins on ROS: topics in the plugin's namespace, a tf_prefix parameter found from
it, gazebo_ros_p3d and gazebo_ros_imu messages, an unknown plugin named once in the node's log."""
import pytest

from plant_helpers import PLUGIN_URDF
from ros_harness import spawn_urdf, start_plant

pytestmark = pytest.mark.ros


def first_message(ros, topic):
    return ros.probe('sensor_plugins/probes/first_message.py', topic, timeout=60)


@pytest.mark.slow
def test_plugins_publish_in_their_namespaces_with_their_frames(ros, tmp_path):
    plant = start_plant(ros)
    urdf = tmp_path / 'probe.urdf'
    urdf.write_text(PLUGIN_URDF)
    ros.set_param('/probe_description', textfile=str(urdf))
    ros.set_param('/other/tf_prefix', 'custom')      # found by the camera's searchParam
    ros.set_param('/robot_a/tf_prefix', 'truth_prefix')  # read by gazebo_ros_p3d
    spawn_urdf(ros, plant, '/probe_description', 'probe', robot_namespace='/robot_a')
    assert first_message(ros, '/shared/laser') == {'frame': 'scanner', 'type': 'sensor_msgs/LaserScan'}
    assert first_message(ros, '/other/front/rgb') == {'frame': 'custom/eye_frame', 'type': 'sensor_msgs/Image'}
    assert first_message(ros, '/robot_a/ground_truth') == {'frame': 'truth_prefix/world', 'child': 'base_footprint',
                                                           'type': 'nav_msgs/Odometry'}
    assert first_message(ros, '/robot_a/imu_raw') == {'frame': 'scanner', 'type': 'sensor_msgs/Imu'}
    log = plant.log()
    assert log.count('libacme_sonar_plugin.so') == 1, log


def ray_sensor(name, samples, min_angle, max_angle, range_min, range_max, kind='gpu_ray'):
    plugin = 'libgazebo_ros_gpu_laser.so' if kind == 'gpu_ray' else 'libgazebo_ros_laser.so'
    return f"""<sensor type="{kind}" name="{name}"><update_rate>20</update_rate>
      <ray><scan><horizontal><samples>{samples}</samples><min_angle>{min_angle}</min_angle>
        <max_angle>{max_angle}</max_angle></horizontal></scan>
        <range><min>{range_min}</min><max>{range_max}</max></range></ray>
      <plugin name="{name}_plugin" filename="{plugin}"><topicName>{name}</topicName><frameName>head</frameName></plugin>
    </sensor>"""


def camera_sensor(name, fov, width, height):
    return f"""<sensor type="camera" name="{name}"><update_rate>20</update_rate>
      <camera><horizontal_fov>{fov}</horizontal_fov><image><width>{width}</width><height>{height}</height></image></camera>
      <plugin name="{name}_plugin" filename="libgazebo_ros_camera.so"><cameraName>{name}</cameraName>
        <frameName>head</frameName></plugin>
    </sensor>"""


# name: (samples, min_angle, max_angle, range_min, range_max, kind) of the lidars that scan
SCANNING = {
    'one_ray': (1, 0, 0, 0, 10, 'ray'),
    'full_circle': (3000, -3.14159, 3.14159, 0.1, 10, 'gpu_ray'),
    'min_is_max': (7, -0.5, 0.5, 2, 2, 'gpu_ray'),
    'min_above_max': (7, -0.5, 0.5, 3, 2, 'ray'),
    'reversed_fan': (9, 1, -1, 0.1, 10, 'gpu_ray'),
    'zero_width_fan': (5, 0.3, 0.3, 0, 10, 'ray'),
}
# name: (sensor XML, what the error at spawn says) of the sensors the plant refuses
REFUSED = {
    'no_samples': (ray_sensor('no_samples', 0, -1, 1, 0.1, 10), "<scan> has 0 horizontal and 1 vertical <samples>"),
    'no_range': (ray_sensor('no_range', 5, -1, 1, 0, 0), '<range><max> is 0'),
    # (below SDF's 0.1 rad, which sdformat 12 enforces: it reads no such camera)
    'zero_fov': (camera_sensor('zero_fov', 0, 8, 6), "<horizontal_fov> '0': The value [0] is less than the minimum"),
    'negative_fov': (camera_sensor('negative_fov', -1, 8, 6),
                     "<horizontal_fov> '-1': The value [-1] is less than the minimum"),
    'huge_image': (camera_sensor('huge_image', 1, 100000, 100000), '100000 x 100000 pixels is more than'),
}
# held where it is spawned: its sensors look 0.5 rad down from 0.3 m
EDGE_URDF = """<robot name="edges">
  <link name="base_footprint"/>
  <link name="head"><collision><geometry><box size="0.05 0.05 0.05"/></geometry></collision></link>
  <joint name="head_joint" type="fixed"><parent link="base_footprint"/><child link="head"/>
    <origin xyz="0 0 0.3" rpy="0 0.5 0"/></joint>
  <gazebo><static>true</static></gazebo>
  <gazebo reference="head">
    %s
  </gazebo>
</robot>""" % '\n    '.join(
    [ray_sensor(name, *spec) for name, spec in SCANNING.items()] + [camera_sensor('one_pixel', 1.0, 1, 1)] +
    [xml for xml, _ in REFUSED.values()])


def test_the_node_survives_whatever_a_sensor_asks_for_on_every_embree_kernel(embree_isa, ros, tmp_path):
    # Lidars of 1 to 3000 rays, of minimum range 0, equal to or above the maximum, fans of negative
    # or zero width, a 1-pixel camera: all scan, on every ISA of Embree's kernels. What no sensor
    # can do (no samples, no range, a field of view of 0 or below) is an error at spawn naming it.
    plant = start_plant(ros)
    urdf = tmp_path / 'edges.urdf'
    urdf.write_text(EDGE_URDF)
    ros.set_param('/edges_description', textfile=str(urdf))
    spawn_urdf(ros, plant, '/edges_description', 'edges')
    scans = ros.probe('sensor_plugins/probes/scans_of_every_edge_case.py', *SCANNING, timeout=120)
    for name, (samples, *_rest) in SCANNING.items():
        assert scans[name]['n'] == samples, (name, scans[name])
        assert scans[name]['below_min'] == 0, (name, scans[name])
    # tilted 0.5 rad down from 0.3 m: the rays ahead meet the ground 0.6 m away
    assert scans['one_ray']['finite'] == 1
    assert scans['full_circle']['finite'] > 500
    assert scans['min_is_max']['finite'] == scans['min_above_max']['finite'] == 0, 'nothing lies within an empty range'
    assert scans['one_pixel']['n'] == 1
    assert plant.popen.poll() is None, 'the node is alive:\n' + plant.log()
    log = plant.log()
    assert "rays cast with Embree's %s kernels" % embree_isa in log, log
    for name, (_, says) in REFUSED.items():
        lines = [line for line in log.splitlines() if "'%s'" % name in line]
        assert len(lines) == 1 and says in lines[0] and 'it publishes nothing' in lines[0], (name, lines, log)
