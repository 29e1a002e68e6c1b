"""ros_controllers' gripper_action_controller on the plant: the two-finger gripper
(test/fixtures/urdf/gripper.urdf, the second finger following the first by the mimic joint plugin)
driven through control_msgs/GripperCommand goals, by the position and the effort kinds: a goal
reached within goal_tolerance, a goal past the joint's limit aborted as stalled after stall_timeout,
max_effort bounding the effort kind (0: none at all, as upstream), cancel and preemption; through the
node, actionlib's SimpleActionClient against /gripper/gripper_controller/gripper_cmd."""
import pytest
import yaml

from plant_helpers import FIXTURES, logged
from tianracer_description import bullet_plant
from ros_harness import spawn_urdf, start_plant


def gripper_urdf(interface='Position'):
    with open(FIXTURES + '/urdf/gripper.urdf') as f:
        return f.read().replace('PositionJointInterface', interface + 'JointInterface')


def gripper_controllers(kind='position_controllers', **controller):
    c = {'type': kind + '/GripperActionController', 'joint': 'finger_joint', 'goal_tolerance': 0.002,
         'stall_velocity_threshold': 0.001, 'stall_timeout': 0.5}
    if kind == 'effort_controllers':
        c['gains'] = {'finger_joint': {'p': 100.0, 'i': 0.0, 'd': 2.0}}
    c.update(controller)
    return {'gripper': {'gripper_controller': c}}


def gripper_world(kind='position_controllers', **controller):
    world = bullet_plant.World()
    world.echo = False
    world.load_params(gripper_controllers(kind, **controller))
    robot = world.spawn(gripper_urdf('Position' if kind == 'position_controllers' else 'Effort'), 'gripper')
    manager = robot.controller_manager
    assert manager.spawn(['gripper_controller']) == (['gripper_controller'], True), world.messages()
    world.step(100)
    return world, robot, manager


def run_until_done(world, manager, goal_id, seconds):
    for _ in range(int(seconds / 0.01)):
        world.step(10)
        result = manager.goal_result('gripper_controller', action='gripper_cmd')
        if result and result['goal_id'] == goal_id:
            return result
    return None


@pytest.mark.parametrize('kind', ['position_controllers', 'effort_controllers'])
def test_a_goal_is_reached_and_the_mimic_finger_follows(kind):
    world, robot, manager = gripper_world(kind)
    assert manager.send_goal('gripper_controller', 'open', {'position': 0.03, 'max_effort': 5.0}, action='gripper_cmd')
    result = run_until_done(world, manager, 'open', 2.0)
    assert (result['outcome'], result['reached_goal'], result['stalled']) == ('succeeded', True, False)
    assert result['position'] == pytest.approx(0.03, abs=0.002)
    if kind == 'position_controllers':
        assert result['effort'] == 5.0, "the position kind reports the goal's max_effort"
    else:
        assert abs(result['effort']) <= 5.0
    world.step(500)
    assert robot.joint_state('finger_joint')[0] == pytest.approx(0.03, abs=0.002), 'still driven to the goal'
    assert robot.joint_state('finger_mimic_joint')[0] == pytest.approx(0.03, abs=0.003)


def test_a_goal_past_the_limit_stalls_and_aborts_after_stall_timeout():
    world, robot, manager = gripper_world()
    start = world.time
    assert manager.send_goal('gripper_controller', 'too far', {'position': 0.06}, action='gripper_cmd')
    result = run_until_done(world, manager, 'too far', 3.0)
    assert (result['outcome'], result['reached_goal'], result['stalled']) == ('aborted', False, True)
    assert result['position'] == pytest.approx(0.04, abs=0.002), 'at the URDF limit'
    assert 0.5 < world.time - start < 1.0, 'stall_timeout 0.5 s after it stopped moving'


