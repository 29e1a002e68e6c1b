"""libgazebo_ros_diff_drive.so through the node: the diff_bot spawned by spawn_model (its '/'
namespace written into the plugin, as upstream's) drives on /cmd_vel and publishes /odom, odom ->
base_footprint on /tf and the wheels' joint_states, the only odometry of the robot. A turtlebot3-like
diff-drive robot and the tutorial's car together in one world, each driven on its own topics."""
import os

import pytest

from plant_helpers import DIFF_BOT
from suite_paths import REPOSITORY
from ros_harness import spawn_urdf, start_plant
from tianracer_description.tianracer import TUTORIAL_CONTROLLERS

pytestmark = pytest.mark.ros


@pytest.mark.slow
def test_diff_drive_drives_on_cmd_vel_and_publishes_odometry_tf_and_joint_states(ros):
    plant = start_plant(ros)
    ros.set_param('/robot_description', textfile=DIFF_BOT)
    spawn_urdf(ros, plant, '/robot_description', 'diff_bot')
    seen = ros.probe('model_plugins/probes/diff_drive_drives_on_cmd_vel_and_publishes_odometry_tf_and_joint_states.py',
                     timeout=90)
    assert seen['frames'] == [['odom', 'base_footprint']], "spawn_model's '/' namespace: no prefix"
    assert seen['covariances'] == [[1e-05, 0.001]], "every /odom message is the plugin's: the plant's own is off"
    assert seen['linear'] == pytest.approx(0.2, rel=0.1) and seen['angular'] == pytest.approx(0.5, rel=0.1)
    moved = [m - s for m, s in zip(seen['model_xy'], seen['start_xy'])]
    assert abs(moved[0]) + abs(moved[1]) > 0.2, 'the robot drove'
    assert seen['odom_xy'] == pytest.approx(seen['model_xy'], abs=0.05), 'world odometry: the model pose'
    assert abs(seen['tf_x'] - seen['odom_xy'][0]) < 0.1
    assert seen['joints'] == ['wheel_right_joint', 'wheel_left_joint'] and seen['positions'] == 2

@pytest.mark.slow
def test_a_diff_drive_robot_and_the_tutorial_car_in_one_world(ros, tmp_path):
    arena = os.path.join(REPOSITORY, 'worlds', 'arena.world')
    car = ros.start(['roslaunch', 'tianracer_description', 'tianracer_world.launch', 'gui:=false',
                     'world_name:=' + os.path.abspath(arena)], 'tianracer_world')
    ros.wait_for_controllers(len(TUTORIAL_CONTROLLERS))
    (tmp_path / 'diff_bot.urdf').write_text(open(DIFF_BOT).read())
    ros.set_param('/tb3/robot_description', textfile=str(tmp_path / 'diff_bot.urdf'))
    ros.set_param('/tb3/tf_prefix', 'tb3')  # as turtlebot3's multi-robot launch files give each robot
    spawn_urdf(ros, car, '/tb3/robot_description', 'tb3', robot_namespace='/tb3', xyz=(-1, -1.5, 0))
    seen = ros.probe('model_plugins/probes/a_diff_drive_robot_and_the_tutorial_car_in_one_world.py', timeout=90)
    moved = {name: seen['after'][name][0] - seen['before'][name][0] for name in ('tianracer', 'tb3')}
    assert moved['tianracer'] > 0.5, moved
    assert 0.25 < moved['tb3'] < 0.6, moved
    assert abs(seen['after']['tb3'][1] + 1.5) < 0.05, 'each robot drives on its own topic: tb3 kept its line'
    assert seen['scan_frame'] == 'tb3/base_scan', "gazebo_ros_laser's frame resolves against its namespace"
    assert seen['scan_hits'] > 100, 'the arena walls and the car around it'
    assert seen['tb3_tf_x'] == pytest.approx(seen['after']['tb3'][0], abs=0.15), \
        "the diff drive's frames carry its tf_prefix parameter: tb3/odom -> tb3/base_footprint"
