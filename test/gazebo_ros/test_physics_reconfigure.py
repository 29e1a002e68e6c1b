"""gazebo_ros's physics dynamic_reconfigure (gazebo_ros/cfg/Physics.cfg, physicsReconfigureCallback) on
the plant: /gazebo/parameter_descriptions lists PhysicsConfig's 15 parameters with its types, levels
and ranges; the first configuration is the physics' own; /gazebo/set_parameters applies the
configuration through set_physics_properties' work when it differs from the physics, and the
parameters land on the parameter server; a value the plant refuses changes nothing and the reply
says what holds. set_physics_properties honours the solver's passes, over-relaxation, surface layer
and correcting velocity, and refuses a request with one out of the plant's range whole."""
import pytest

from ros_harness import start_plant

pytestmark = pytest.mark.ros

# PhysicsConfig (gazebo_ros noetic-devel cfg/Physics.cfg): name -> type, level, min, max, default
PHYSICS_CONFIG = {
    'time_step': ['double', 1, 0, 10, 0.001],
    'max_update_rate': ['double', 1, 0, 1000, 60],
    'gravity_x': ['double', 1, -100, 100, 0],
    'gravity_y': ['double', 1, -100, 100, 0],
    'gravity_z': ['double', 1, -100, 100, -9.8],
    'auto_disable_bodies': ['bool', 1, False, True, False],
    'sor_pgs_precon_iters': ['int', 1, 0, 10000, 0],
    'sor_pgs_iters': ['int', 1, 0, 10000, 20],
    'sor_pgs_w': ['double', 1, 0, 5, 1.3],
    'sor_pgs_rms_error_tol': ['double', 1, -1, 10000, -1],
    'cfm': ['double', 1, 0, 10, 0],
    'erp': ['double', 1, 0, 10, 0.2],
    'contact_surface_layer': ['double', 1, 0, 10, 0.001],
    'contact_max_correcting_vel': ['double', 1, 0, 10000000, 100],
    'max_contacts': ['int', 1, 0, 10000000, 100],
}


def test_physics_reconfigure_as_gazebo_ros_serves_it(ros):
    plant = start_plant(ros)
    out = ros.probe('gazebo_ros/probes/physics_reconfigure_and_ode_settings.py', timeout=120)
    descriptions = out['descriptions']
    assert set(descriptions) == set(PHYSICS_CONFIG)
    for name, (kind, level, low, high, default) in PHYSICS_CONFIG.items():
        assert descriptions[name][:2] == [kind, level], name
        assert descriptions[name][2:] == [pytest.approx(low), pytest.approx(high), pytest.approx(default)], name
    assert out['initial'] == pytest.approx(out['physics'])
    assert out['initial'] == pytest.approx([0.001, 1000.0, -9.8, 10, 100.0])
    assert out['changed'] == pytest.approx([-4.0, 0.002, 30])
    # max_update_rate stays 1000 steps a second (Gazebo's real_time_update_rate): 2 ms steps run twice as fast
    assert out['after'] == pytest.approx([-4.0, 0.002, 30, 1.2, 0.002, 1000.0])
    assert out['params'] == pytest.approx([-4.0, 0.002])
    assert out['refused'] == pytest.approx([0.002, -4.0, 0.002, -4.0])
    assert out['last_update'] == pytest.approx([0.002, -4.0])
    assert 'physics dynamics reconfigure refused: time step 0 s is outside [1e-09, 0.1] s' in plant.log()
    assert out['set'] == [True, 'physics engine updated']
    assert out['set_after'] == pytest.approx([0.001, -9.8, 40, 1.5, 0.003, 50.0])
    assert out['no_passes'] == [False, 'SetPhysicsProperties: sor_pgs_iters 0 is not a number of solver passes '
                                       'from 1 to 1000; nothing was changed']
    assert out['sor_too_big'][0] is False and 'sor_pgs_w 2.5 is outside (0, 2)' in out['sor_too_big'][1]
    assert out['unchanged'] == pytest.approx([0.001, -9.8, 40])
    log = plant.log()
    # ODE's own settings are said once each
    assert log.count('ode_config.erp is not honoured') == 1 and log.count('ode_config.max_contacts is not honoured') == 1
