"""gazebo_ros_pkgs' gazebo_ros_wheel_slip (libgazebo_ros_wheel_slip.so, over Gazebo's WheelSlipPlugin,
src/gazebo/plugins/) in a world file's model, reconfigured as its users reconfigure it: its
dynamic_reconfigure server on /<model>/wheel_slip. A rig written for the test: a 0.1 m sphere wheel
on a spin joint under a carriage free to move up and down (its 98 N rest on the wheel), on a slider
that runs along x against a damper of 98 N s/m. A torque of 4.9 N m on the wheel (gazebo_ros's
apply_joint_effort) pushes the ground with 49 N, so the rig goes at 49 / 98 = 0.5 m/s. Without slip
the wheel rolls, r w = v (5 rad/s). With a longitudinal compliance c, ODE's slip is r w / N * c and
the contact slides at slip * F: r w (1 - c F / N) = v, so at c = 1 the wheel spins twice as fast
(10 rad/s) for the same speed of the rig."""
import pytest

from ros_harness import start_plant

pytestmark = pytest.mark.ros

RIG_WORLD = """<?xml version="1.0"?>
<sdf version="1.6">
  <world name="default">
    <gravity>0 0 -9.8</gravity>
    <model name="ground"><static>true</static><link name="link">
      <collision name="c"><geometry><plane><normal>0 0 1</normal><size>100 100</size></plane></geometry>
        <surface><friction><ode><mu>2</mu><mu2>2</mu2></ode></friction></surface></collision></link></model>
    <model name="rig">
      <link name="slider"><pose>0 0 0.1 0 0 0</pose>
        <inertial><mass>0.5</mass><inertia><ixx>0.01</ixx><iyy>0.01</iyy><izz>0.01</izz></inertia></inertial></link>
      <link name="carriage"><pose>0 0 0.1 0 0 0</pose>
        <inertial><mass>8</mass><inertia><ixx>0.1</ixx><iyy>0.1</iyy><izz>0.1</izz></inertia></inertial></link>
      <link name="wheel"><pose>0 0 0.1 0 0 0</pose>
        <inertial><mass>2</mass><inertia><ixx>0.008</ixx><iyy>0.008</iyy><izz>0.008</izz></inertia></inertial>
        <collision name="tire"><geometry><sphere><radius>0.1</radius></sphere></geometry>
          <surface><friction><ode><mu>2</mu><mu2>2</mu2><fdir1>0 1 0</fdir1></ode></friction></surface>
        </collision></link>
      <joint name="run" type="prismatic"><parent>world</parent><child>slider</child>
        <axis><xyz>1 0 0</xyz><dynamics><damping>98</damping></dynamics></axis></joint>
      <joint name="bounce" type="prismatic"><parent>slider</parent><child>carriage</child>
        <axis><xyz>0 0 1</xyz></axis></joint>
      <joint name="spin" type="revolute"><parent>carriage</parent><child>wheel</child>
        <axis><xyz>0 1 0</xyz></axis></joint>
      <plugin name="wheel_slip" filename="libgazebo_ros_wheel_slip.so">
        <wheel link_name="wheel">
          <slip_compliance_lateral>0</slip_compliance_lateral>
          <slip_compliance_longitudinal>0</slip_compliance_longitudinal>
          <wheel_normal_force>98</wheel_normal_force>
        </wheel>
      </plugin>
    </model>
  </world>
</sdf>
"""


@pytest.mark.slow
def test_the_longitudinal_compliance_set_by_dynamic_reconfigure_lets_the_driven_wheel_slip(ros, tmp_path):
    world = tmp_path / 'wheel_slip.world'
    world.write_text(RIG_WORLD)
    plant = start_plant(ros, str(world))
    ros.service('/gazebo/get_world_properties', wait=True, timeout=60)

    def sim_time():
        return ros.service('/gazebo/get_world_properties')['sim_time']

    def wheel_rate():
        return ros.service('/gazebo/get_joint_properties', '{joint_name: "rig::spin"}')['rate'][0]

    def rig_speed():
        return ros.service('/gazebo/get_link_state', '{link_name: "rig::slider"}')['link_state']['twist']['linear']['x']

    def settle(seconds):
        t0 = sim_time()
        ros.wait_until(lambda: sim_time() > t0 + seconds, 60, '%g s of simulated time' % seconds)

    ros.service('/gazebo/apply_joint_effort',
                '{joint_name: "rig::spin", effort: 4.9, start_time: {secs: 0, nsecs: 0}, duration: {secs: -1, nsecs: 0}}')
    settle(3.0)
    assert rig_speed() == pytest.approx(0.5, abs=0.03), plant.log()
    assert wheel_rate() == pytest.approx(5.0, abs=0.2), plant.log()

    ros.service('/rig/wheel_slip/set_parameters',
                '{config: {doubles: [{name: slip_compliance_unitless_longitudinal, value: 1.0}]}}', wait=True, timeout=30)
    settle(3.0)
    assert rig_speed() == pytest.approx(0.5, abs=0.03), plant.log()
    assert wheel_rate() == pytest.approx(10.0, abs=0.5), plant.log()
    assert 'New longitudinal slip compliance: 1.000e+00' in plant.log()
    assert plant.popen.poll() is None, plant.log()