def test_the_effort_kind_is_bounded_by_max_effort():
    world, robot, manager = gripper_world('effort_controllers')
    assert manager.send_goal('gripper_controller', 'none', {'position': 0.03, 'max_effort': 0.0}, action='gripper_cmd')
    result = run_until_done(world, manager, 'none', 2.0)
    assert (result['outcome'], result['stalled']) == ('aborted', True), 'max_effort 0 is no effort, as upstream'
    assert robot.joint_state('finger_joint')[0] == pytest.approx(0.0, abs=0.002)
    assert manager.send_goal('gripper_controller', 'weak', {'position': 0.03, 'max_effort': 0.02}, action='gripper_cmd')
    world.step(200)
    # 0.02 N on the 50 g finger: at most 0.4 m/s^2, 8 mm in 0.2 s
    assert 0.0 < robot.joint_state('finger_joint')[0] < 0.009


def test_cancel_preempt_and_not_running():
    # the hold after a cancel uses the max_effort parameter (0, the default, would be no effort at all)
    world, robot, manager = gripper_world('effort_controllers', gains={'finger_joint': {'p': 50.0, 'd': 2.0}},
                                          max_effort=1.0)
    assert manager.send_goal('gripper_controller', 'first', {'position': 0.03, 'max_effort': 0.5}, action='gripper_cmd')
    world.step(50)
    assert manager.send_goal('gripper_controller', 'second', {'position': 0.035, 'max_effort': 0.5}, action='gripper_cmd')
    assert manager.goal_result('gripper_controller', action='gripper_cmd')['goal_id'] == 'first'
    assert manager.goal_result('gripper_controller', action='gripper_cmd')['outcome'] == 'canceled'
    world.step(50)
    assert manager.cancel_goal('gripper_controller', 'second', action='gripper_cmd')
    assert manager.goal_result('gripper_controller', action='gripper_cmd')['outcome'] == 'canceled'
    world.step(300)
    held = robot.joint_state('finger_joint')[0]
    world.step(500)
    assert robot.joint_state('finger_joint')[0] == pytest.approx(held, abs=0.001) and held < 0.034, \
        'held where cancelled, short of the goal'
    assert manager.switch([], ['gripper_controller'], 2)
    world.step(1)
    assert not manager.send_goal('gripper_controller', 'late', {'position': 0.01}, action='gripper_cmd')
    assert manager.goal_result('gripper_controller', action='gripper_cmd')['outcome'] == 'rejected'
    assert any("Can't accept new action goals. Controller is not running." in m for m in logged(world, 'ERROR'))


def test_configuration_errors():
    world = bullet_plant.World()
    world.echo = False
    params = gripper_controllers()
    del params['gripper']['gripper_controller']['joint']
    world.load_params(params)
    robot = world.spawn(gripper_urdf(), 'gripper')
    assert not robot.controller_manager.load('gripper_controller')
    assert any('Could not find joint name on param server' in m for m in logged(world, 'ERROR'))


@pytest.mark.ros
def test_gripper_command_with_actionlib(ros, tmp_path):
    (tmp_path / 'gripper.urdf').write_text(gripper_urdf())
    (tmp_path / 'controllers.yaml').write_text(yaml.safe_dump(gripper_controllers()))
    plant = start_plant(ros)
    ros.set_param('/gripper/robot_description', textfile=str(tmp_path / 'gripper.urdf'))
    ros.load_params(str(tmp_path / 'controllers.yaml'))
    spawn_urdf(ros, plant, '/gripper/robot_description', 'gripper')
    ros.start(['rosrun', 'controller_manager', 'spawner', '__ns:=/gripper', 'gripper_controller'], 'spawner')
    ros.wait_for_controllers(1, namespace='/gripper')
    seen = ros.probe('controllers/probes/gripper_command_with_actionlib.py', timeout=60)
    SUCCEEDED, ABORTED = 3, 4
    state, position, reached, stalled = seen['reached']
    assert (state, reached, stalled) == (SUCCEEDED, True, False) and position == pytest.approx(0.025, abs=0.002)
    state, position, reached, stalled = seen['stalled']
    assert (state, reached, stalled) == (ABORTED, False, True) and position == pytest.approx(0.04, abs=0.002)
