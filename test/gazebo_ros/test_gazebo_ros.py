"""gazebo_ros's interfaces on the plant (docs/interfaces.md section 10): the tutorial's launch files
as it prints them, every /gazebo service's success and error cases with gazebo_ros's status
messages, the model and link state topics, spawn_model's command line, and scripts that drive the
car from /gazebo/link_states with ackermann_msgs/AckermannDriveStamped. Each test has its own master."""
import hashlib
import math
import os

import pytest

from suite_paths import TEST_DIR
from ros_harness import PYTHON, tianracer_plant
from tianracer_description.tianracer import PACKAGE, TUTORIAL_CONTROLLERS


# sha256 of the tutorial's two launch files as it prints them (tabs, comments, trailing spaces and all).
TUTORIAL_LAUNCH_SHA256 = {
    'tianracer.launch': '2cc6cf4556db98bdb8269ba85f807ecdae92062d4c9ba2ee941c529a6cfae0db',
    'control.launch': '4a67d6a1ecb647b129b53728c99c6ba13cc76575f6d856bad2da53c3df24fbb8',
}


@pytest.mark.parametrize('name', sorted(TUTORIAL_LAUNCH_SHA256))
def test_the_tutorials_launch_files_are_kept_byte_for_byte(name):
    with open(os.path.join(PACKAGE, 'launch', name), 'rb') as f:
        assert hashlib.sha256(f.read()).hexdigest() == TUTORIAL_LAUNCH_SHA256[name]


def test_tianracer_launch_uses_gazebo_ros_as_the_tutorial_does():
    with open(os.path.join(PACKAGE, 'launch', 'tianracer.launch')) as f:
        text = f.read()
    assert '$(find gazebo_ros)/launch/empty_world.launch' in text
    assert 'pkg="gazebo_ros" type="spawn_model"' in text


@pytest.fixture
def paused_plant(ros, urdf_file):
    """The plant paused with the car spawned (tianracer_plant), so that states stay where they are set."""
    return tianracer_plant(ros, urdf_file, paused=True)


@pytest.mark.ros
def test_queries_answer_with_gazebo_ros_flags_and_messages(ros, paused_plant):
    out = ros.probe('gazebo_ros/probes/queries_answer_with_gazebo_ros_flags_and_messages.py', timeout=90)
    assert out['world'] == [['ground_plane', 'tianracer'], True, 'GetWorldProperties: got properties']
    assert out['props'] == [[True, 'GetModelProperties: got properties'], True, True]
    assert out['props_unknown'] == [False, 'GetModelProperties: model does not exist']
    assert out['model'][0] == [True, 'GetModelState: got properties'] and abs(out['model'][1]) < 0.05
    assert out['model_unknown'] == [False, 'GetModelState: model does not exist']
    assert out['model_bad_frame'] == [False, 'GetModelState: reference relative_entity_name not found, did you '
                                             'forget to scope the body by model name?']
    # base_footprint (the model frame) seen from base_link: the rear axle is above the ground.
    assert out['model_relative'][0][0] and out['model_relative'][2] < -0.01
    assert out['link'][0] == [True, 'GetLinkState: got state'] and out['link'][1] > 0.05
    link_not_found = [False, 'GetLinkState: link not found, did you forget to scope the link by model name?']
    assert out['link_unknown'] == link_not_found and out['link_unscoped'] == link_not_found
    assert out['link_bad_frame'] == [False, 'GetLinkState: reference reference_frame not found, did you forget '
                                            'to scope the link by model name?']
    assert out['physics'] == [[True, 'GetPhysicsProperties: got properties'], 0.001, True, pytest.approx(-9.8),
                              pytest.approx(1000.0)]


@pytest.mark.ros
def test_setters_move_the_car_and_refuse_unknown_names(ros, paused_plant):
    out = ros.probe('gazebo_ros/probes/setters_move_the_car_and_refuse_unknown_names.py', timeout=90)
    assert out['set'] == [True, 'SetModelState: set model state done']
    assert out['after_set'] == [pytest.approx(1.0, abs=1e-4), pytest.approx(2.0, abs=1e-4), pytest.approx(1.0, abs=1e-4)]
    assert out['set_unknown'] == [False, 'SetModelState: model does not exist']
    assert out['set_bad_frame'] == [False, 'SetModelState: specified reference frame entity does not exist']
    assert out['by_topic'] == pytest.approx(-1.0, abs=1e-3)
    assert out['set_link'] == [True, 'SetLinkState: success']
    assert out['after_set_link'] == pytest.approx(3.0, abs=1e-4)
    assert out['set_link_unknown'] == [False, 'SetLinkState: link does not exist']
    assert out['set_link_bad_frame'] == [False, 'SetLinkState: failed']
    assert out['config'] == [True, 'SetModelConfiguration: success']
    assert out['hinge_yaw'] == pytest.approx(0.3, abs=1e-4)
    assert out['config_unknown'] == [False, 'SetModelConfiguration: model does not exist']
    assert out['config_lengths'] == [False, 'SetModelConfiguration: joint name and position list have different lengths']


