"""gazebo_ros_pkgs' gazebo_ros_harness (libgazebo_ros_harness.so, over Gazebo's HarnessPlugin,
src/gazebo/plugins/) in a world file's model, called as its users call it: a std_msgs/Float32 on
/<model>/harness/velocity lowers the model at that speed (in simulated time), a std_msgs/Bool true on
/<model>/harness/detach lets it fall to the ground (its link read through gazebo_ros's
get_link_state). The harness is Gazebo's harness world's: a prismatic joint from the world to the
model's link, made at run time, its winch and detach joint; the box is written for the test."""
import pytest

from ros_harness import start_plant

pytestmark = pytest.mark.ros

HARNESS_WORLD = """<?xml version="1.0"?>
<sdf version="1.6">
  <world name="default">
    <include><uri>model://ground_plane</uri></include>
    <model name="box">
      <pose>0 0 2 0 0 0</pose>
      <link name="link">
        <inertial><mass>10</mass><inertia><ixx>0.4</ixx><iyy>0.4</iyy><izz>0.4</izz></inertia></inertial>
        <collision name="c"><geometry><box><size>0.5 0.5 0.5</size></box></geometry></collision>
      </link>
      <plugin name="harness" filename="libgazebo_ros_harness.so">
        <joint name="joint1" type="prismatic">
          <pose>0 0 0 0 0 0</pose>
          <parent>world</parent>
          <child>link</child>
          <axis><xyz>0 0 1</xyz><dynamics><damping>10</damping></dynamics>
            <limit><lower>-1.5</lower><upper>1.5</upper><effort>10000</effort></limit></axis>
        </joint>
        <winch><joint>joint1</joint>
          <pos_pid><p>1000000</p><i>0</i><d>0</d><i_max>0</i_max><i_min>0</i_min><cmd_max>2000</cmd_max><cmd_min>-2000</cmd_min></pos_pid>
          <vel_pid><p>10000</p><i>0</i><d>0</d><i_max>0</i_max><i_min>0</i_min><cmd_max>10000</cmd_max><cmd_min>0</cmd_min></vel_pid>
        </winch>
        <detach>joint1</detach>
      </plugin>
    </model>
  </world>
</sdf>
"""


@pytest.mark.slow
def test_the_harness_lowers_the_box_at_the_speed_on_its_topic_and_lets_it_fall_when_detached(ros, tmp_path):
    world = tmp_path / 'harness.world'
    world.write_text(HARNESS_WORLD)
    plant = start_plant(ros, str(world))
    ros.service('/gazebo/get_world_properties', wait=True, timeout=60)

    def box_z():
        return ros.service('/gazebo/get_link_state', '{link_name: "box::link"}')['link_state']['pose']['position']['z']

    def sim_time():
        return ros.service('/gazebo/get_world_properties')['sim_time']
    assert box_z() == pytest.approx(2.0, abs=0.005), plant.log()
    ros.run(['rostopic', 'pub', '-1', '/box/harness/velocity', 'std_msgs/Float32', 'data: -0.1'], timeout=30)
    ros.wait_until(lambda: box_z() < 1.95, 30, 'the box going down')
    # At the winch's speed, in simulated time, read between two heights well above the joint's
    # lower limit (1.5 m down).
    z0, t0 = box_z(), sim_time()
    ros.wait_until(lambda: sim_time() > t0 + 2.0, 30, 'two seconds of simulated time')
    z1, t1 = box_z(), sim_time()
    assert z1 > 0.6, 'at the lower limit already: %g' % z1
    assert (z0 - z1) / (t1 - t0) == pytest.approx(0.1, rel=0.1)
    ros.run(['rostopic', 'pub', '-1', '/box/harness/detach', 'std_msgs/Bool', 'data: true'], timeout=30)
    ros.wait_until(lambda: box_z() < 0.26, 30, 'the box on the ground')
    assert plant.popen.poll() is None, plant.log()
