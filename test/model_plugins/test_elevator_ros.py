"""gazebo_ros_pkgs' gazebo_ros_elevator (libgazebo_ros_elevator.so, over Gazebo's ElevatorPlugin,
src/gazebo/plugins/) in a world file's model, called as its users call it: a floor number in a
std_msgs/String on /elevator takes the car to floor x <floor_height> (its link read through
gazebo_ros's get_link_state), and a word that is no floor is an error on ROS's log while the car
stays and the simulator runs. The elevator is written for the test: a shaft fixed to the world, a car
on a prismatic lift, a door sliding on the car."""
import pytest

from ros_harness import start_plant

pytestmark = pytest.mark.ros

ELEVATOR_WORLD = """<?xml version="1.0"?>
<sdf version="1.6">
  <world name="default">
    <include><uri>model://ground_plane</uri></include>
    <model name="elevator">
      <pose>0 0 0.1 0 0 0</pose>
      <link name="shaft"><inertial><mass>1000</mass></inertial></link>
      <joint name="shaft_fixed" type="fixed"><parent>world</parent><child>shaft</child></joint>
      <link name="car">
        <inertial><mass>200</mass><inertia><ixx>50</ixx><iyy>50</iyy><izz>50</izz></inertia></inertial>
        <collision name="floor"><geometry><box><size>2 2 0.1</size></box></geometry></collision>
      </link>
      <joint name="lift" type="prismatic"><parent>shaft</parent><child>car</child>
        <axis><xyz>0 0 1</xyz><limit><lower>0</lower><upper>7</upper></limit></axis></joint>
      <link name="door"><pose>1 0 1 0 0 0</pose>
        <inertial><mass>10</mass><inertia><ixx>1</ixx><iyy>1</iyy><izz>1</izz></inertia></inertial>
      </link>
      <joint name="door_slide" type="prismatic"><parent>car</parent><child>door</child>
        <axis><xyz>0 1 0</xyz><limit><lower>0</lower><upper>1</upper></limit></axis></joint>
      <plugin name="elevator" filename="libgazebo_ros_elevator.so">
        <lift_joint>lift</lift_joint>
        <door_joint>door_slide</door_joint>
        <floor_height>2</floor_height>
        <door_wait_time>1</door_wait_time>
      </plugin>
    </model>
  </world>
</sdf>
"""


def start_elevator(ros, tmp_path):
    """The plant on ELEVATOR_WORLD, up: (the plant, a function giving the car's height)."""
    world = tmp_path / 'elevator.world'
    world.write_text(ELEVATOR_WORLD)
    plant = start_plant(ros, str(world))
    ros.service('/gazebo/get_world_properties', wait=True, timeout=60)

    def car_z():
        return ros.service('/gazebo/get_link_state', '{link_name: "elevator::car"}')['link_state']['pose']['position']['z']
    return plant, car_z


@pytest.mark.slow
def test_a_floor_on_the_elevator_topic_takes_the_car_there(ros, tmp_path):
    plant, car_z = start_elevator(ros, tmp_path)
    assert car_z() == pytest.approx(0.1, abs=0.15), plant.log()
    ros.run(['rostopic', 'pub', '-1', '/elevator', 'std_msgs/String', "data: '2'"], timeout=30)
    ros.wait_until(lambda: car_z() > 0.1 + 4.0 - 0.15, 60, 'the car at floor 2 (4 m up)')
    assert plant.popen.poll() is None, plant.log()


def test_a_word_that_is_no_floor_is_an_error_and_the_car_stays(ros, tmp_path):
    """The plant's own plugin (upstream's throws in its ROS thread, which ends the server)."""
    plant, car_z = start_elevator(ros, tmp_path)
    ros.run(['rostopic', 'pub', '-1', '/elevator', 'std_msgs/String', "data: 'up'"], timeout=30)
    ros.wait_until(lambda: "'up' on /elevator is not a floor number" in plant.log(), 30, 'the error on the log')
    assert car_z() == pytest.approx(0.1, abs=0.15)
    assert plant.popen.poll() is None, plant.log()