@pytest.mark.ros
def test_efforts_physics_and_simulation_control(ros, paused_plant):
    out = ros.probe('gazebo_ros/probes/efforts_physics_and_simulation_control.py', timeout=90)
    assert out['wrench'] == [True, '']
    assert out['wrench_unknown'] == [False, 'ApplyBodyWrench: body does not exist']
    assert out['wrench_bad_frame'] == [False, 'ApplyBodyWrench: reference_frame not found']
    assert out['lifted'] > 0.3, 'the force lifts the car'
    assert out['paused_clock'][0] == out['paused_clock'][1]
    assert out['effort'] == [True, 'ApplyJointEffort: effort set']
    assert out['effort_unknown'] == [False, 'ApplyJointEffort: joint not found']
    assert out['set_physics'] == [True, 'physics engine updated']
    assert out['new_physics'] == [pytest.approx(0.002), pytest.approx(250.0), pytest.approx(-3.0)]
    assert out['bad_step'][0] is False and 'time step 0 s is outside' in out['bad_step'][1]
    assert abs(out['reset_world'][0]) < 0.05 and out['reset_world'][1], 'reset_world: poses back, time goes on'
    assert out['reset_simulation'] < 0.05


@pytest.mark.ros
@pytest.mark.slow
def test_step_physics_runs_that_many_iterations_while_paused_and_scene_contacts_has_the_tyres(ros, paused_plant):
    """/gazebo/step_physics (gzclient's step button): while paused, exactly that many 1 ms steps, /clock
    sent at the end whatever its 100 Hz rate; none while running is added. /gazebo/scene_contacts: the
    four tyres on the ground at the viewers' rate while subscribed."""
    out = ros.probe('gazebo_ros/probes/step_physics_runs_that_many_iterations_while_paused_and_scene_contacts_has_the_tyres.py',
                    timeout=90)
    assert out['after_7'] - out['start'] == 7000000, 'seven 1 ms steps, and /clock at once'
    assert out['after_2000'] - out['after_7'] == 2000000000
    assert out['still'] == out['after_2000'] and out['paused'] is True, 'paused again after the steps'
    # 2 s at 30 Hz: about 60 messages while stepping, none while paused
    assert 50 <= out['contact_messages'] <= 70, out['contact_messages']
    tyres = sorted(c[0].split('::')[1] for c in out['contacts'])
    assert tyres == ['left_front_wheel', 'left_rear_wheel', 'right_front_wheel', 'right_rear_wheel'], out['contacts']
    for _, other, z, normal_z, force_z, frame in out['contacts']:
        assert other == 'ground_plane::link::collision' and frame == 'world'
        assert abs(z) < 1e-3 and normal_z == pytest.approx(1.0)
    assert sum(c[4] for c in out['contacts']) == pytest.approx(2.69 * 9.8, rel=0.02), 'the tyres bear the car'


@pytest.mark.ros
def test_spawn_and_delete_with_gazebo_ros_messages(ros, paused_plant, urdf_file):
    out = ros.probe('gazebo_ros/probes/spawn_and_delete_with_gazebo_ros_messages.py', urdf_file, timeout=120)
    assert out['second'] == [True, 'SpawnModel: Successfully spawned entity']
    assert out['second_at'] == pytest.approx(1.0, abs=1e-3), 'spawned relative to tianracer::base_footprint'
    assert out['again'] == [False, 'SpawnModel: Failure - entity already exists.']
    assert out['bad_frame'] == [False, 'SpawnModel: reference reference_frame not found, did you forget to scope '
                                       'the link by model name?']
    assert out['not_urdf'] == 'call failed', 'spawn_urdf_model fails the call for what is not URDF, as gazebo_ros'
    # spawn_sdf_model takes SDF (test_spawn_sdf.py); one the plant refuses answers the parser's message
    assert out['sdf'] == [False, "SpawnModel: Failure - model 'box' has no <link>: a model that moves needs one"]
    assert out['sdf_takes_urdf'] == [True, 'SpawnModel: Successfully spawned entity']
    assert out['delete'] == [True, 'DeleteModel: successfully deleted model']
    assert out['delete_again'] == [False, 'DeleteModel: model does not exist']
    assert sorted(out['names']) == ['car4', 'ground_plane', 'tianracer']


