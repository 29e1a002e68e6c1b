"""gazebo_ros's get/set_link_properties and set_joint_properties on the plant, with
gazebo_ros_api_plugin.cpp's status messages: a free crate (1 kg) with gravity off floats where it is,
and a 2 N push for 0.5 s gains it 1 m/s at 1 kg and 0.25 m/s once set to 4 kg; a new centre of mass is
not taken, values no link can have are refused, gravity back on drops it. A spinner on a vertical
axis: damping holds it at effort / damping, ODE's joint motor (fmax, vel) turns it at vel, its stops
hold it, a low stop above the high one frees it."""
import pytest

from ros_harness import start_plant

pytestmark = pytest.mark.ros


def test_link_and_joint_properties_change_the_dynamics(ros):
    plant = start_plant(ros, paused=True)
    out = ros.probe('gazebo_ros/probes/link_and_joint_properties_change_the_dynamics.py', timeout=180)
    spawned = [True, 'SpawnModel: Successfully spawned entity']
    assert out['spawn'] == [spawned, spawned]
    got = [True, 'GetLinkProperties: got properties']
    assert out['crate'] == [got, 1.0, pytest.approx([0.01, 0.01, 0.01, 0, 0, 0]), True, [0, 0, 0, 1]]
    assert out['unknown'][0] == [False, 'GetLinkProperties: link not found, did you forget to scope the link by '
                                        'model name?']
    properties_set = [True, 'SetLinkProperties: properties set']
    assert out['gravity_off'] == properties_set
    assert out['floating_z'] == pytest.approx(1.0, abs=1e-6)
    assert out['pushed_1kg'] == pytest.approx(1.0, rel=0.01)
    assert out['heavier'] == properties_set
    assert out['crate_after'] == [got, 4.0, pytest.approx([0.04, 0.04, 0.04, 0, 0, 0]), False, [0, 0, 0, 1]]
    assert out['pushed_4kg'] == pytest.approx(0.25, rel=0.01)
    assert out['moved_com'] == properties_set and out['com_after'] == [0, 0, 0, 1]
    assert "crate::body: The link's centre of mass stays at 0 0 0" in plant.log()
    assert out['negative_mass'][0] is False and 'mass -1 is outside [0, 1e+06] kg' in out['negative_mass'][1]
    assert out['nan_inertia'][0] is False and 'must be finite' in out['nan_inertia'][1]
    assert out['gravity_on'] == properties_set and out['fell'] > 0.1

    assert out['joint_unknown'] == [False, 'SetJointProperties: joint not found']
    assert out['negative_damping'][0] is False and 'damping -1 is not' in out['negative_damping'][1]
    joint_set = [True, 'SetJointProperties: properties set']
    assert out['damping'] == joint_set
    assert out['damped_rate'] == pytest.approx(0.1, rel=0.02)
    assert out['motor'] == joint_set
    assert out['motor_rate'] == pytest.approx(2.0, rel=0.01)
    assert out['stops'] == joint_set
    assert out['at_stop'] == pytest.approx(0.1, abs=0.005)
    assert plant.log().count('ode_joint_config.erp is not honoured') == 1
    assert out['no_stops'] == joint_set
    assert out['past_stop'] > 0.5
