"""gazebo_ros_triggered_camera in a world file's model, as gazebo_ros_pkgs' triggered_camera test
uses it: the camera (1 Hz) publishes nothing until a std_msgs/Empty on <cameraName>/image_trigger,
then one frame per trigger, two triggers 10 ms apart giving two, each stamped at the step it was
rendered at (received within 0.2 s of simulated time)."""
import pytest

from plant_helpers import sdf_world
from ros_harness import start_plant

pytestmark = pytest.mark.ros

EYE = """<model name="eye"><static>true</static><pose>0 0 1 0 0.5 0</pose><link name="link">
  <sensor name="camera1" type="camera"><update_rate>1</update_rate>
    <camera><horizontal_fov>1.0</horizontal_fov><image><width>32</width><height>24</height></image>
      <clip><near>0.05</near><far>20</far></clip></camera>
    <plugin name="camera_controller" filename="libgazebo_ros_triggered_camera.so">
      <cameraName>cam</cameraName><updateRate>0</updateRate><frameName>eye</frameName></plugin>
  </sensor></link></model>"""


def test_a_triggered_camera_publishes_one_frame_per_trigger(ros, tmp_path):
    (tmp_path / 'eye.world').write_text(sdf_world(EYE))
    plant = start_plant(ros, str(tmp_path / 'eye.world'))
    # the probe on simulated time: after the launch file has set /use_sim_time
    ros.wait_until(lambda: '/gazebo/get_model_state' in ros.services(), 60, 'the node')
    counts = ros.probe('sensor_plugins/probes/triggered_camera_frames.py', timeout=90)
    assert counts['trigger_subscribers'] == ['/gazebo'], counts
    assert counts['untriggered'] == 0, 'a 1 Hz camera publishes nothing in 1.5 s until triggered'
    assert counts['after_one'] == 1, counts
    assert counts['after_two_more'] == 3, counts
    assert counts['stamp_lag'] < 0.2, counts
    assert plant.popen.poll() is None