@pytest.mark.ros
@pytest.mark.slow
def test_model_and_link_states_are_published_on_every_step_with_scoped_names(ros, paused_plant):
    out = ros.probe('gazebo_ros/probes/model_and_link_states_are_published_on_every_step_with_scoped_names.py',
                    timeout=90)
    assert out['models'] == ['ground_plane', 'tianracer'], 'the static ground plane is a model, as in Gazebo'
    assert 'tianracer::base_link' in out['links'] and 'tianracer::left_rear_wheel' in out['links']
    assert all(name.startswith(('tianracer::', 'ground_plane::')) for name in out['links'])
    assert 'ground_plane::link' in out['links'], "a static model's link, as Gazebo lists it"
    assert out['laser_z'][0] == pytest.approx(out['laser_z'][1], abs=1e-3)  # the car settles on its wheels
    assert out['while_paused'] == 0, 'published on world updates: none while paused, as gazebo_ros'

    # Every 1 ms step (a Python subscriber on a loaded machine keeps up with a good part of them).
    assert out['count'] > 0.3 * out['span'] * 1000, out


@pytest.mark.ros
@pytest.mark.slow
def test_spawn_model_sets_joints_unpauses_and_reports_like_gazebo_ros(ros, urdf_file):
    plant = ros.start(['roslaunch', 'gazebo_ros', 'empty_world.launch', 'gui:=false', 'paused:=true'], 'plant')
    ros.set_param('/robot_description', textfile=urdf_file)
    spawn = ros.run(['rosrun', 'gazebo_ros', 'spawn_model', '-urdf', '-param', 'robot_description', '-model', 'car',
                     '-x', '0.5', '-J', 'left_steering_hinge_joint', '0.25', '-unpause'], timeout=60)
    log = spawn.stdout + spawn.stderr
    assert spawn.returncode == 0, log + plant.log()
    assert 'Spawn status: SpawnModel: Successfully spawned entity' in log
    state = ros.probe('gazebo_ros/probes/spawn_model_sets_joints_unpauses_and_reports_like_gazebo_ros.py', timeout=60)
    assert state['hinge'] == pytest.approx(0.25, abs=0.02) and state['x'] == pytest.approx(0.5, abs=0.01)
    assert state['paused'] is False, '-unpause'
    again = ros.run(['rosrun', 'gazebo_ros', 'spawn_model', '-urdf', '-param', 'robot_description', '-model', 'car'],
                    timeout=60)
    assert again.returncode == 1
    assert 'SpawnModel: Failure - entity already exists.' in again.stdout + again.stderr
    sdf = ros.run(['rosrun', 'gazebo_ros', 'spawn_model', '-sdf', '-database', 'coke_can', '-model', 'can'], timeout=60)
    # no coke_can on the model path: the status names the include and where it was looked for
    assert sdf.returncode == 1 and 'model://coke_can' in sdf.stdout and 'GAZEBO_MODEL_PATH' in sdf.stdout
    usage = ros.run(['rosrun', 'gazebo_ros', 'spawn_model', '-param', 'robot_description', '-model', 'x'], timeout=60)
    assert usage.returncode == 1 and '-urdf or -sdf' in usage.stdout + usage.stderr


@pytest.mark.ros
@pytest.mark.slow
def test_a_script_reading_link_states_drives_the_car_with_ackermann_drive_stamped(ros):
    """The tutorial's system (tianracer.launch); test/scripts/drive_to_point.py steers the car to a
    point from the base link's pose in /gazebo/link_states, commanding AckermannDriveStamped."""
    ros.start(['roslaunch', 'tianracer_description', 'tianracer.launch', 'gui:=false'], 'tianracer_launch')
    ros.wait_for_controllers(len(TUTORIAL_CONTROLLERS))
    drive = ros.run([PYTHON, os.path.join(TEST_DIR, 'scripts', 'drive_to_point.py'), '_x:=2.0', '_y:=1.5',
                     '_tolerance:=0.25', '_timeout:=40'], timeout=150)
    assert drive.returncode == 0, drive.stdout + drive.stderr
    final = ros.probe('gazebo_ros/probes/a_script_reading_link_states_drives_the_car_with_ackermann_drive_stamped.py',
                      timeout=60)
    assert math.hypot(final[0] - 2.0, final[1] - 1.5) < 0.4, (final, drive.stdout)
