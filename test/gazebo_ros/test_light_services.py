"""gazebo_ros's light services on the plant (get_light_properties, set_light_properties, delete_light,
gazebo_ros_api_plugin.cpp's status messages), seen by a gazebo_ros_camera: a static model's camera
3 m up looks straight down at the ground plane (Gazebo/Grey: ambient 0.3, diffuse 0.7) under a sun
shining straight down (model://sun's colour and attenuation, no specular), a point lamp 1 m above the
floor and an ambient light of 0.2. Each change shows in the first frame stamped
after the call: a brighter lamp, the lamp deleted, the sun slanted 45 degrees, the sun deleted (the
ambient light alone)."""
import pytest

from plant_helpers import sdf_world
from ros_harness import start_plant

pytestmark = pytest.mark.ros

AMBIENT, DIFFUSE = 0.3 * 255, 0.7 * 255  # the ground plane's Gazebo/Grey
LIGHTS = """<scene><ambient>0.2 0.2 0.2 1</ambient><shadows>false</shadows></scene>
<light name="sun" type="directional"><direction>0 0 -1</direction><diffuse>0.8 0.8 0.8 1</diffuse>
  <specular>0 0 0 1</specular><attenuation><range>1000</range><constant>0.9</constant><linear>0.01</linear>
  <quadratic>0.001</quadratic></attenuation></light>
<light name="lamp" type="point"><pose>0 0 1 0 0 0</pose><diffuse>0.5 0.5 0.5 1</diffuse>
  <attenuation><range>5</range><constant>1</constant><linear>0.5</linear><quadratic>0</quadratic></attenuation></light>
<model name="eye"><static>true</static><pose>0 0 3 0 1.5707963267948966 0</pose><link name="link">
  <sensor name="camera" type="camera"><update_rate>20</update_rate><camera><horizontal_fov>1.2</horizontal_fov>
    <image><width>40</width><height>30</height></image><clip><near>0.1</near><far>10</far></clip></camera>
    <plugin name="eye_plugin" filename="libgazebo_ros_camera.so"><cameraName>eye</cameraName></plugin>
  </sensor></link></model>"""


def test_light_services_change_what_the_camera_sees(ros, tmp_path):
    world = tmp_path / 'lit.world'
    world.write_text(sdf_world(LIGHTS))
    plant = start_plant(ros, str(world))
    out = ros.probe('gazebo_ros/probes/light_services_change_what_the_camera_sees.py', timeout=180)
    assert out['lamp'] == [[True, ''], pytest.approx([0.5, 0.5, 0.5, 1.0]), pytest.approx([1.0, 0.5, 0.0])]
    # the sun's colour and attenuation as the world gives them (a directional light is not attenuated)
    assert out['sun'] == [[True, ''], pytest.approx([0.8, 0.8, 0.8, 1.0]), pytest.approx([0.9, 0.01, 0.001])]
    assert out['unknown'][0] == [False, 'getLightProperties: Requested light nolamp not found!']
    lit = AMBIENT * 0.2 + DIFFUSE * 0.8  # ambient and the sun straight down
    assert out['start'] > lit + 5, 'the lamp adds its share'
    assert out['set_lamp'] == [True, '']
    assert out['brighter'] > out['start'] + 5
    assert out['lamp_after'] == [[True, ''], pytest.approx([1.0, 1.0, 1.0, 1.0]), pytest.approx([1.0, 0.5, 0.0])]
    assert out['dark_attenuation'][0] is False and 'lights nothing' in out['dark_attenuation'][1]
    assert out['set_unknown'] == [False, 'setLightProperties: Requested light nolamp not found!']
    assert out['delete_lamp'] == [True, 'DeleteLight: lamp successfully deleted']
    assert out['without_lamp'] == pytest.approx(lit, abs=2.0), plant.log()
    assert out['delete_again'] == [False, 'DeleteLight: Requested light lamp not found!']
    assert out['slant_sun'] == [True, '']
    assert out['slanted'] == pytest.approx(AMBIENT * 0.2 + DIFFUSE * 0.8 * 0.5 ** 0.5, abs=2.0)
    assert out['delete_sun'] == [True, 'DeleteLight: sun successfully deleted']
    assert out['ambient_only'] == pytest.approx(AMBIENT * 0.2, abs=2.0)
    assert out['sun_gone'][0] == [False, 'getLightProperties: Requested light sun not found!']
