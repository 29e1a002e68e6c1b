"""A world file's SDF model with a camera (gazebo_ros_camera), a ray sensor (gazebo_ros_laser), a range
sensor (gazebo_ros_range), an IMU sensor (gazebo_ros_imu_sensor) and a gazebo_ros_p3d model plugin publishes from the node's start as
its URDF twin, spawned by spawn_model, does: the same topic names (the twin's under its
-robot_namespace), frame ids (as given: no tf_prefix parameter is set), sizes and values; so does the same SDF spawned by spawn_model
-sdf -robot_namespace. Each stands 1.5 m before a wall of its own, 20 m apart."""
import math

import pytest

from plant_helpers import box_model, sdf_world
from ros_harness import spawn_urdf, start_plant

pytestmark = pytest.mark.ros

SENSORS = """
    <sensor type="ray" name="lidar"><pose>0.1 0 0.05 0 0 0</pose><update_rate>20</update_rate>
      <ray><scan><horizontal><samples>9</samples><min_angle>-0.4</min_angle><max_angle>0.4</max_angle></horizontal></scan>
        <range><min>0.1</min><max>5</max></range></ray>
      <plugin name="lidar_plugin" filename="libgazebo_ros_laser.so"><topicName>scan</topicName><frameName>base</frameName></plugin>
    </sensor>
    <sensor type="camera" name="eye"><pose>0.1 0 0.05 0 0 0</pose><update_rate>10</update_rate>
      <camera><horizontal_fov>1.0</horizontal_fov><image><width>16</width><height>12</height></image>
        <clip><near>0.05</near><far>20</far></clip></camera>
      <plugin name="eye_plugin" filename="libgazebo_ros_camera.so"><cameraName>cam</cameraName><frameName>base</frameName></plugin>
    </sensor>
    <sensor type="ray" name="sonar"><pose>0.1 0 0.05 0 0 0</pose><update_rate>10</update_rate>
      <ray><scan><horizontal><samples>3</samples><min_angle>-0.1</min_angle><max_angle>0.1</max_angle></horizontal>
        <vertical><samples>3</samples><min_angle>-0.1</min_angle><max_angle>0.1</max_angle></vertical></scan>
        <range><min>0.02</min><max>4</max></range></ray>
      <plugin name="sonar_plugin" filename="libgazebo_ros_range.so"><topicName>range</topicName>
        <frameName>base</frameName><radiation>ultrasound</radiation><fov>0.2</fov></plugin>
    </sensor>
    <sensor type="imu" name="imu"><pose>0 0 0 0 0 0.3</pose><update_rate>50</update_rate>
      <plugin name="imu_plugin" filename="libgazebo_ros_imu_sensor.so"><topicName>imu</topicName>
        <frameName>base</frameName><updateRateHZ>50</updateRateHZ></plugin>
    </sensor>"""
P3D = """<plugin name="truth" filename="libgazebo_ros_p3d.so"><bodyName>base</bodyName>
      <topicName>ground_truth</topicName><updateRate>50</updateRate></plugin>"""
INERTIA = '<ixx>0.0133</ixx><iyy>0.0133</iyy><izz>0.0133</izz>'

SDF_MODEL = f"""<model name="probe"><pose>0 0 0.1 0 0 0</pose>
  <link name="base">
    <inertial><mass>2</mass><inertia>{INERTIA}</inertia></inertial>
    <collision name="shell"><geometry><box><size>0.2 0.2 0.2</size></box></geometry></collision>
    {SENSORS}
  </link>
  {P3D}
</model>"""

URDF_TWIN = f"""<robot name="twin">
  <link name="base">
    <inertial><mass value="2"/><inertia ixx="0.0133" iyy="0.0133" izz="0.0133" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><geometry><box size="0.2 0.2 0.2"/></geometry></collision>
  </link>
  <gazebo reference="base">{SENSORS}
  </gazebo>
  <gazebo>{P3D}</gazebo>
</robot>"""

# the world-file model's topic and frame id, its twin's: the laser and the camera resolve their
# frameName against a tf_prefix parameter found from their namespace, the range plugin against one of
# its own namespace only (none here: each as given, as gazebo_ros_pkgs 2.9.2's plugins); the IMU
# sensor keeps it as given; p3d publishes in `world`.
TOPICS = [('/scan', 'base', '/twin/scan', 'base'),
          ('/cam/image_raw', 'base', '/twin/cam/image_raw', 'base'),
          ('/cam/camera_info', 'base', '/twin/cam/camera_info', 'base'),
          ('/range', 'base', '/twin/range', 'base'),
          ('/probe/imu', 'base', '/twin/imu', 'base'),
          ('/ground_truth', 'world', '/twin/ground_truth', 'world')]


