"""A world file's static models through gazebo_ros, as Gazebo has them: a goal sign listed in
/gazebo/model_states, moved by set_model_state (a teleport) and taken out by delete_model, and what a
lidar and a camera (gazebo_ros_laser, gazebo_ros_camera on a static post looking at it) see after each."""
import pytest

from plant_helpers import sdf_world
from ros_harness import RosSystem, start_plant

pytestmark = pytest.mark.ros

# A post 0.5 m up with a 5-ray lidar and a 16 x 16 camera looking along x, at a red sign 2 m off
# (its near face 1.9 m away) on a grey ground.
POST = """<model name="post"><static>true</static><pose>0 0 0.5 0 0 0</pose><link name="head">
  <sensor name="lidar" type="ray"><update_rate>20</update_rate>
    <ray><scan><horizontal><samples>5</samples><min_angle>-0.1</min_angle><max_angle>0.1</max_angle></horizontal></scan>
      <range><min>0.1</min><max>10</max><resolution>0.01</resolution></range></ray>
    <plugin name="lidar" filename="libgazebo_ros_laser.so"><topicName>/post/scan</topicName><frameName>head</frameName></plugin>
  </sensor>
  <sensor name="camera" type="camera"><update_rate>20</update_rate>
    <camera><horizontal_fov>0.4</horizontal_fov><image><width>16</width><height>16</height><format>R8G8B8</format></image>
      <clip><near>0.1</near><far>20</far></clip></camera>
    <plugin name="camera" filename="libgazebo_ros_camera.so"><cameraName>post/camera</cameraName>
      <imageTopicName>image_raw</imageTopicName><frameName>head</frameName></plugin>
  </sensor></link></model>"""
SIGN = """<model name="sign"><static>true</static><pose>2 0 0.5 0 0 0</pose><link name="board">
  <collision name="board"><geometry><box><size>0.2 1 1</size></box></geometry></collision>
  <visual name="board"><geometry><box><size>0.2 1 1</size></box></geometry>
    <material><ambient>1 0 0 1</ambient><diffuse>1 0 0 1</diffuse></material></visual></link></model>"""


@pytest.fixture(scope='module')
def sim(tmp_path_factory):
    work = tmp_path_factory.mktemp('static_models')
    world = work / 'sign.world'
    world.write_text(sdf_world(POST + SIGN))
    system = RosSystem(str(work))
    try:
        system.plant = start_plant(system, str(world))
        yield system
    finally:
        system.close()


def test_a_static_model_is_listed_teleported_and_deleted_and_the_sensors_see_it(sim):
    out = sim.probe('gazebo_ros/probes/static_models_move_and_go.py', timeout=120)
    assert {'ground_plane', 'post', 'sign'} <= set(out['models']), out['models']
    assert out['sign_props'] == {'success': True, 'body_names': ['board'], 'geom_names': ['board'],
                                 'joint_names': [], 'is_static': True}
    assert out['sign_state'] == pytest.approx([2.0, 0.0, 0.5], abs=1e-6)
    # where the file put it: the lidar's middle ray meets its face, the camera's middle is red
    assert out['before']['range'] == pytest.approx(1.9, abs=0.02)
    assert out['before']['red'], out['before']
    # teleported 3 m sideways: listed there, the rays and the camera pass where it was
    assert out['moved_set'] == [True, 'SetModelState: set model state done']
    assert out['moved_state'] == pytest.approx([2.0, 3.0, 0.5], abs=1e-6)
    assert out['moved_listed'] == pytest.approx([2.0, 3.0, 0.5], abs=1e-6)
    assert out['moved']['range'] > 9.0, out['moved']
    assert not out['moved']['red'], out['moved']
    # back in front of the post, then deleted: gone from model_states, from the rays and the camera
    assert out['back']['range'] == pytest.approx(1.9, abs=0.02) and out['back']['red']
    assert out['delete'] == [True, 'DeleteModel: successfully deleted model']
    assert 'sign' not in out['after_delete'], out['after_delete']
    assert out['deleted']['range'] > 9.0 and not out['deleted']['red'], out['deleted']
