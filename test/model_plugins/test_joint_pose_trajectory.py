"""gazebo_plugins' libgazebo_ros_joint_pose_trajectory.so on the plant: the three-joint arm
(test/fixtures/urdf/arm.urdf, no controller running) posed by a JointTrajectory on the plugin's
topic: each point set at upstream's times (the first at once, each next the time_from_start of the
point before it later), the world's physics off while it plays (the elbow does not sag, a crate in
the air does not fall) and back on after it; an unknown joint skipped, a frame_id naming no link
refused (an empty one too, as upstream: "world" or "map" it must be), a point with too few positions
reported."""
import pytest

from plant_helpers import arm, logged
from tianracer_description import bullet_plant

PLUGIN = ('<gazebo><plugin name="pose_player" filename="libgazebo_ros_joint_pose_trajectory.so">'
          '<updateRate>100</updateRate></plugin></gazebo>\n</robot>')


CRATE = """<robot name="crate"><link name="box">
  <inertial><mass value="1.0"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial>
  <collision><geometry><box size="0.2 0.2 0.2"/></geometry></collision></link></robot>"""


def posed_arm():
    """The arm with the plugin, and a crate 3 m up beside it."""
    world = bullet_plant.World()
    world.echo = False
    robot = world.spawn(arm().replace('</robot>', PLUGIN), 'arm')
    crate = world.spawn(CRATE, 'crate', [2.0, 0.0, 3.0, 0, 0, 0])
    world.step(10)
    return world, robot, crate


def joints(robot):
    return [robot.joint_state(j)[0] for j in ('shoulder', 'elbow')]


def test_points_are_set_at_upstreams_times_with_the_physics_off_while_playing():
    world, robot, crate = posed_arm()
    assert robot.plugin_topics('pose_player') == {'subscribes': ['set_joint_trajectory'], 'publishes': []}
    trajectory = {'joint_names': ['shoulder', 'elbow', 'nowhere'], 'frame_id': 'world', 'points': [
        {'positions': [0.3, -0.4, 9.0], 'time_from_start': 0.2},
        {'positions': [0.6, -0.8, 9.0], 'time_from_start': 0.3}]}
    assert robot.plugin_send('pose_player', 'set_joint_trajectory', trajectory)
    start = world.time
    world.step(1)
    assert joints(robot) == pytest.approx([0.3, -0.4], abs=1e-6), 'the first point at once'
    world.step(198)
    assert joints(robot) == pytest.approx([0.3, -0.4], abs=1e-6), 'no physics: the elbow does not sag'
    world.step(1)
    assert world.time == pytest.approx(start + 0.2)
    assert joints(robot) == pytest.approx([0.6, -0.8], abs=1e-6), 'the second 0.2 s (its predecessor\'s time) later'
    world.step(299)
    assert joints(robot) == pytest.approx([0.6, -0.8], abs=1e-6)
    world.step(200)  # past 0.5 s the trajectory is over and the physics is back
    elbow = joints(robot)[1]
    world.step(200)
    assert joints(robot)[1] != pytest.approx(elbow, abs=1e-3), 'the physics runs again'
    assert any('updating configuration [1/2]' in m for m in logged(world, 'INFO'))


def test_other_models_freeze_while_it_plays():
    world, robot, crate = posed_arm()
    falling = crate.base_pose()[2]
    assert robot.plugin_send('pose_player', 'set_joint_trajectory', {'joint_names': ['wrist'], 'frame_id': 'map', 'points': [
        {'positions': [1.0], 'time_from_start': 0.5}]})
    world.step(400)
    assert crate.base_pose()[2] == pytest.approx(falling, abs=1e-6), 'the crate hangs in the air'
    assert robot.joint_state('wrist')[0] == pytest.approx(1.0, abs=1e-6)
    world.step(300)
    assert crate.base_pose()[2] < falling - 0.1, 'and falls once the trajectory is over'


def test_a_frame_naming_no_link_is_refused_and_bad_points_reported():
    world, robot, crate = posed_arm()
    assert not robot.plugin_send('pose_player', 'set_joint_trajectory', {
        'joint_names': ['elbow'], 'frame_id': 'nowhere', 'points': [{'positions': [0.5], 'time_from_start': 0.1}]})
    assert any('ros_joint_trajectory plugin needs a reference link [nowhere] as frame_id, aborting.' in m
               for m in logged(world, 'ERROR'))
    assert not robot.plugin_send('pose_player', 'set_joint_trajectory', {
        'joint_names': ['elbow'], 'points': [{'positions': [0.5], 'time_from_start': 0.1}]}), \
        'no frame_id is no reference link either: upstream wants "world" or "map"'
    assert robot.plugin_send('pose_player', 'set_joint_trajectory', {
        'joint_names': ['elbow', 'shoulder'], 'frame_id': 'arm::forearm',
        'points': [{'positions': [0.5], 'time_from_start': 0.1}, {'positions': [0.2, 0.1], 'time_from_start': 0.1}]})
    world.step(150)
    assert any('point[0] in JointTrajectory has different number of joint names[2] and positions[1].' in m
               for m in logged(world, 'ERROR'))
    assert joints(robot) == pytest.approx([0.1, 0.2], abs=1e-6)