def test_a_world_file_sdf_model_publishes_as_its_urdf_twin(ros, tmp_path):
    walls = ''.join(box_model(name, (0.2, 2.0, 1.0), (1.5, y, 0.5))
                    for name, y in (('wall', 0.0), ('twin_wall', 20.0), ('sdf_twin_wall', -20.0)))
    (tmp_path / 'probe.world').write_text(sdf_world(SDF_MODEL + walls))
    (tmp_path / 'twin.urdf').write_text(URDF_TWIN)
    plant = start_plant(ros, str(tmp_path / 'probe.world'))
    ros.set_param('/twin_description', textfile=str(tmp_path / 'twin.urdf'))
    spawn_urdf(ros, plant, '/twin_description', 'twin', robot_namespace='/twin', xyz=(0, 20, 0.1))
    # The same SDF spawned by spawn_sdf_model in a namespace of its own publishes as the twin does there.
    spawned = ros.run(['rosrun', 'gazebo_ros', 'spawn_model', '-sdf', '-stdin', '-model', 'sdf_twin', '-y', '-20',
                       '-robot_namespace', '/sdf_twin'], timeout=60,
                      input='<sdf version="1.6">%s</sdf>' % SDF_MODEL.replace('"probe"', '"anything"'))
    assert spawned.returncode == 0, spawned.stdout + spawned.stderr + plant.log()
    topics = [t for sdf_topic, _, urdf_topic, _ in TOPICS for t in (sdf_topic, urdf_topic)]
    spawned_topics = [t.replace('/twin/', '/sdf_twin/') for _, _, t, _ in TOPICS]
    seen = ros.probe('sensor_plugins/probes/messages_after.py', 1.0, *topics, *spawned_topics, timeout=90)
    for _, _, urdf_topic, twin_frame in TOPICS:
        spawned_topic = urdf_topic.replace('/twin/', '/sdf_twin/')
        assert seen[spawned_topic]['frame'] == twin_frame.replace('twin/', 'sdf_twin/'), spawned_topic
    assert seen['/sdf_twin/scan']['ranges'] == pytest.approx(seen['/scan']['ranges'], abs=2e-3)
    assert seen['/sdf_twin/ground_truth']['position'] == pytest.approx([0.0, -20.0, 0.1], abs=2e-3)
    for sdf_topic, frame, urdf_topic, twin_frame in TOPICS:
        mine, twin = seen[sdf_topic], seen[urdf_topic]
        assert mine['type'] == twin['type'], (sdf_topic, mine['type'], twin['type'])
        assert [mine['frame'], twin['frame']] == [frame, twin_frame], sdf_topic
    scan, twin_scan = seen['/scan'], seen['/twin/scan']
    assert len(scan['ranges']) == len(twin_scan['ranges']) == 9
    assert scan['ranges'] == pytest.approx(twin_scan['ranges'], abs=2e-3)
    assert scan['ranges'][4] == pytest.approx(1.5 - 0.1 - 0.1, abs=5e-3), 'the wall face 1.3 m before the lidar'
    sonar, twin_sonar = seen['/range'], seen['/twin/range']
    assert sonar['range'] == pytest.approx(twin_sonar['range'], abs=2e-3)
    assert sonar['range'] == pytest.approx(1.5 - 0.1 - 0.1, abs=5e-3), 'the nearest ray: the wall face 1.3 m ahead'
    assert [sonar['radiation'], sonar['fov']] == [twin_sonar['radiation'], twin_sonar['fov']] == [0, pytest.approx(0.2)]
    image, twin_image = seen['/cam/image_raw'], seen['/twin/cam/image_raw']
    assert [image['width'], image['height'], image['encoding']] == [twin_image['width'], twin_image['height'],
                                                                    twin_image['encoding']] == [16, 12, 'rgb8']
    assert image['mean'] == pytest.approx(twin_image['mean'], abs=3.0), 'both see their wall alike'
    assert seen['/cam/camera_info']['K'] == pytest.approx(seen['/twin/cam/camera_info']['K'])
    imu, twin_imu = seen['/probe/imu'], seen['/twin/imu']
    assert imu['acceleration'] == pytest.approx(twin_imu['acceleration'], abs=0.05)
    assert imu['acceleration'][2] == pytest.approx(9.8, abs=0.1)
    assert imu['orientation'] == pytest.approx(twin_imu['orientation'], abs=1e-3)
    # turned 0.3 rad in its link: its orientation in the world (REP 145, gazebo_ros_pkgs 2.9's default)
    assert 2 * math.atan2(imu['orientation'][2], imu['orientation'][3]) == pytest.approx(0.3, abs=1e-3)
    truth, twin_truth = seen['/ground_truth'], seen['/twin/ground_truth']
    assert truth['child'] == twin_truth['child'] == 'base'
    assert truth['position'] == pytest.approx([0.0, 0.0, 0.1], abs=2e-3)
    assert twin_truth['position'] == pytest.approx([0.0, 20.0, 0.1], abs=2e-3)
    log = plant.log()
    assert "world model 'probe' loaded" in log, log
